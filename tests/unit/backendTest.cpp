// Back-ends (backend/backend.hpp): the serial launcher and the OpenMP one run
// the same kernel bodies and give bitwise-identical points, for every shape
// function, transfer and stress-update order, with walls, gravity and a
// real stress; asking for a back-end this build or machine cannot run
// stops at setup with the reason.
#include "testHelpers.hpp"
#include <gtest/gtest.h>
#include <omp.h>

using namespace mpm;
using namespace mpm::test;

namespace {

// A falling elastic block in a walled box, 6 steps: P2G (mass, momentum,
// force), the nodal update, G2P, the stress update and the point motion,
// with points near the walls.
Real meanVy(const Particles& P)
{
    Real s = 0;
    for (Index p = 0; p < P.size(); ++p) s += P.v[1][p];
    return s/Real(P.size());
}

// Also returns the points' mean y-velocity before the steps.
Particles run(Backend backend, ShapeKind shape, Transfer transfer, StressUpdate order, Real& vy0)
{
    MpmSystem s;
    BoundarySpec b;
    b.conditions = {WallCondition{WallType::slip, 0}};
    StepOptions o;
    o.shape = shape; o.transfer = transfer; o.stressUpdate = order;
    o.flipRatio = 0.95; o.backend = backend;
    o.gravity = {0.3, -9.81, 0.1};
    s.setup(box(10, 10, 8), b, o);
    s.materials().push_back(makeLaw("linearElastic", {{"rho", 1000}, {"E", 1e5}, {"nu", 0.3}}));
    seedRandom(s, 6000, 0.02, 0.6);
    vy0 = meanVy(s.particles());
    for (int n = 0; n < 6; ++n) s.step(2e-4);
    return s.particles();
}

} // namespace

TEST(Backend, SerialEqualsOpenMPBitwise)
{
    const Index threshold = MpmSystem::parallelThreshold;
    MpmSystem::parallelThreshold = 500;   // openmp: every loop threaded
    omp_set_num_threads(2);
    for (auto shape : {ShapeKind::linearHat, ShapeKind::quadraticBSpline, ShapeKind::cubicBSpline})
    for (auto transfer : {Transfer::picFlip, Transfer::apic})
    for (auto order : {StressUpdate::USF, StressUpdate::USL, StressUpdate::MUSL})
    {
        Real vy0 = 0;
        const Particles a = run(Backend::serial, shape, transfer, order, vy0);
        const Particles b = run(Backend::openmp, shape, transfer, order, vy0);
        const std::string what = std::string(shapeName(shape)) + " " + transferName(transfer)
                               + " " + stressUpdateName(order);
        ASSERT_EQ(a.size(), b.size()) << what;
        EXPECT_EQ(a.id, b.id) << what;
        for (int d = 0; d < 3; ++d)
        {
            EXPECT_EQ(a.x[d], b.x[d]) << what;
            EXPECT_EQ(a.v[d], b.v[d]) << what;
        }
        for (int c = 0; c < 6; ++c) EXPECT_EQ(a.sigma[c], b.sigma[c]) << what;
        // The run did something: the points fell and carry stress
        EXPECT_LT(meanVy(a), vy0 - 1e-3) << what;
        EXPECT_GT(std::abs(a.sigma[YY][0]), 0.0) << what;
    }
    MpmSystem::parallelThreshold = threshold;
}

TEST(Backend, NamesRoundTrip)
{
    for (Backend b : {Backend::serial, Backend::openmp, Backend::cuda})
    {
        Backend c = Backend::serial;
        EXPECT_TRUE(parseBackend(backendName(b), c));
        EXPECT_EQ(int(b), int(c));
    }
    Backend c;
    EXPECT_FALSE(parseBackend("gpu", c));
    EXPECT_EQ(backendUnavailableReason(Backend::serial), "");
    EXPECT_EQ(backendUnavailableReason(Backend::openmp), "");
}

TEST(Backend, UnavailableCudaStopsAtSetupWithTheReason)
{
    const std::string why = backendUnavailableReason(Backend::cuda);
    if (why.empty()) GTEST_SKIP() << "this build and machine can run cuda";
    MpmSystem s;
    StepOptions o;
    o.backend = Backend::cuda;
    try
    {
        s.setup(box(4, 4, 4), BoundarySpec{}, o);
        FAIL() << "setup accepted an unavailable back-end";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("backend cuda: " + why), std::string::npos) << e.what();
    }
}

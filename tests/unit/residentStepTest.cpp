// The step plan (step/stepPlan.hpp) and the resident device step
// (backend/residentStep.hpp) tested on the CPU through its host stand-in.
//
// Plan: each stress update gives its documented phase order, and every
// back-end of this machine (serial, OpenMP, the resident stand-in) runs a
// step as exactly that order (recorded through MpmSystem::recordPhases).
//
// Resident: a block thrown at the floor of a box under gravity, 20 steps,
// for every shape function, transfer, stress update, in 2D and 3D, with
// noSlip and slip (unilateral: the block leaves one wall and presses on
// another) box walls, a slip level-set obstacle and a moving noSlip
// level-set plate under the block; per point the position, velocity and
// stress agree with the serial host step to 1e-10 of the field's largest
// magnitude. Why that tolerance: both run the same kernel bodies; only the
// order of the nodal sums differs (the host sums colour blocks of points,
// the stand-in points in storage order, and the ghost folds in another
// order), a few units of round-off per sum, which 20 explicit steps below
// the Courant limit amplify by far less than 1e5. A wrong phase (a fold or
// gravity twice or not at all, a missing contact decision, the plate's
// velocity ignored) changes the fields at 1e-4 or more: the mutation checks
// at the end show it.
#include "constitutive/constitutiveLaw.hpp"
#include "step/mpmSystem.hpp"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <map>

using namespace mpm;

namespace {

struct Scene
{
    StepOptions options;
    BoundarySpec boundary;
    int dim = 3;
    bool obstacle = false;     // a slip sphere in the block's path
    bool plate = false;        // a noSlip plate moving along x under the block
};

void build(MpmSystem& s, const Scene& c, Backend backend, bool standIn)
{
    Lattice L;
    L.h = 0.1;
    L.nCells = {10, c.dim == 3 ? 8 : 1, 10};
    if (c.dim == 2) L.solved = {true, false, true};
    StepOptions o = c.options;
    o.backend = backend;
    o.residentStandIn = standIn;
    o.gravity = {0, 0, -9.81};
    s.setup(L, c.boundary, o);
    s.materials().push_back(makeLaw("linearElastic", {{"rho", 1000}, {"E", 2e5}, {"nu", 0.3}}));
    const Real h = L.h;
    // On the floor (above the plate), against the x- wall, moving away
    // from it and down
    const Real vol = c.dim == 3 ? h*h*h/8 : h*h/4;
    const int k0 = c.plate ? 2 : 0;
    for (int k = k0; k < k0 + 4; ++k)
    for (int j = 3; j < (c.dim == 3 ? 5 : 4); ++j)
    for (int i = 0; i < 4; ++i)
    for (int q = 0; q < (c.dim == 3 ? 8 : 4); ++q)
    {
        const Real x = (i + 0.25 + 0.5*(q & 1))*h;
        const Real y = c.dim == 3 ? (j + 0.25 + 0.5*((q >> 2) & 1))*h : 0.05;
        const Real z = (k + 0.25 + 0.5*((q >> 1) & 1))*h;
        s.particles().add({x, y, z}, {0.4, 0, -1.0}, 1000*vol, vol, 0);
    }
    if (c.obstacle)
    {
        s.setLevelSetWalls({{"ball", std::make_shared<SphereShape>(std::array<Real, 3>{0.5, c.dim == 3 ? 0.4 : 0.05, 0.15}, 0.08),
                             WallCondition{WallType::slip, 0, {0, 0, 0}}}}, {0, 0.05, 0});
    }
    if (c.plate)
    {
        s.setLevelSetWalls({{"plate", std::make_shared<HalfSpaceShape>(std::array<Real, 3>{0, 0, 0.17},
                                                                      std::array<Real, 3>{0, 0, 1}),
                             WallCondition{WallType::noSlip, 0, {0, 0, 0}}}}, {0, 0.05, 0});
    }
}

// The same scene on the host step and on the resident step's stand-in
void buildPair(MpmSystem& host, MpmSystem& resident, const Scene& c)
{
    build(host, c, Backend::serial, false);
    build(resident, c, Backend::serial, true);
}

void run(MpmSystem& s, const Scene& c, int steps)
{
    const Real dt = 2e-4;
    for (int i = 0; i < steps; ++i)
    {
        if (c.plate) s.moveLevelSetWalls({{0.3*i*dt, 0, 0}}, {{0.3, 0, 0}});
        s.step(dt);
    }
}

// Largest difference over the points (matched by id) relative to the
// largest magnitude, over x, v and sigma
double relativeDifference(const MpmSystem& a, const MpmSystem& b)
{
    const Particles& P = a.particles();
    const Particles& Q = b.particles();
    EXPECT_EQ(P.size(), Q.size());
    std::map<std::int64_t, Index> at;
    for (Index q = 0; q < Q.size(); ++q) at[Q.id[q]] = q;
    double worst = 0;
    auto field = [&](auto get, int components)
    {
        double scale = 0, diff = 0;
        for (Index p = 0; p < P.size(); ++p)
        {
            const Index q = at.at(P.id[p]);
            for (int c = 0; c < components; ++c)
            {
                scale = std::max(scale, std::abs(get(P, p, c)));
                diff = std::max(diff, std::abs(get(P, p, c) - get(Q, q, c)));
            }
        }
        worst = std::max(worst, scale > 0 ? diff/scale : diff);
    };
    field([](const Particles& X, Index p, int c) { return X.x[c][p]; }, 3);
    field([](const Particles& X, Index p, int c) { return X.v[c][p]; }, 3);
    field([](const Particles& X, Index p, int c) { return X.sigma[c][p]; }, 6);
    return worst;
}

std::vector<Scene> scenes()
{
    std::vector<Scene> out;
    BoundarySpec slip;
    slip.conditions = {WallCondition{WallType::slip, 0, {0, 0, 0}}};
    BoundarySpec friction;
    friction.conditions = {WallCondition{WallType::friction, 0.3, {0, 0, 0}}};

    for (int dim : {2, 3})
    for (auto shape : {ShapeKind::linearHat, ShapeKind::quadraticBSpline, ShapeKind::cubicBSpline})
    for (auto transfer : {Transfer::picFlip, Transfer::apic})
    for (auto update : {StressUpdate::USF, StressUpdate::USL, StressUpdate::MUSL})
    {
        Scene c;
        c.dim = dim;
        c.options.shape = shape;
        c.options.transfer = transfer;
        c.options.stressUpdate = update;
        out.push_back(c);
    }
    // Slip walls (the unilateral contact), the level sets, grain volume
    for (auto shape : {ShapeKind::quadraticBSpline, ShapeKind::cubicBSpline})
    for (int dim : {2, 3})
    {
        Scene c;
        c.dim = dim;
        c.options.shape = shape;
        c.boundary = slip;
        out.push_back(c);
        c.boundary = BoundarySpec();
        c.obstacle = true;
        out.push_back(c);
        c.obstacle = false;
        c.plate = true;
        c.options.stressUpdate = StressUpdate::MUSL;
        out.push_back(c);
        c.plate = false;
        c.options.constantGrainVolume = true;
        out.push_back(c);
        c.options.constantGrainVolume = false;
        c.options.stressUpdate = StressUpdate::USL;
        // Coulomb friction: every wall, and slip walls on a friction floor
        // (the granular column's box), with the re-map's friction (MUSL)
        c.boundary = friction;
        out.push_back(c);
        // Lattice of build(): 10 x (8 or 1) x 10 cells; the z- side's faces
        // are indexed by x and y
        BoundarySpec slipOnFrictionFloor = slip;
        slipOnFrictionFloor.conditions.push_back(WallCondition{WallType::friction, 0.5, {0, 0, 0}});
        slipOnFrictionFloor.faceCondition[4].assign(std::size_t(10*(dim == 3 ? 8 : 1)), 1);
        c.boundary = slipOnFrictionFloor;
        out.push_back(c);
        // Periodic along x (the block across x-, moving along it), on a
        // friction floor; and periodic along x and y in 3D
        BoundarySpec periodicX = slipOnFrictionFloor;
        periodicX.conditions.push_back(WallCondition{WallType::periodic, 0, {0, 0, 0}});
        periodicX.faceCondition[0].assign(std::size_t((dim == 3 ? 8 : 1)*10), 2);
        periodicX.faceCondition[1].assign(std::size_t((dim == 3 ? 8 : 1)*10), 2);
        c.boundary = periodicX;
        out.push_back(c);
        if (dim == 3)
        {
            BoundarySpec periodicXY = periodicX;
            periodicXY.faceCondition[2].assign(10*10, 2);
            periodicXY.faceCondition[3].assign(10*10, 2);
            c.boundary = periodicXY;
            out.push_back(c);
        }
        c.options.stressUpdate = StressUpdate::MUSL;
        c.options.transfer = Transfer::apic;
        out.push_back(c);
        c.options.transfer = Transfer::picFlip;
    }
    return out;
}

std::string name(const Scene& c)
{
    return std::to_string(c.dim) + "D " + shapeName(c.options.shape) + " " + transferName(c.options.transfer)
        + " " + stressUpdateName(c.options.stressUpdate)
        + (c.boundary.conditions[0].type == WallType::slip ? " slip box" : "")
        + (c.boundary.conditions.size() > 1 && c.boundary.conditions[1].type == WallType::friction ? " friction floor" : "")
        + (c.boundary.conditions.back().type == WallType::periodic ? " periodic" : "")
        + (c.obstacle ? " obstacle" : "") + (c.plate ? " moving plate" : "")
        + (c.options.constantGrainVolume ? " grain volume" : "");
}

} // namespace

TEST(StepPlan, OrderPerStressUpdate)
{
    StepOptions o;
    o.stressUpdate = StressUpdate::USF;
    EXPECT_EQ(makeStepPlan(o).describe(), "scatter nodalAfterScatter gradientFromOld stress scatterForce "
                                          "foldForce nodalUpdate gather move migrate");
    o.stressUpdate = StressUpdate::USL;
    EXPECT_EQ(makeStepPlan(o).describe(), "scatter+force nodalAfterScatter nodalUpdate gather stress move migrate");
    o.stressUpdate = StressUpdate::MUSL;
    EXPECT_EQ(makeStepPlan(o).describe(), "scatter+force nodalAfterScatter nodalUpdate gather remapMomentum "
                                          "nodalAfterRemap gradientFromNew stress move migrate");
}

// runPlan books the halo time a phase spends (decomposed runs) to that
// phase's category: the cost breakdown prints it under the right phase
TEST(StepPlan, HaloTimeBookedToItsPhase)
{
    StepOptions o;
    o.stressUpdate = StressUpdate::USF;
    StepTimers t;
    runPlan(makeStepPlan(o), t, [&](Phase p)
    {
        if (p == Phase::nodalUpdate) t.halo += 2;
        if (p == Phase::foldForce) t.halo += 1;
        if (p == Phase::scatter) t.halo += 0.5;
    });
    EXPECT_EQ(t.haloIn.nodal, 3);
    EXPECT_EQ(t.haloIn.p2g, 0.5);
    EXPECT_EQ(t.haloIn.constitutive, 0);
    EXPECT_EQ(t.haloIn.g2p, 0);
}

// Every back-end of this machine issues the plan's phases, in its order,
// for every option that shapes the plan (and those that do not)
TEST(StepPlan, EveryBackEndRunsThePlan)
{
    for (auto update : {StressUpdate::USF, StressUpdate::USL, StressUpdate::MUSL})
    for (auto transfer : {Transfer::picFlip, Transfer::apic})
    for (auto mass : {MassMatrix::lumped, MassMatrix::consistent})
    {
        Scene c;
        c.options.shape = ShapeKind::quadraticBSpline;
        c.options.stressUpdate = update;
        c.options.transfer = transfer;
        c.options.massMatrix = mass;
        const std::vector<Phase> expected = makeStepPlan(c.options).phases;
        for (int backend = 0; backend < 3; ++backend)
        {
            MpmSystem s;
            build(s, c, backend == 1 ? Backend::openmp : Backend::serial, backend == 2);
            std::vector<Phase> recorded;
            s.recordPhases(&recorded);
            run(s, c, 2);
            std::vector<Phase> twice(expected);
            twice.insert(twice.end(), expected.begin(), expected.end());
            EXPECT_EQ(recorded, twice) << stressUpdateName(update) << " back-end " << backend;
            // The stand-in runs the lumped cases resident, consistent mass
            // on the host step
            if (backend == 2) EXPECT_EQ(s.lastStepResident(), mass == MassMatrix::lumped);
        }
    }
}

TEST(ResidentStep, StandInAgreesWithTheHostStep)
{
    for (const Scene& c : scenes())
    {
        MpmSystem host, resident;
        buildPair(host, resident, c);
        ASSERT_EQ(resident.residentUnsupported(), "") << name(c);
        run(host, c, 20);
        run(resident, c, 20);
        ASSERT_TRUE(resident.lastStepResident()) << name(c);
        EXPECT_FALSE(host.lastStepResident());
        EXPECT_LT(relativeDifference(host, resident), 1e-10) << name(c);
        EXPECT_EQ(host.levelSetContainedCount(), resident.levelSetContainedCount()) << name(c);
        // The run did something: the block moved by more than round-off
        const Particles& P = resident.particles();
        EXPECT_GT(std::abs(P.v[2][0] + 1.0), 1e-3) << name(c);
    }
}

// The host may change the points between resident steps (seeding,
// reading, a restart): the change goes up before the next step
TEST(ResidentStep, HostChangesGoUp)
{
    Scene c;
    c.options.shape = ShapeKind::quadraticBSpline;
    MpmSystem host, resident;
    buildPair(host, resident, c);
    run(host, c, 5);
    run(resident, c, 5);
    for (MpmSystem* s : {&host, &resident}) s->particles().v[0][3] += 0.5;
    run(host, c, 5);
    run(resident, c, 5);
    EXPECT_LT(relativeDifference(host, resident), 1e-10);
}

// What the resident step does not cover runs on the host step, named
TEST(ResidentStep, UnsupportedCasesSayWhyAndRunOnTheHost)
{
    auto reason = [](auto change)
    {
        Scene c;
        change(c);
        MpmSystem s;
        build(s, c, Backend::serial, true);
        run(s, c, 1);
        EXPECT_FALSE(s.lastStepResident());
        return s.residentUnsupported();
    };
    EXPECT_EQ(reason([](Scene& c) { c.options.massMatrix = MassMatrix::consistent; }), "consistent mass");
    EXPECT_EQ(reason([](Scene& c) { c.boundary.conditions[0] = WallCondition{WallType::outlet, 0, {0, 0, 0}}; }),
              "open faces");
}

// The comparison can fail: the same scene with gravity changed by 0.1 %
// on one side, and with the plate left still on the host, differ far
// beyond the tolerance
TEST(ResidentStep, ComparisonCatchesAWrongStep)
{
    Scene c;
    c.options.shape = ShapeKind::quadraticBSpline;
    MpmSystem host, resident;
    buildPair(host, resident, c);
    resident.setGravity({0, 0, -9.81*1.001});
    run(host, c, 20);
    run(resident, c, 20);
    EXPECT_GT(relativeDifference(host, resident), 1e-6);

    Scene moving = c;
    moving.plate = true;
    MpmSystem still, plate;
    buildPair(still, plate, moving);
    run(plate, moving, 20);
    for (int i = 0; i < 20; ++i) still.step(2e-4);   // the plate never moves
    EXPECT_GT(relativeDifference(still, plate), 1e-6);
}

// The Courant number's signal speed of resident points is reduced on the
// device (the host's copy is stale between steps): it equals the host
// step's, and it follows the points (it changes over the run)
TEST(ResidentStep, SignalSpeedOnTheDevice)
{
    Scene c;
    c.options.shape = ShapeKind::quadraticBSpline;
    MpmSystem host, resident;
    buildPair(host, resident, c);
    const Real before = host.maxSignalSpeed();
    run(host, c, 10);
    run(resident, c, 10);
    ASSERT_TRUE(resident.lastStepResident());
    const Real a = host.maxSignalSpeed(), b = resident.maxSignalSpeed();
    EXPECT_NEAR(b, a, 1e-10*a);
    EXPECT_GT(std::abs(a - before), 1e-6*a);
}

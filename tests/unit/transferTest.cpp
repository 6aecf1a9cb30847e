// Transfers: P2G -> G2P conserves mass and momentum to round-off, a rigid
// translation is exact under PIC, APIC preserves affine velocity fields, and
// results do not depend on the number of OpenMP threads.
#include "testHelpers.hpp"
#include "kernels/g2p.hpp"
#include "kernels/p2g.hpp"
#include "transfer/stencil.hpp"
#include <gtest/gtest.h>
#include <omp.h>
#include <deque>
#include <tuple>

using namespace mpm;
using namespace mpm::test;

namespace {

struct Totals { Real mass = 0; Real mom[3] = {0, 0, 0}; };

Totals pointTotals(const Particles& P)
{
    Totals t;
    for (Index p = 0; p < P.size(); ++p)
    {
        t.mass += P.mass[p];
        for (int d = 0; d < 3; ++d) t.mom[d] += P.mass[p]*P.v[d][p];
    }
    return t;
}

Totals gridTotals(const MpmSystem& s)
{
    Totals t;
    const Lattice& L = s.lattice();
    for (int k = 0; k < L.nCells[2]; ++k)
    for (int j = 0; j < L.nCells[1]; ++j)
    for (int i = 0; i < L.nCells[0]; ++i)
    {
        const Index I = L.realNode(i, j, k);
        t.mass += s.grid().mass[I];
        for (int d = 0; d < 3; ++d) t.mom[d] += s.grid().mass[I]*s.grid().velocity[d][I];
    }
    return t;
}

MpmSystem periodicSystem(ShapeKind shape, int dim, Transfer transfer = Transfer::picFlip, Real alpha = 0, Index nPoints = 2000)
{
    MpmSystem s;
    BoundarySpec b;
    b.conditions = {WallCondition{WallType::periodic, 0}};
    StepOptions o;
    o.shape = shape; o.flipRatio = alpha; o.transfer = transfer;
    s.setup(box(12, dim > 1 ? 9 : 1, dim > 2 ? 8 : 1), b, o);
    s.materials().push_back(std::make_unique<NoStress>());
    seedRandom(s, nPoints, 0.0, 1.0);
    return s;
}

const ShapeKind allShapes[] = {ShapeKind::linearHat, ShapeKind::quadraticBSpline, ShapeKind::cubicBSpline};

} // namespace

TEST(Transfer, P2GConservesMassAndMomentum)
{
    for (auto shape : allShapes)
    for (int dim = 1; dim <= 3; ++dim)
    {
        MpmSystem s = periodicSystem(shape, dim);
        s.mapToGrid();
        const Totals tp = pointTotals(s.particles()), tg = gridTotals(s);
        EXPECT_NEAR(tg.mass, tp.mass, 1e-12*tp.mass) << shapeName(shape) << " " << dim << "D";
        for (int d = 0; d < 3; ++d) EXPECT_NEAR(tg.mom[d], tp.mom[d], 1e-11*tp.mass);
    }
}

TEST(Transfer, StepConservesMassAndMomentumPeriodic)
{
    // With no stress and no gravity, a full step (P2G, update, G2P) keeps
    // total momentum for PIC, FLIP and APIC on a periodic lattice.
    for (auto shape : allShapes)
    for (auto tr : {Transfer::picFlip, Transfer::apic})
    for (Real alpha : {0.0, 1.0})
    {
        MpmSystem s = periodicSystem(shape, 3, tr, alpha);
        s.mapToGrid();
        const Totals t0 = gridTotals(s);
        for (int n = 0; n < 3; ++n) s.step(1e-3);
        s.mapToGrid();
        const Totals t1 = gridTotals(s);
        EXPECT_NEAR(t1.mass, t0.mass, 1e-12*t0.mass);
        for (int d = 0; d < 3; ++d) EXPECT_NEAR(t1.mom[d], t0.mom[d], 1e-11*t0.mass) << shapeName(shape);
    }
}

TEST(Transfer, RigidTranslationExactUnderPIC)
{
    for (auto shape : allShapes)
    {
        MpmSystem s = periodicSystem(shape, 3, Transfer::picFlip, 0.0);
        auto& P = s.particles();
        const Real u[3] = {0.3, -0.2, 0.1};
        StaggeredArray<Real> x0[3];
        for (int d = 0; d < 3; ++d) { for (Index p = 0; p < P.size(); ++p) P.v[d][p] = u[d]; x0[d] = P.x[d]; }
        const Real dt = 1e-3;
        s.step(dt);
        // The step may store the points in block order: find them by id
        for (Index p = 0; p < P.size(); ++p)
        for (int d = 0; d < 3; ++d)
        {
            EXPECT_NEAR(P.v[d][p], u[d], 1e-13);
            Real moved = P.x[d][p] - x0[d][P.id[p]];
            const Real len = s.lattice().length(d);
            if (moved > 0.5*len) moved -= len;
            if (moved < -0.5*len) moved += len;
            EXPECT_NEAR(moved, u[d]*dt, 1e-13);
        }
    }
}

TEST(Transfer, APICPreservesAffineField)
{
    // v = A x is represented exactly by APIC with B-splines on a periodic
    // lattice away from the wrap; test on interior points only.
    for (auto shape : {ShapeKind::quadraticBSpline, ShapeKind::cubicBSpline})
    {
        MpmSystem s;
        BoundarySpec b;
        StepOptions o; o.shape = shape; o.transfer = Transfer::apic;
        b.conditions = {WallCondition{WallType::slip, 0}};
        s.setup(box(16, 16, 16), b, o);
        s.materials().push_back(std::make_unique<NoStress>());
        seedRandom(s, 3000, 0.3, 0.7);
        const Real A[9] = {0.1, 0.2, -0.1, 0.05, -0.2, 0.3, 0.0, 0.1, 0.1};
        auto& P = s.particles();
        for (Index p = 0; p < P.size(); ++p)
        for (int i = 0; i < 3; ++i)
        {
            P.v[i][p] = A[3*i]*P.x[0][p] + A[3*i + 1]*P.x[1][p] + A[3*i + 2]*P.x[2][p];
            for (int j = 0; j < 3; ++j) P.C[3*i + j][p] = A[3*i + j];
        }
        auto v0 = P.v;
        s.step(1e-9);   // negligible motion: a pure transfer round trip
        for (Index p = 0; p < P.size(); ++p)   // by id: the step may reorder
        for (int i = 0; i < 3; ++i)
        {
            EXPECT_NEAR(P.v[i][p], v0[i][P.id[p]], 1e-7) << shapeName(shape);
            for (int j = 0; j < 3; ++j) EXPECT_NEAR(P.C[3*i + j][p], A[3*i + j], 1e-9);
        }
    }
}

TEST(Transfer, ThreadCountIndependent)
{
    // Colour-blocked P2G sums each node in a fixed order, so 1 and 2
    // threads give bitwise-identical points. The serial-loop threshold is
    // lowered so that 2 threads do run in parallel; consistent mass and
    // APIC exercise every kernel.
    for (auto shape : allShapes)
    for (auto transfer : {Transfer::picFlip, Transfer::apic})
    {
        std::array<StaggeredArray<Real>, 3> xs[2], vs[2];
        std::array<StaggeredArray<Real>, 6> sig[2];
        const Index threshold = MpmSystem::parallelThreshold;
        MpmSystem::parallelThreshold = 1000;   // every loop runs threaded
        for (int run = 0; run < 2; ++run)
        {
            omp_set_num_threads(run + 1);
            MpmSystem s = periodicSystem(shape, 3, transfer, 0.9, 20000);
            // A real stress, so the force scatter sums non-zero terms.
            s.materials()[0] = makeLaw("linearElastic", {{"rho", 1}, {"E", 10}, {"nu", 0.3}});
            StepOptions o = s.options();
            o.massMatrix = transfer == Transfer::apic ? MassMatrix::consistent : MassMatrix::lumped;
            s.setup(s.lattice(), BoundarySpec{{WallCondition{WallType::periodic, 0}}, {}}, o);
            for (int n = 0; n < 5; ++n) s.step(2e-3);
            xs[run] = s.particles().x; vs[run] = s.particles().v; sig[run] = s.particles().sigma;
        }
        omp_set_num_threads(2);
        MpmSystem::parallelThreshold = threshold;
        for (int d = 0; d < 3; ++d)
        {
            EXPECT_EQ(xs[0][d], xs[1][d]) << shapeName(shape);
            EXPECT_EQ(vs[0][d], vs[1][d]) << shapeName(shape);
        }
        for (int c = 0; c < 6; ++c) EXPECT_EQ(sig[0][c], sig[1][c]) << shapeName(shape);
        EXPECT_GT(std::abs(sig[0][XY][17]), 0.0);
    }
}

TEST(Transfer, P2gRowLoopChangesNoBit)
{
    // The 3D P2G without APIC adds each node's terms in the same order
    // whether it walks the node rows as vector loops or node by node, so
    // the run-time choice between them (step/p2gRowChoice.hpp) can never
    // change a result: forced rows, forced nodes and the automatic choice
    // (which alternates both while it times them) give the same bits. A
    // stress and USL/USF/MUSL make every scatter (mass, momentum, force,
    // the MUSL re-map) non-trivial.
    for (auto shape : allShapes)
    for (auto order : {StressUpdate::USL, StressUpdate::USF, StressUpdate::MUSL})
    {
        std::array<StaggeredArray<Real>, 3> xs[3], vs[3];
        std::array<StaggeredArray<Real>, 6> sig[3];
        const P2gRowLoop modes[3] = {P2gRowLoop::always, P2gRowLoop::never, P2gRowLoop::automatic};
        for (int run = 0; run < 3; ++run)
        {
            MpmSystem s = periodicSystem(shape, 3, Transfer::picFlip, 0.9, 3000);
            s.materials()[0] = makeLaw("linearElastic", {{"rho", 1}, {"E", 10}, {"nu", 0.3}});
            StepOptions o = s.options();
            o.stressUpdate = order;
            o.p2gRowLoop = modes[run];
            s.setup(s.lattice(), BoundarySpec{{WallCondition{WallType::periodic, 0}}, {}}, o);
            for (Index n = 0; n < P2gRowChoice::tuningSteps + 2; ++n) s.step(2e-3);
            EXPECT_TRUE(s.p2gRowChoice().decided());
            xs[run] = s.particles().x; vs[run] = s.particles().v; sig[run] = s.particles().sigma;
        }
        for (int run = 1; run < 3; ++run)
        {
            for (int d = 0; d < 3; ++d)
            {
                EXPECT_EQ(xs[0][d], xs[run][d]) << shapeName(shape) << " run " << run;
                EXPECT_EQ(vs[0][d], vs[run][d]) << shapeName(shape) << " run " << run;
            }
            for (int c = 0; c < 6; ++c) EXPECT_EQ(sig[0][c], sig[run][c]) << shapeName(shape) << " run " << run;
        }
        EXPECT_GT(std::abs(sig[0][XY][17]), 0.0);
    }
}

TEST(Transfer, P2gRowChoiceKeepsTheFasterLoop)
{
    // The automatic choice: rows in the warm-up, then alternating trials,
    // then the loop with the smaller summed trial time, for good.
    for (bool rowsFaster : {true, false})
    {
        P2gRowChoice c;
        for (Index step = 0; step < P2gRowChoice::tuningSteps; ++step)
        {
            const bool rows = c.rows(step);
            if (step < P2gRowChoice::warmupSteps) EXPECT_TRUE(rows);
            else EXPECT_EQ(rows, (step - P2gRowChoice::warmupSteps) % 2 == 0);
            EXPECT_FALSE(c.decided());
            // Two scatters per step (USL with MUSL-like re-map): both count
            const double t = rows == rowsFaster ? 1.0 : 1.5;
            c.record(step, rows, t);
            c.record(step, rows, t);
        }
        for (Index step = P2gRowChoice::tuningSteps; step < P2gRowChoice::tuningSteps + 5; ++step)
        {
            EXPECT_EQ(c.rows(step), rowsFaster);
            c.record(step, !rowsFaster, 0.0);   // after the choice, times are ignored
        }
        EXPECT_TRUE(c.decided());
        EXPECT_LT(c.trialSeconds(rowsFaster), c.trialSeconds(!rowsFaster));
    }
    EXPECT_TRUE(P2gRowChoice(P2gRowLoop::always).rows(0));
    EXPECT_FALSE(P2gRowChoice(P2gRowLoop::never).rows(0));
    EXPECT_FALSE(P2gRowChoice(P2gRowLoop::never).rows(100));
}

TEST(Boundary, NoSlipWallVelocityVanishesOnWall)
{
    // Ghost mirroring makes the interpolated velocity zero on a no-slip
    // wall plane for every kernel.
    for (auto shape : allShapes)
    {
        MpmSystem s;
        BoundarySpec b;   // default: noSlip everywhere
        StepOptions o; o.shape = shape; o.flipRatio = 0;
        s.setup(box(10, 1, 1, 1.0), b, o);
        s.materials().push_back(std::make_unique<NoStress>());
        for (int i = 0; i < 20; ++i) s.particles().add({0.25 + 0.5*i, 0.5, 0.5}, {1.0, 0, 0}, 1.0, 0.5, 0);
        s.mapToGrid();
        // Evaluate the grid velocity at x = 0 with the same stencil.
        const Lattice& L = s.lattice();
        Real vWall = 0;
        dispatchShape(shape, [&](auto k)
        {
            Stencil<decltype(k), 1> st;
            st.compute(L, 0.0, 0.5, 0.5);
            st.forEach(L, [&](Index I, Real N, const Real*, const Real*) { vWall += N*s.grid().velocity[0][I]; });
        });
        EXPECT_NEAR(vWall, 0.0, 1e-14) << shapeName(shape);
    }
}

TEST(Boundary, SlipWallReleasesLeavingMaterialAndHoldsApproaching)
{
    // Points touching a slip wall: moving away they keep their velocity
    // exactly (the wall is unilateral); moving towards it they are stopped
    // in the normal direction near the wall.
    for (auto shape : allShapes)
    for (Real u : {1.0, -1.0})
    {
        MpmSystem s;
        BoundarySpec b;
        b.conditions = {WallCondition{WallType::slip, 0}};
        StepOptions o; o.shape = shape; o.flipRatio = 0;
        s.setup(box(10, 1, 1, 1.0), b, o);
        s.materials().push_back(std::make_unique<NoStress>());
        for (int i = 0; i < 8; ++i) s.particles().add({0.25 + 0.5*i, 0.5, 0.5}, {u, 0, 0}, 1.0, 0.5, 0);
        s.step(1e-6);
        const Real v0 = s.particles().v[0][0];
        if (u > 0) EXPECT_NEAR(v0, u, 1e-12) << shapeName(shape) << " leaving";
        else EXPECT_LT(std::abs(v0), 0.9*std::abs(u)) << shapeName(shape) << " approaching";
    }
}

TEST(Boundary, GravityNextToWallsSameForUSFAndUSL)
{
    // Points at rest and stress free on a floor under gravity: after one
    // step USF and USL must give the same point velocities (the stress is
    // zero either way), whatever the floor. USF used to add gravity after
    // the mass fold, when each wall ghost holds a copy of its image's
    // mass: the fold then cancelled the image's weight at a no-slip floor
    // and doubled its tangential part at a slip one.
    for (auto shape : allShapes)
    for (auto wall : {WallType::noSlip, WallType::slip, WallType::friction})
    {
        StaggeredArray<Real> vy[2];
        for (auto update : {StressUpdate::USL, StressUpdate::USF})
        {
            MpmSystem s;
            BoundarySpec b;
            b.conditions = {WallCondition{wall, 0.3}};
            StepOptions o;
            o.shape = shape; o.stressUpdate = update; o.flipRatio = 0;
            o.gravity = {0.5, -9.81, 0};   // a tangential part for slip walls
            s.setup(box(8, 8, 1, 0.1), b, o);
            s.materials().push_back(makeLaw("linearElastic", {{"rho", 1000}, {"E", 1e4}, {"nu", 0.3}}));
            for (int j = 0; j < 6; ++j)
            for (int i = 0; i < 12; ++i)
            {
                s.particles().add({0.1 + 0.05*i + 0.025, 0.05*j + 0.025, 0.05}, {0, 0, 0}, 2.5, 2.5e-3, 0);
            }
            s.step(1e-3);
            vy[update == StressUpdate::USF] = s.particles().v[1];
        }
        Real worst = 0;
        for (std::size_t p = 0; p < vy[0].size(); ++p) worst = std::max(worst, std::abs(vy[0][p] - vy[1][p]));
        EXPECT_LE(worst, 1e-15) << shapeName(shape) << " " << wallTypeName(wall);
        // Near the floor the wall matters: not free fall everywhere
        Real vmin = 0, vmax = -1;
        for (Real v : vy[0]) { vmin = std::min(vmin, v); vmax = std::max(vmax, v); }
        EXPECT_LT(vmin, -0.5*9.81e-3) << shapeName(shape);
    }
}

TEST(Transfer, ReorderingPointsChangesOnlyRoundOff)
{
    // Random seeding leaves the storage order unrelated to space, so the
    // step stores the points in block order (reorderPoints). The binning is
    // stable, so that step's sums keep their order; a point entering a
    // block later takes its place by storage index, which the reordering
    // changed, so later sums may add in another order: each point, found
    // by id, ends where it ends without the reordering, to round-off.
    for (auto shape : allShapes)
    {
        std::vector<Real> x[2], v[2], s[2];
        std::vector<std::int64_t> firstIds[2];
        for (int reorder = 0; reorder < 2; ++reorder)
        {
            MpmSystem sys = periodicSystem(shape, 3, Transfer::apic, 0, 3000);
            sys.materials()[0] = makeLaw("linearElastic", {{"rho", 1}, {"E", 10}, {"nu", 0.3}});
            StepOptions o = sys.options();
            o.reorderPoints = reorder == 1;
            sys.setup(sys.lattice(), BoundarySpec{{WallCondition{WallType::periodic, 0}}, {}}, o);
            for (int n = 0; n < 5; ++n) sys.step(2e-3);
            const Particles& P = sys.particles();
            firstIds[reorder].assign(P.id.begin(), P.id.begin() + 10);
            x[reorder].resize(P.size()); v[reorder].resize(P.size()); s[reorder].resize(P.size());
            for (Index p = 0; p < P.size(); ++p)
            {
                x[reorder][P.id[p]] = P.x[0][p];
                v[reorder][P.id[p]] = P.v[1][p];
                s[reorder][P.id[p]] = P.sigma[XY][p];
            }
        }
        EXPECT_NE(firstIds[0], firstIds[1]) << "the points were not reordered";
        Real dx = 0, dv = 0, ds = 0, vmax = 0, smax = 0;
        for (std::size_t p = 0; p < x[0].size(); ++p)
        {
            dx = std::max(dx, std::abs(x[0][p] - x[1][p]));
            dv = std::max(dv, std::abs(v[0][p] - v[1][p]));
            ds = std::max(ds, std::abs(s[0][p] - s[1][p]));
            vmax = std::max(vmax, std::abs(v[0][p]));
            smax = std::max(smax, std::abs(s[0][p]));
        }
        EXPECT_LE(dx, 1e-14) << shapeName(shape);
        EXPECT_LE(dv, 1e-12*vmax) << shapeName(shape);
        EXPECT_LE(ds, 1e-12*smax) << shapeName(shape);
    }
}

namespace {

// The 3D lattice of the kernel-level tests below
Lattice smallLattice()
{
    Lattice L;
    L.h = 0.1;
    L.nCells = {9, 8, 7};
    L.finalise();
    return L;
}

// Zeroed arrays for raw views, alive as long as the store (a deque: adding
// one moves none)
struct ArrayStore
{
    std::deque<std::vector<Real>> arrays;
    Real* operator()(Index n) { arrays.emplace_back(n, 0.0); return arrays.back().data(); }
};

} // namespace

// The 3D P2G without APIC scatters row by row as one vector loop
// (kernels/p2g.hpp); the APIC scatter goes node by node through
// Stencil::forEach. With C = 0 the APIC momentum is v + 0 exactly, so both
// must leave the same bits on every node, for every shape function: the
// row loop gives each node the same terms, in the same order.
TEST(Transfer, RowScatterEqualsNodeByNode)
{
    auto run = [](auto k)
    {
        using K = decltype(k);
        const Lattice L = smallLattice();
        const Index np = 500;
        ArrayStore array;
        PointView P;
        P.n = np;
        for (int d = 0; d < 3; ++d) { P.x[d] = array(np); P.v[d] = array(np); }
        for (int e = 0; e < 9; ++e) P.C[e] = array(np);
        for (int c = 0; c < 6; ++c) P.sigma[c] = array(np);
        P.mass = array(np);
        P.volume = array(np);
        std::vector<int> material(np, 0);
        P.material = material.data();
        std::mt19937 rng(7);
        std::uniform_real_distribution<Real> u(0, 1);
        for (Index p = 0; p < np; ++p)
        {
            for (int d = 0; d < 3; ++d)
            {
                P.x[d][p] = L.h*(2 + u(rng)*(L.nCells[d] - 4));
                P.v[d][p] = u(rng) - 0.5;
            }
            for (int c = 0; c < 6; ++c) P.sigma[c][p] = 1e3*(u(rng) - 0.5);
            P.mass[p] = 1 + u(rng);
            P.volume[p] = 1e-3*(1 + u(rng));
        }
        auto grid = [&]()
        {
            GridView g;
            g.n = L.nNodes;
            g.mass = array(g.n);
            g.volume = array(g.n);
            for (int d = 0; d < 3; ++d) { g.momentum[d] = array(g.n); g.force[d] = array(g.n); }
            return g;
        };
        const GridView rows = grid(), nodes = grid();
        const Real invRho0 = 1e-3;
        for (Index p = 0; p < np; ++p)
        {
            p2gPoint<K, 3, true, true, false>(L, P, rows, &invRho0, false, p, PlainAdd{});
            p2gPoint<K, 3, true, true, true>(L, P, nodes, &invRho0, false, p, PlainAdd{});
        }
        Index touched = 0;
        for (Index I = 0; I < L.nNodes; ++I)
        {
            touched += rows.mass[I] != 0;
            ASSERT_EQ(rows.mass[I], nodes.mass[I]) << "width " << K::width << ", node " << I;
            ASSERT_EQ(rows.volume[I], nodes.volume[I]);
            for (int d = 0; d < 3; ++d)
            {
                ASSERT_EQ(rows.momentum[d][I], nodes.momentum[d][I]);
                ASSERT_EQ(rows.force[d][I], nodes.force[d][I]);
            }
        }
        EXPECT_GT(touched, 100);
    };
    run(LinearHat{});
    run(QuadraticBSpline{});
    run(CubicBSpline{});
}

// The host's G2P from the packed node velocities (kernels/g2p.hpp:
// g2pPackedPoints, one and two points at a time, its sums factored by
// rows) must agree with g2pPoint's node loop over the six velocity arrays,
// which the device runs, to round-off; one and two at a time must give the
// same bits (the same sums per point).
#ifdef MPM_HOST_LANES
TEST(Transfer, PackedGatherAgreesWithNodeByNode)
{
    auto run = [](auto k)
    {
        using K = decltype(k);
        const Lattice L = smallLattice();
        const Index np = 501;
        ArrayStore array;
        std::mt19937 rng(11);
        std::uniform_real_distribution<Real> u(0, 1);
        GridView g;
        g.n = L.nNodes;
        for (int d = 0; d < 3; ++d)
        {
            g.velocity[d] = array(g.n);
            g.velocityOld[d] = array(g.n);
            for (Index I = 0; I < g.n; ++I)
            {
                g.velocity[d][I] = u(rng) - 0.5;
                g.velocityOld[d][I] = u(rng) - 0.5;
            }
        }
        std::vector<Real> pack(8*g.n, 0.0);
        for (Index I = 0; I < g.n; ++I) packNodeVelocity(g, pack.data(), I);
        // Three copies of the points: node loop, one and two at a time
        PointView P[3];
        for (int c = 0; c < 3; ++c)
        {
            P[c].n = np;
            for (int d = 0; d < 3; ++d) { P[c].x[d] = array(np); P[c].v[d] = array(np); P[c].dx[d] = array(np); }
            for (int e = 0; e < 9; ++e) P[c].L[e] = array(np);
        }
        for (Index p = 0; p < np; ++p)
        for (int d = 0; d < 3; ++d)
        {
            const Real x = L.h*(2 + u(rng)*(L.nCells[d] - 4)), v = u(rng) - 0.5;
            for (int c = 0; c < 3; ++c) { P[c].x[d][p] = x; P[c].v[d][p] = v; }
        }
        GridView packed = g;
        packed.velocityPack = pack.data();
        const Real flip = 0.97, dt = 1e-3;
        for (Index p = 0; p < np; ++p)
        {
            g2pPoint<K, 3, false>(L, P[0], g, flip, dt, p);
            g2pPackedPoints<K, 1>(L, P[1], packed, flip, dt, &p);
        }
        for (Index p = 0; p + 1 < np; p += 2)
        {
            const Index pair[2] = {p, p + 1};
            g2pPackedPoints<K, 2>(L, P[2], packed, flip, dt, pair);
        }
        const Index last = np - 1;
        g2pPackedPoints<K, 1>(L, P[2], packed, flip, dt, &last);
        // Round-off: relative to each field's largest value (the sums have
        // at most 64 terms of that size)
        auto scale = [&](Real* const* f, int components)
        {
            Real m = 0;
            for (int c = 0; c < components; ++c) for (Index p = 0; p < np; ++p) m = std::max(m, std::abs(f[c][p]));
            return m;
        };
        const Real sv = scale(P[0].v, 3), sdx = scale(P[0].dx, 3), sL = scale(P[0].L, 9);
        const Real tol = 1e-14;
        for (Index p = 0; p < np; ++p)
        {
            for (int d = 0; d < 3; ++d)
            {
                ASSERT_NEAR(P[1].v[d][p], P[0].v[d][p], tol*sv) << "width " << K::width << ", point " << p;
                ASSERT_NEAR(P[1].dx[d][p], P[0].dx[d][p], tol*sdx);
                ASSERT_EQ(P[2].v[d][p], P[1].v[d][p]);
                ASSERT_EQ(P[2].dx[d][p], P[1].dx[d][p]);
            }
            for (int e = 0; e < 9; ++e)
            {
                ASSERT_NEAR(P[1].L[e][p], P[0].L[e][p], tol*sL) << "width " << K::width << ", point " << p;
                ASSERT_EQ(P[2].L[e][p], P[1].L[e][p]);
            }
        }
        // The gather did something
        EXPECT_NE(P[0].L[0][np/2], 0.0);
        EXPECT_NE(P[0].dx[1][np/2], 0.0);
    };
    run(LinearHat{});
    run(QuadraticBSpline{});
    run(CubicBSpline{});
}
#endif

namespace {

// The spread onto a partly covered lattice, point by point as its
// definition says (MpmSystem::setCoverage): each point's N v over the
// covered share of its stencil, nothing from a point with none
// (second: the grain volume of the points with a covered node)
template<class K, int D>
std::pair<std::vector<Real>, Real> spreadByDefinition(const MpmSystem& s, const std::vector<double>& coverage)
{
    const Lattice& L = s.lattice();
    const Particles& P = s.particles();
    std::vector<Real> out(std::size_t(L.nNodes), 0.0);
    Real volume = 0;
    for (Index p = 0; p < P.size(); ++p)
    {
        Stencil<K, D> st;
        st.compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
        Real covered = 0;
        st.forEach(L, [&](Index I, Real N, const Real*, const Real*) { covered += N*coverage[std::size_t(I)]; });
        if (!(covered > 0)) continue;
        const Real v = P.mass[p]/s.material(P.material[p]).rho0();
        volume += v;
        st.forEach(L, [&](Index I, Real N, const Real*, const Real*) { out[std::size_t(I)] += N*v/covered; });
    }
    return {out, volume};
}

} // namespace

// mapToGrid(&spread) + spreadGrainVolume against the definition, on a
// lattice whose coverage is 1 (to within fullCoverage) on its low x side,
// partial on two planes and 0 beyond: the points whose stencil is all
// covered keep their P2G volume, the others are renormalised. A shortcut
// taken for a point whose stencil reaches a partly covered node (a stencil
// window too short for the shape, or a first node one off) is off by the
// renormalisation, about 10 %.
TEST(Transfer, CoverageSpreadMatchesItsDefinition)
{
    for (const ShapeKind shape : allShapes)
    for (const int dim : {2, 3})
    {
        MpmSystem s;
        BoundarySpec b;
        StepOptions o;
        o.shape = shape;
        s.setup(box(14, 9, dim > 2 ? 8 : 1), b, o);
        s.materials().push_back(std::make_unique<NoStress>());
        s.setConstantGrainVolume(true);
        seedRandom(s, 3000, 0.02, 0.98);
        const Lattice& L = s.lattice();
        std::vector<double> coverage(std::size_t(L.nNodes), 0.0);
        for (int k = 0; k < L.nCells[2]; ++k)
        for (int j = 0; j < L.nCells[1]; ++j)
        for (int i = 0; i < L.nCells[0]; ++i)
        {
            // Round-off in the full part, as the exact overlaps give
            double c = i < 8 ? 1 - 1e-15*((i + j + k) % 3) : i == 8 ? 0.7 : i == 9 ? 0.25 : 0;
            coverage[std::size_t(L.realNode(i, j, k))] = c;
        }
        s.setCoverage(coverage);
        std::vector<Real> spread;
        s.mapToGrid(&spread);
        s.spreadGrainVolume(spread);
        std::vector<Real> expected;
        Real points = 0;
        dispatchShape(shape, [&](auto k)
        {
            std::tie(expected, points) = dim == 3 ? spreadByDefinition<decltype(k), 3>(s, coverage)
                                                  : spreadByDefinition<decltype(k), 2>(s, coverage);
        });
        Real worst = 0, largest = 0, onMesh = 0;
        for (std::size_t I = 0; I < spread.size(); ++I)
        {
            worst = std::max(worst, std::abs(spread[I] - expected[I]));
            largest = std::max(largest, std::abs(expected[I]));
            onMesh += coverage[I]*spread[I];
        }
        // The points beyond the covered part give nothing
        Real all = 0;
        for (Index p = 0; p < s.particles().size(); ++p) all += s.particles().mass[p]/s.material(0).rho0();
        EXPECT_LT(points, 0.9*all);
        EXPECT_LT(worst, 1e-12*largest) << "shape " << int(shape) << ", " << dim << "D";
        EXPECT_NEAR(onMesh/points, 1.0, 1e-12) << "shape " << int(shape) << ", " << dim << "D";
    }
}

// The sparse grid (grid/activeRegion.hpp) is an optimisation, not a model:
// a body moving through a larger box must give bitwise the dense step's
// points and grid (its real nodes), whatever the walls (no-slip, slip with contact release,
// friction, periodic seams, outlets), the transfer, the stress update, the mass
// matrix and the coupling. The bodies are small against the box, move
// across it and hit its walls, so nodes enter and leave the region.
#include "testHelpers.hpp"
#include <gtest/gtest.h>

using namespace mpm;
using namespace mpm::test;

namespace {

struct Variant
{
    const char* name;
    ShapeKind shape;
    Transfer transfer;
    StressUpdate update;
    MassMatrix mass;
    int dim;
    bool periodicX;
    bool coupled;
    bool outletX = false;    // the x = 0 side an outlet: the body leaves
};

struct Result
{
    Particles points;
    GridState grid;
    std::array<std::vector<Real>, 3> velocityIntegral;
    Index regionNodes = 0;     // the active region of the first step
    Index latticeNodes = 0;
};

Result run(const Variant& v, bool sparse)
{
    MpmSystem s;
    BoundarySpec b;
    // floor friction, sides slip, others no-slip; x periodic when asked
    b.conditions = {WallCondition{WallType::noSlip, 0}, WallCondition{WallType::slip, 0},
                    WallCondition{WallType::friction, 0.4}, WallCondition{WallType::periodic, 0},
                    WallCondition{WallType::outlet, 0}};
    const int nx = 40, ny = v.dim > 1 ? 16 : 1, nz = v.dim > 2 ? 12 : 1;
    Lattice L = box(nx, ny, nz);
    L.finalise();
    auto sideFaces = [&](int side) { const int a = side/2;
        return (a == 0 ? ny*nz : a == 1 ? nx*nz : nx*ny); };
    for (int side = 0; side < 6; ++side)
    {
        const int a = side/2;
        if (!L.solved[a]) continue;
        int cond = a == 0 ? (v.periodicX ? 3 : 1) : (side == 2 ? 2 : (a == 2 ? 0 : 1));
        if (side == 0 && v.outletX) cond = 4;
        b.faceCondition[side].assign(sideFaces(side), cond);
    }
    StepOptions o;
    o.shape = v.shape; o.transfer = v.transfer; o.stressUpdate = v.update;
    o.massMatrix = v.mass; o.flipRatio = 0.95;
    o.gravity = {0, v.dim > 1 ? -9.81 : 0.0, 0};
    o.sparseGrid = sparse;
    s.setup(L, b, o);
    s.materials().push_back(makeLaw("linearElastic", {{"rho", 1000}, {"E", 500}, {"nu", 0.3}}));
    // A small body near the low corner, thrown at the x = 0 wall (or
    // through the periodic seam), and falling
    seedRandom(s, 600, 0.05, 0.3, 7);
    auto& P = s.particles();
    for (Index p = 0; p < P.size(); ++p)
    {
        P.mass[p] *= 0.1;
        P.volume0[p] = P.volume[p] = 1e-4;
        P.v[0][p] = -3.0 + 0.2*P.v[0][p];
        P.v[1][p] *= 0.5;
    }
    if (v.coupled)
    {
        auto& c = s.coupling();
        const Index n = s.lattice().nNodes;
        c.resize(n);
        for (auto& a : c.fluidAcceleration) a.assign(n, 0.0);
        for (Index I = 0; I < n; ++I)
        {
            c.K[I] = 0.5 + 0.001*Real(I % 97);
            c.U[0][I] = 0.3*std::sin(0.01*Real(I));
            c.F[1][I] = 5.0;
        }
        c.addedMassDensity = 500;
    }
    Result r;
    for (int n = 0; n < 60; ++n)
    {
        s.step(2e-3);
        if (n == 0) r.regionNodes = s.activeNodeCount();
    }
    r.latticeNodes = s.lattice().nNodes;
    s.mapToGrid();
    r.points = s.particles();
    // The grid on the real nodes (what the fluid and the output read; a
    // ghost outside the region is never read, and the dense step fills it)
    const Lattice& La = s.lattice();
    auto real = [&](const auto& a)
    {
        StaggeredArray<Real> out;
        for (int k = 0; k < La.nCells[2]; ++k)
        for (int j = 0; j < La.nCells[1]; ++j)
        for (int i = 0; i < La.nCells[0]; ++i) out.push_back(a[La.realNode(i, j, k)]);
        return out;
    };
    const GridState& g = s.grid();
    r.grid.mass = real(g.mass);
    r.grid.volume = real(g.volume);
    for (int d = 0; d < 3; ++d)
    {
        r.grid.momentum[d] = real(g.momentum[d]);
        r.grid.velocity[d] = real(g.velocity[d]);
        if (v.coupled)
        {
            const StaggeredArray<Real> vi = real(s.coupling().velocityIntegral[d]);
            r.velocityIntegral[d].assign(vi.begin(), vi.end());
        }
    }
    return r;
}

} // namespace

TEST(ActiveRegion, SparseStepEqualsDenseBitwise)
{
    const Variant variants[] =
    {
        {"3D QBS PIC/FLIP USL lumped", ShapeKind::quadraticBSpline, Transfer::picFlip, StressUpdate::USL, MassMatrix::lumped, 3, false, false},
        {"3D CBS APIC MUSL lumped, periodic x", ShapeKind::cubicBSpline, Transfer::apic, StressUpdate::MUSL, MassMatrix::lumped, 3, true, false},
        {"3D QBS PIC/FLIP MUSL consistent", ShapeKind::quadraticBSpline, Transfer::picFlip, StressUpdate::MUSL, MassMatrix::consistent, 3, false, false},
        {"3D LH PIC/FLIP USF lumped", ShapeKind::linearHat, Transfer::picFlip, StressUpdate::USF, MassMatrix::lumped, 3, false, false},
        {"2D CBS PIC/FLIP USL lumped, periodic x, coupled", ShapeKind::cubicBSpline, Transfer::picFlip, StressUpdate::USL, MassMatrix::lumped, 2, true, true},
        {"2D QBS APIC USL lumped, coupled", ShapeKind::quadraticBSpline, Transfer::apic, StressUpdate::USL, MassMatrix::lumped, 2, false, true},
        {"2D LH PIC/FLIP USL consistent, coupled", ShapeKind::linearHat, Transfer::picFlip, StressUpdate::USL, MassMatrix::consistent, 2, false, true},
        {"2D CBS PIC/FLIP USL lumped, coupled, outlet x", ShapeKind::cubicBSpline, Transfer::picFlip, StressUpdate::USL, MassMatrix::lumped, 2, false, true, true},
        {"3D QBS PIC/FLIP MUSL consistent, outlet x", ShapeKind::quadraticBSpline, Transfer::picFlip, StressUpdate::MUSL, MassMatrix::consistent, 3, false, false, true},
        {"3D QBS APIC MUSL lumped, outlet x", ShapeKind::quadraticBSpline, Transfer::apic, StressUpdate::MUSL, MassMatrix::lumped, 3, false, false, true},
    };
    for (const Variant& v : variants)
    {
        Result dense, sparse;
        try { dense = run(v, false); sparse = run(v, true); }
        catch (const std::exception& e) { ADD_FAILURE() << v.name << ": " << e.what(); continue; }
        for (int d = 0; d < 3; ++d)
        {
            EXPECT_EQ(dense.points.x[d], sparse.points.x[d]) << v.name;
            EXPECT_EQ(dense.points.v[d], sparse.points.v[d]) << v.name;
            EXPECT_EQ(dense.grid.velocity[d], sparse.grid.velocity[d]) << v.name;
            EXPECT_EQ(dense.grid.momentum[d], sparse.grid.momentum[d]) << v.name;
            if (v.coupled) EXPECT_EQ(dense.velocityIntegral[d], sparse.velocityIntegral[d]) << v.name;
        }
        for (int c = 0; c < 6; ++c) EXPECT_EQ(dense.points.sigma[c], sparse.points.sigma[c]) << v.name;
        EXPECT_EQ(dense.grid.mass, sparse.grid.mass) << v.name;
        EXPECT_EQ(dense.grid.volume, sparse.grid.volume) << v.name;
        // The region was a part of the lattice; the body reached the wall
        // (or crossed the seam: points near the far end)
        EXPECT_LT(sparse.regionNodes, sparse.latticeNodes/2) << v.name;
        EXPECT_EQ(dense.regionNodes, dense.latticeNodes) << v.name;
        Real xmin = 10, xmax = 0;
        for (Real x : sparse.points.x[0]) { xmin = std::min(xmin, x); xmax = std::max(xmax, x); }
        if (v.periodicX) EXPECT_GT(xmax, 3.6) << v.name;
        else if (!v.outletX) EXPECT_LT(xmin, 0.05) << v.name;
        // Through an outlet: some points left (the same ones, above)
        if (v.outletX) EXPECT_LT(sparse.points.size(), Index(600)) << v.name;
        if (v.outletX) EXPECT_GT(sparse.points.size(), Index(0)) << v.name;
    }
}

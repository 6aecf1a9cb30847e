// Open faces (grid/boundary.hpp): no mirror ghost beyond an outlet or an
// inlet, free nodes there (the inlet's carrying its velocity), and the
// removal of the points that cross them, counted per condition; a point
// that would cross a wall is clamped and counted.
#include "testHelpers.hpp"
#include <gtest/gtest.h>

using namespace mpm;
using namespace mpm::test;

namespace {

// 2D box nx x ny, h = 0.1: the floor (y-) condition `floor`, the top `top`,
// the sides slip
BoundarySpec spec(const Lattice& L, WallType floor, WallType top)
{
    BoundarySpec b;
    b.conditions = {WallCondition{WallType::slip, 0}, WallCondition{floor, 0}, WallCondition{top, 0}};
    b.conditions[2].velocity = {0, -0.5, 0};
    for (int side = 0; side < 4; ++side)
    {
        const int n = side < 2 ? L.nCells[1] : L.nCells[0];
        b.faceCondition[side].assign(n, side == 2 ? 1 : side == 3 ? 2 : 0);
    }
    return b;
}

} // namespace

TEST(OpenBoundary, NoMirrorBeyondOpenFaces)
{
    Lattice L = box(8, 6, 1);
    L.finalise();
    Boundary b;
    b.build(L, spec(L, WallType::outlet, WallType::inlet));
    // No wall ghost lies beyond the floor or the top alone: only the side
    // ghosts (and the corners beyond a side and an open face) mirror
    for (const auto& g : b.ghosts())
    {
        const int j = int((g.ghost/L.stride[1]) % L.nodes[1]) - L.pad;
        const int i = int((g.ghost/L.stride[0]) % L.nodes[0]) - L.pad;
        EXPECT_TRUE(i < 0 || i >= L.nCells[0]) << "ghost at (" << i << ", " << j << ")";
    }
    // Free nodes: pad layers below the floor and above the top, nx wide
    EXPECT_EQ(b.freeNodes().size(), std::size_t(2*L.pad*L.nCells[0]));
    EXPECT_EQ(b.inletNodes().size(), std::size_t(L.pad*L.nCells[0]));
    for (const auto& in : b.inletNodes()) EXPECT_EQ(in.condition, 2);
    EXPECT_TRUE(b.hasOpenFaces());
    // The same box with walls: a mirror for every node beyond the box
    Boundary w;
    w.build(L, spec(L, WallType::slip, WallType::noSlip));
    EXPECT_TRUE(w.freeNodes().empty());
    EXPECT_FALSE(w.hasOpenFaces());
    EXPECT_EQ(w.ghosts().size(), std::size_t(L.nNodes - L.nRealNodes));
}

TEST(OpenBoundary, PointsLeavingAreRemovedAndCounted)
{
    for (ShapeKind shape : {ShapeKind::linearHat, ShapeKind::quadraticBSpline, ShapeKind::cubicBSpline})
    {
        Lattice L = box(8, 10, 1);
        L.finalise();
        MpmSystem s;
        StepOptions o;
        o.shape = shape;
        o.gravity = {0, -10, 0};
        s.setup(L, spec(L, WallType::outlet, WallType::slip), o);
        // Stress-free: a uniform velocity field, exact free fall
        s.materials().push_back(std::make_unique<NoStress>());
        // A column of points in free fall, rows 0.05 apart from y = 0.025
        for (int r = 0; r < 12; ++r)
        for (int c = 0; c < 8; ++c)
        {
            s.particles().add({0.21 + 0.05*c, 0.025 + 0.05*r, 0}, {0, 0, 0}, 1.0 + r, 2.5e-3, 0);
        }
        const Real dt = 1e-3;
        for (int n = 1; n <= 200; ++n)
        {
            s.step(dt);
            // Discrete free fall: g dt^2 n (n + 1)/2; removed: the rows below
            const Real fall = 10*dt*dt*n*(n + 1)/2;
            Index count = 0;
            Real mass = 0;
            for (int r = 0; r < 12; ++r)
            {
                if (0.025 + 0.05*r - fall < 0) { count += 8; mass += 8*(1.0 + r); }
            }
            ASSERT_EQ(s.removedCount()[1], count) << "step " << n << " shape " << shapeName(shape);
            ASSERT_NEAR(s.removedMass()[1], mass, 1e-12*mass) << "step " << n;
            ASSERT_EQ(s.particles().size(), 96 - count);
        }
        EXPECT_EQ(s.removedCount()[0], 0);
        EXPECT_EQ(s.clampedCount(), 0);
        // The four lowest rows (y0 < 0.201) have left, the rest fall on
        EXPECT_EQ(s.removedCount()[1], 32);
    }
}

TEST(OpenBoundary, WallCrossingIsClampedAndCounted)
{
    // A block thrown at a no-slip floor at two cells per step: points cross
    // the wall plane; put back inside and counted, none removed
    Lattice L = box(8, 10, 1);
    L.finalise();
    MpmSystem s;
    StepOptions o;
    s.setup(L, spec(L, WallType::noSlip, WallType::slip), o);
    s.materials().push_back(std::make_unique<NoStress>());
    for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 8; ++c)
    {
        s.particles().add({0.21 + 0.05*c, 0.325 + 0.05*r, 0}, {0, -200, 0}, 1.0, 2.5e-3, 0);
    }
    for (int n = 0; n < 5; ++n) s.step(1e-3);
    EXPECT_GT(s.clampedCount(), 0);
    EXPECT_EQ(s.particles().size(), 32);
    EXPECT_EQ(s.removedCount()[1], 0);
    for (Index p = 0; p < 32; ++p) EXPECT_GT(s.particles().x[1][p], 0.0);
}

// Level-set walls (grid/levelSet.hpp) against closed forms:
//   * the shapes' signed distances and normals;
//   * a block on a plane inclined at 20, 25 and 37 degrees, not aligned
//     with the lattice, under vertical gravity: frictionless it accelerates
//     at g sin(theta); with Coulomb friction mu at g (sin theta - mu cos
//     theta) above the friction angle, and it holds below it;
//   * a block sliding on a level-set floor placed between node layers
//     decelerates at mu g, as on the box's mirrored friction floor;
//   * containment: a disk thrown at a round obstacle at 0.5 and 2 wave
//     speeds, head-on and grazing, never has a point inside the obstacle
//     (exact distance) at the end of a step, and its energy stays bounded;
//   * an inlet wall's node condition and its leaving points.
#include "testHelpers.hpp"
#include "kernels/levelSetWall.hpp"
#include <gtest/gtest.h>
#include <cmath>

using namespace mpm;
using namespace mpm::test;

namespace {

constexpr Real g = 9.81;
constexpr Real rho = 1000, E = 1e6, nu = 0.3;
constexpr Real h = 0.05;
constexpr Real blockW = 0.4, blockH = 0.2;

Real waveSpeed() { return std::sqrt(E*(1 - nu)/((1 + nu)*(1 - 2*nu)*rho)); }

BoundarySpec allSlip()
{
    BoundarySpec b;
    b.conditions = {WallCondition{WallType::slip, 0}};
    return b;
}

WallCondition condition(Real mu)
{
    return mu > 0 ? WallCondition{WallType::friction, mu} : WallCondition{WallType::slip, 0};
}

// A 2D block (2 x 2 points per cell) resting on a plane through `origin`
// whose surface runs along t = (cos theta, -sin theta) with the material on
// the side of n = (sin theta, cos theta); vertical gravity. Its stress is
// the geostatic one of a layer in the slope's frame (sigma_nn = -rho g
// cos(theta) (H - r), the in-plane ones nu/(1 - nu) of it), so it does not
// bounce on landing. Returns the mass-weighted mean velocity along t over
// time.
History slideOnPlane
(
    Real mu, Real thetaDeg, Real u0, Real tEnd, const StepOptions& base,
    int nx, int ny, const std::array<Real, 3>& origin, Real s0
)
{
    const Real th = thetaDeg*M_PI/180;
    const Real t[2] = {std::cos(th), -std::sin(th)}, n[2] = {std::sin(th), std::cos(th)};
    const Lattice L = box(nx, ny, 1, h);
    StepOptions o = base;
    o.gravity = {0, -g, 0};
    MpmSystem s;
    s.setup(L, allSlip(), o);
    s.setLevelSetWalls
    (
        {LevelSetWall{"slope", std::make_shared<HalfSpaceShape>(origin, std::array<Real, 3>{n[0], n[1], 0}), condition(mu)}},
        {0, 0, 0.5*h}
    );
    s.materials().push_back(makeLaw("linearElastic", {{"rho", rho}, {"E", E}, {"nu", nu}}));
    const Real dp = 0.5*h, vol = dp*dp*h;
    for (int j = 0; j < int(blockH/dp + 0.5); ++j)
    for (int i = 0; i < int(blockW/dp + 0.5); ++i)
    {
        const Real ss = s0 + (i + 0.5)*dp, r = (j + 0.5)*dp;
        const std::array<Real, 3> x{origin[0] + ss*t[0] + r*n[0], origin[1] + ss*t[1] + r*n[1], 0.5*h};
        const Index p = s.particles().add(x, {u0*t[0], u0*t[1], 0}, rho*vol, vol, 0);
        const Real snn = -rho*g*std::cos(th)*(blockH - r), stt = nu/(1 - nu)*snn;
        auto& S = s.particles().sigma;
        S[0][p] = stt*t[0]*t[0] + snn*n[0]*n[0];
        S[1][p] = stt*t[1]*t[1] + snn*n[1]*n[1];
        S[2][p] = stt;
        S[3][p] = stt*t[0]*t[1] + snn*n[0]*n[1];
    }
    const Real dt = 0.3*h/waveSpeed();
    History r;
    const auto& P = s.particles();
    for (Real time = 0; time < tEnd; time += dt)
    {
        Real m = 0, mu0 = 0;
        for (Index p = 0; p < P.size(); ++p)
        {
            m += P.mass[p];
            mu0 += P.mass[p]*(P.v[0][p]*t[0] + P.v[1][p]*t[1]);
        }
        r.t.push_back(time);
        r.u.push_back(mu0/m);
        s.step(dt);
    }
    return r;
}

// The slope from near the box's upper left corner, reaching y = 0.5 m at
// x = 3 m; the block starts 0.3 m down it.
History slideDownSlope(Real mu, Real thetaDeg, Real tEnd, const StepOptions& o)
{
    const Real top = 3*std::tan(thetaDeg*M_PI/180) + 0.5;
    const int ny = int(std::ceil((top + 0.4)/h));
    return slideOnPlane(mu, thetaDeg, 0, tEnd, o, 60, ny, {0, top, 0}, 0.3);
}

const Real angles[] = {20, 25, 37};

} // namespace

TEST(LevelSetShapes, DistancesAndNormalsMatchClosedForms)
{
    Real n[3];
    const Real big = 1e9;
    const HalfSpaceShape plane({0, 1, 0}, {0, 2, 0});
    const Real a[3] = {3, 4, 5};
    EXPECT_DOUBLE_EQ(plane.distance(a, n, big), 3);
    EXPECT_DOUBLE_EQ(n[1], 1);

    const SphereShape ball({1, 1, 1}, 0.5);
    const Real b[3] = {1, 1, 3};
    EXPECT_DOUBLE_EQ(ball.distance(b, n, big), 1.5);
    EXPECT_DOUBLE_EQ(n[2], 1);
    const Real bi[3] = {1.2, 1, 1};
    EXPECT_NEAR(ball.distance(bi, n, big), -0.3, 1e-15);
    EXPECT_DOUBLE_EQ(n[0], 1);

    const CylinderShape cyl({0, 0, 0}, {0, 0, 2}, 1);
    const Real c1[3] = {3, 0, 1};        // beside the mantle
    EXPECT_DOUBLE_EQ(cyl.distance(c1, n, big), 2);
    EXPECT_DOUBLE_EQ(n[0], 1);
    const Real c2[3] = {0, 0.5, 2.5};    // above the top
    EXPECT_DOUBLE_EQ(cyl.distance(c2, n, big), 0.5);
    EXPECT_DOUBLE_EQ(n[2], 1);
    const Real c3[3] = {4, 0, -4};       // beyond the rim
    EXPECT_DOUBLE_EQ(cyl.distance(c3, n, big), 5);
    EXPECT_NEAR(n[0], 0.6, 1e-15);
    EXPECT_NEAR(n[2], -0.8, 1e-15);
    const Real c4[3] = {0.9, 0, 1};      // inside, near the mantle
    EXPECT_NEAR(cyl.distance(c4, n, big), -0.1, 1e-15);
    EXPECT_DOUBLE_EQ(n[0], 1);

    const BoxShape bx({0, 0, 0}, {1, 2, 3});
    const Real d1[3] = {0.5, 1, 3.25};
    EXPECT_DOUBLE_EQ(bx.distance(d1, n, big), 0.25);
    EXPECT_DOUBLE_EQ(n[2], 1);
    const Real d2[3] = {0.9, 1, 1.5};    // inside, nearest the x+ face
    EXPECT_NEAR(bx.distance(d2, n, big), -0.1, 1e-15);
    EXPECT_DOUBLE_EQ(n[0], 1);
}

TEST(LevelSetShapes, NodesStoreTheNearestWall)
{
    const Lattice L = box(20, 20, 1, 0.1);
    LevelSetWalls ls;
    Lattice Lf = L;
    Lf.finalise();
    ls.build(Lf,
    {
        {"floor", std::make_shared<HalfSpaceShape>(std::array<Real, 3>{0, 0.33, 0}, std::array<Real, 3>{0, 1, 0}), {}},
        {"ball", std::make_shared<SphereShape>(std::array<Real, 3>{1, 1, 0.05}, 0.3), {}}
    }, {0, 0, 0.05});
    // Node (real 3, 1): centre (0.35, 0.15): 0.18 under the floor
    const LevelSetView v = ls.view();
    const Index I = Lf.realNode(3, 1, 0);
    EXPECT_NEAR(v.phi[I], -0.18, 1e-14);
    EXPECT_EQ(v.wall[I], 0);
    // Node (10, 10): centre (1.05, 1.05), 0.3 - 0.0707 inside the ball
    const Index J = Lf.realNode(10, 10, 0);
    EXPECT_NEAR(v.phi[J], std::sqrt(2*0.05*0.05) - 0.3, 1e-14);
    EXPECT_EQ(v.wall[J], 1);
    EXPECT_NEAR(v.normal[0][J], std::sqrt(0.5), 1e-14);
    EXPECT_THROW(ls.build(Lf, {{"out", std::make_shared<SphereShape>(std::array<Real, 3>{1, 1, 0}, 0.3),
                                WallCondition{WallType::outlet, 0}}}, {0, 0, 0.05}),
                 std::invalid_argument);
}

TEST(LevelSetWall, FrictionlessSlopeAcceleratesAtGSinTheta)
{
    for (const Real theta : angles)
    {
        const Real expected = g*std::sin(theta*M_PI/180);
        for (const auto& [name, o] : algorithms())
        {
            const History r = slideDownSlope(0, theta, 0.4, o);
            const Real a = slope(r, 0.05, 0.4);
            std::cout << "  " << theta << " deg, " << name << ": " << a/expected << " g sin(theta)\n";
            EXPECT_NEAR(a/expected, 1.0, 0.02) << name << " at " << theta << " deg";
        }
    }
}

TEST(LevelSetWall, FrictionSlopeAcceleratesAtCoulombRate)
{
    const Real mu = 0.3;   // friction angle 16.7 deg, below every slope
    for (const Real theta : angles)
    {
        const Real th = theta*M_PI/180;
        const Real expected = g*(std::sin(th) - mu*std::cos(th));
        for (const auto& [name, o] : algorithms())
        {
            const History r = slideDownSlope(mu, theta, 0.5, o);
            const Real a = slope(r, 0.05, 0.5);
            std::cout << "  " << theta << " deg, " << name << ": " << a/expected
                      << " g (sin theta - mu cos theta)\n";
            EXPECT_NEAR(a/expected, 1.0, 0.02) << name << " at " << theta << " deg";
        }
    }
}

TEST(LevelSetWall, BlockHoldsBelowFrictionAngle)
{
    // mu = 0.75: friction angle 36.9 deg, above 20 and 25 deg. Frictionless
    // the block would slide g sin(theta) t^2/2 (0.42 m at 25 deg in 0.5 s).
    const Real mu = 0.75, tEnd = 0.5;
    for (const Real theta : {20.0, 25.0})
    {
        for (const auto& [name, o] : algorithms())
        {
            const History r = slideDownSlope(mu, theta, tEnd, o);
            Real x = 0;
            for (std::size_t i = 1; i < r.t.size(); ++i) x += 0.5*(r.u[i] + r.u[i - 1])*(r.t[i] - r.t[i - 1]);
            const Real free = 0.5*g*std::sin(theta*M_PI/180)*r.t.back()*r.t.back();
            std::cout << "  " << theta << " deg, " << name << ": displacement " << x/free
                      << " of the frictionless slide\n";
            EXPECT_LT(std::abs(x), 0.01*free) << name << " at " << theta << " deg";
        }
    }
}

TEST(LevelSetWall, FloorBetweenNodeLayersDeceleratesAtMuG)
{
    // The floor plane y = 0.2718 lies between node layers (not on a cell
    // face, where the box's mirrored floor would be): u = u0 - mu g t.
    const Real mu = 0.3, u0 = 2;
    for (const auto& [name, o] : algorithms())
    {
        const History r = slideOnPlane(mu, 0, u0, 0.5, o, 60, 14, {0, 0.2718, 0}, 0.2);
        const Real a = -slope(r, 0.05, 0.45);
        std::cout << "  " << name << ": deceleration " << a/(mu*g) << " mu g\n";
        EXPECT_NEAR(a/(mu*g), 1.0, 0.02) << name;
    }
}

namespace {

// A disk of radius 0.15 m (2 x 2 points per cell), elastic, thrown at
// `speed` towards a round obstacle of radius 0.3 m (a sphere cut by the 2D
// plane) with its centre `offset` off the line of flight (grazing when
// near the sum of the radii); or head-on at a flat wall where the
// obstacle's surface was: a level-set plane, or the box's mirrored slip
// wall. After every step: the
// smallest exact distance of a point from the obstacle (or wall), and the
// energy.
struct Impact { Real minDistance = 1e9; Real maxEnergyRatio = 0; Index contained = 0; };

enum class Target { obstacle, plane, mirror };

Impact throwDisk(Real speedInWaves, Real offset, const StepOptions& o, Target target = Target::obstacle)
{
    const bool mirror = target == Target::mirror;
    const std::array<Real, 3> c{1.6, 0.8, 0.5*h};
    const Real radius = 0.3;
    const Lattice L = box(mirror ? 26 : 48, 32, 1, h);    // wall at x = 1.3; 2.4 x 1.6 m
    MpmSystem s;
    s.setup(L, allSlip(), o);
    const std::array<Real, 3> face{c[0] - radius, 0, 0};
    if (target == Target::obstacle)
    {
        s.setLevelSetWalls({{"ball", std::make_shared<SphereShape>(c, radius), WallCondition{WallType::slip, 0}}},
                           {0, 0, 0.5*h});
    }
    if (target == Target::plane)
    {
        s.setLevelSetWalls({{"wall", std::make_shared<HalfSpaceShape>(face, std::array<Real, 3>{-1, 0, 0}),
                             WallCondition{WallType::slip, 0}}}, {0, 0, 0.5*h});
    }
    s.materials().push_back(makeLaw("linearElastic", {{"rho", rho}, {"E", E}, {"nu", nu}}));
    const Real v0 = speedInWaves*waveSpeed();
    const Real dp = 0.5*h, vol = dp*dp*h, R = 0.15;
    const Real x0 = 0.6, y0 = c[1] + offset;
    for (Real y = y0 - R + 0.5*dp; y < y0 + R; y += dp)
    for (Real x = x0 - R + 0.5*dp; x < x0 + R; x += dp)
    {
        if ((x - x0)*(x - x0) + (y - y0)*(y - y0) > R*R) continue;
        s.particles().add({x, y, 0.5*h}, {v0, 0, 0}, rho*vol, vol, 0);
    }
    auto energy = [&]
    {
        const auto& P = s.particles();
        Real e = 0;
        for (Index p = 0; p < P.size(); ++p)
        {
            const Real v2 = P.v[0][p]*P.v[0][p] + P.v[1][p]*P.v[1][p];
            Real F[9], S[6];
            for (int k = 0; k < 9; ++k) F[k] = P.F[k][p];
            for (int k = 0; k < 6; ++k) S[k] = P.sigma[k][p];
            e += 0.5*P.mass[p]*v2 + P.volume0[p]*s.material(0).storedEnergy(S, F);
        }
        return e;
    };
    const Real e0 = energy();
    // The Courant number 0.3 counts the flight speed too
    const Real dt = 0.3*h/(waveSpeed() + v0);
    // Long enough to hit (1.6 - 0.3 - 0.75 = 0.55 m away) and rebound
    const Real tEnd = 0.55/v0 + 0.03;
    Impact r;
    for (Real t = 0; t < tEnd; t += dt)
    {
        s.step(dt);
        const auto& P = s.particles();
        for (Index p = 0; p < P.size(); ++p)
        {
            const Real x[3] = {P.x[0][p], P.x[1][p], P.x[2][p]};
            const Real d = mirror ? face[0] - x[0] : s.levelSetWalls().distance(x);
            r.minDistance = std::min(r.minDistance, d);
        }
        r.maxEnergyRatio = std::max(r.maxEnergyRatio, energy()/e0);
    }
    r.contained = s.levelSetContainedCount();
    return r;
}

} // namespace

TEST(LevelSetWall, ThrownDiskNeverEntersObstacle)
{
    // Bounded energy: the APIC algorithms never exceed the initial energy.
    // Linear hats with FLIP gain energy in an impact on any wall (next
    // test); here they are held to containment only.
    for (const auto& [name, o] : algorithms())
    {
        const bool apic = o.transfer == Transfer::apic;
        for (const Real speed : {0.5, 2.0})
        {
            for (const Real offset : {0.0, 0.42})   // head-on; grazing (radii sum 0.45)
            {
                const Impact r = throwDisk(speed, offset, o);
                std::cout << "  " << name << ", " << speed << " wave speeds, offset " << offset
                          << ": min distance " << r.minDistance << " m, max energy "
                          << r.maxEnergyRatio << " of the initial, points put back "
                          << r.contained << "\n";
                EXPECT_GE(r.minDistance, 0) << name << ", " << speed << " wave speeds, offset " << offset;
                if (apic) EXPECT_LE(r.maxEnergyRatio, 1 + 1e-6) << name << ", " << speed << " wave speeds, offset " << offset;
                // It reached the obstacle (the test tests something)
                EXPECT_LT(r.minDistance, 0.5*h) << name << ", " << speed << " wave speeds, offset " << offset;
            }
        }
    }
}

TEST(LevelSetWall, FlatWallImpactMatchesMirroredWall)
{
    // The same disk thrown head-on at a flat level-set wall and at the
    // box's mirrored wall in the same place: the level-set wall adds at
    // most 1 % of the initial energy to what the mirrored wall gives
    // (linear hats with FLIP gain a few per cent at both).
    for (const auto& [name, o] : algorithms())
    {
        for (const Real speed : {0.5, 2.0})
        {
            const Impact mirror = throwDisk(speed, 0, o, Target::mirror);
            const Impact plane = throwDisk(speed, 0, o, Target::plane);
            std::cout << "  " << name << ", " << speed << " wave speeds: max energy "
                      << plane.maxEnergyRatio << " (level set), " << mirror.maxEnergyRatio
                      << " (mirrored); min distance " << plane.minDistance << ", "
                      << mirror.minDistance << " m\n";
            EXPECT_GE(plane.minDistance, 0) << name << ", " << speed << " wave speeds";
            EXPECT_LE(plane.maxEnergyRatio, std::max(Real(1), mirror.maxEnergyRatio) + 0.01)
                << name << ", " << speed << " wave speeds";
        }
    }
}

TEST(LevelSetWall, MovingWallsCarryAndPushBlocks)
{
    // 1. A conveyor: a noSlip floor plane (y = 0.2718, between node layers)
    //    moving along itself at V = 0.5 m/s under a block resting on it
    //    (gravity): the floor's nodes hold the block's base to V, and the
    //    block travels at V (mean velocity over 0.3-0.6 s within 2 %).
    // 2. A plough: a slip plane moving at V along its normal reaches a
    //    resting block (no gravity) and pushes it: no point is ever behind
    //    the plane at the end of a step (containment against the plane
    //    where it is then), and the block leaves at V or faster (an elastic
    //    block rebounds from it). Also at 2 wave speeds, where the plane
    //    runs into the block faster than its nodes can push it away.
    const Real dp = 0.5*h, vol = dp*dp*h;
    for (const auto& [name, o0] : algorithms())
    {
        for (const int variant : {0, 1, 2})
        {
            const bool plough = variant > 0;
            const Real V = variant == 2 ? 2*waveSpeed() : 0.5;
            StepOptions o = o0;
            o.gravity = {0, plough ? 0.0 : -g, 0};
            const Lattice L = box(40, 14, 1, h);
            MpmSystem s;
            s.setup(L, allSlip(), o);
            const std::array<Real, 3> p0 = plough ? std::array<Real, 3>{0.45, 0, 0} : std::array<Real, 3>{0, 0.2718, 0};
            const std::array<Real, 3> n = plough ? std::array<Real, 3>{1, 0, 0} : std::array<Real, 3>{0, 1, 0};
            s.setLevelSetWalls({{"wall", std::make_shared<HalfSpaceShape>(p0, n),
                                 WallCondition{plough ? WallType::slip : WallType::noSlip, 0}}}, {0, 0, 0.5*h});
            s.materials().push_back(makeLaw("linearElastic", {{"rho", rho}, {"E", E}, {"nu", nu}}));
            const Real y0 = plough ? 0.3 : 0.2718;
            for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 16; ++i)
            {
                s.particles().add({0.5 + (i + 0.5)*dp, y0 + (j + 0.5)*dp, 0.5*h}, {0, 0, 0}, rho*vol, vol, 0);
            }
            const Real dt = 0.3*h/(waveSpeed() + V);
            const Real tEnd = variant == 2 ? 0.01 : plough ? 0.8 : 0.6;
            Real behind = 1e9, uSum = 0;
            int uCount = 0;
            for (Real t = 0; t < tEnd; t += dt)
            {
                // The plough moves along x; the conveyor's plane along itself
                s.moveLevelSetWalls({{t*V, 0, 0}}, {{V, 0, 0}});
                s.step(dt);
                const auto& P = s.particles();
                Real m = 0, mu = 0;
                for (Index p = 0; p < P.size(); ++p)
                {
                    if (plough) behind = std::min(behind, P.x[0][p] - (p0[0] + (t + dt)*V));
                    m += P.mass[p];
                    mu += P.mass[p]*P.v[0][p];
                }
                if (t > tEnd - (variant == 2 ? 0.003 : 0.3)) { uSum += mu/m; ++uCount; }
            }
            const Real u = uSum/uCount;
            if (plough)
            {
                std::cout << "  " << name << ", plough at " << V << " m/s: block at " << u/V << " of the wall's speed, closest to the wall "
                          << behind << " m\n";
                EXPECT_GE(behind, 0) << name;
                EXPECT_GE(u/V, 0.98) << name;
            }
            else
            {
                std::cout << "  " << name << ", conveyor: block at " << u/V << " of the floor's speed\n";
                EXPECT_NEAR(u/V, 1.0, 0.02) << name;
            }
        }
    }
}

// An inlet level-set wall (a mesh's inlet patch off the box's sides): its
// nodes beyond the plane with material get the entering velocity, nodes on
// the material's side and empty nodes keep theirs; a point found beyond it
// leaves (2 + wall), and the plane does not move with the inlet's velocity
// (it is the material's, not the wall's).
TEST(LevelSetWall, InletSetsItsVelocityBeyondThePlaneAndLetsPointsLeave)
{
    Lattice L = box(10, 10, 1, 0.1);
    L.finalise();
    LevelSetWalls ls;
    WallCondition in{WallType::inlet, 0};
    in.velocity = {0.5, -2, 0};
    // The plane y = 0.83, the material below it (normal -y)
    LevelSetWall w{"top", std::make_shared<HalfSpaceShape>(std::array<Real, 3>{0, 0.83, 0}, std::array<Real, 3>{0, -1, 0}), in};
    EXPECT_THROW(ls.build(L, {w}, {0, 0, 0.05}), std::invalid_argument);   // no booking index
    w.specCondition = 3;
    ls.build(L, {w}, {0, 0, 0.05});
    EXPECT_TRUE(ls.hasOutlets());
    const LevelSetView v = ls.view();
    const Index beyond = L.realNode(4, 8, 0), inside = L.realNode(4, 7, 0), empty = L.realNode(5, 9, 0);
    ASSERT_LT(v.phi[beyond], 0);   // node centre y = 0.85
    ASSERT_GT(v.phi[inside], 0);   // 0.75
    std::vector<Real> mass(std::size_t(L.nNodes), 0.0);
    std::array<std::vector<Real>, 3> vel;
    for (auto& a : vel) a.assign(std::size_t(L.nNodes), 0.3);
    mass[std::size_t(beyond)] = mass[std::size_t(inside)] = 1;
    Real* vp[3] = {vel[0].data(), vel[1].data(), vel[2].data()};
    for (const Index I : {beyond, inside, empty}) levelSetWallNode(v, mass.data(), vp, 1e-12, I, 1e9);
    EXPECT_EQ(vel[0][beyond], 0.5);
    EXPECT_EQ(vel[1][beyond], -2);
    for (const Index I : {inside, empty}) for (int d = 0; d < 3; ++d) EXPECT_EQ(vel[d][I], 0.3);

    // Two points: one beyond the plane (leaves), one below it (stays); a
    // large dt would move the plane by the inlet velocity if it moved
    Particles P;
    P.add({0.45, 0.86, 0.05}, {0, 1, 0}, 1, 1, 0);
    P.add({0.45, 0.80, 0.05}, {0, 1, 0}, 1, 1, 0);
    std::array<StaggeredArray<Real>, 9> Lg;
    std::array<StaggeredArray<Real>, 3> dx;
    for (auto& a : Lg) a.assign(2, 0.0);
    for (auto& a : dx) a.assign(2, 0.0);
    const PointView pv = pointView(P, Lg, dx);
    EXPECT_EQ(levelSetContainPoint(L, v, pv, 0, 1.0), 2);
    EXPECT_EQ(levelSetContainPoint(L, v, pv, 1, 1.0), 0);
    EXPECT_EQ(P.x[1][1], 0.80);
}

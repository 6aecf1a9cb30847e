// Coulomb friction walls against the rigid-block closed forms: an elastic
// block sliding on a horizontal friction floor decelerates at mu g; on an
// incline of angle theta it stays at rest below atan(mu) and accelerates at
// g (sin theta - mu cos theta) above it. The bound of the tangential impulse
// is mu times the normal impulse the wall delivers at a node in that step
// (the mirror fold's and the contact's together): a friction taken from the
// normal velocity the fold leaves over alone gives about half of mu.
#include "testHelpers.hpp"
#include <gtest/gtest.h>
#include <cmath>

using namespace mpm;
using namespace mpm::test;

namespace {

constexpr Real g = 9.81;
constexpr Real rho = 1000, E = 1e6, nu = 0.3;
constexpr Real h = 0.05;             // cell size; the block is 8 x 4 cells
constexpr Real blockW = 0.4, blockH = 0.2;

// Floor (y-) friction with coefficient mu, every other side slip.
BoundarySpec frictionFloor(const Lattice& L, Real mu)
{
    BoundarySpec b;
    b.conditions = {WallCondition{WallType::slip, 0}, WallCondition{WallType::friction, mu}};
    b.faceCondition[2].assign(std::size_t(L.nCells[0])*std::size_t(L.nCells[2]), 1);
    return b;
}

// A 2D block of 2 x 2 points per cell on the floor, under gravity
// g (sin theta, -cos theta) (the floor stays the lattice's y- side), with
// initial velocity u0 along the floor and the geostatic normal stress of a
// layer (sigma_yy = -rho g cos(theta) (H - y), sigma_xx = sigma_zz =
// nu/(1 - nu) sigma_yy) so that it does not bounce on landing.
History slideBlock(Real mu, Real thetaDeg, Real u0, Real tEnd, const StepOptions& base)
{
    const Real th = thetaDeg*M_PI/180;
    const Lattice L = box(60, 6, 1, h);   // 3 m: the block never reaches the far wall
    StepOptions o = base;
    o.gravity = {g*std::sin(th), -g*std::cos(th), 0};
    MpmSystem s;
    s.setup(L, frictionFloor(L, mu), o);
    s.materials().push_back(makeLaw("linearElastic", {{"rho", rho}, {"E", E}, {"nu", nu}}));
    const Real dp = 0.5*h, vol = dp*dp*h;
    const Real x0 = 0.2;
    for (int j = 0; j < int(blockH/dp + 0.5); ++j)
    for (int i = 0; i < int(blockW/dp + 0.5); ++i)
    {
        const Real y = (j + 0.5)*dp;
        const Index p = s.particles().add({x0 + (i + 0.5)*dp, y, 0.5*h}, {u0, 0, 0}, rho*vol, vol, 0);
        const Real syy = -rho*g*std::cos(th)*(blockH - y);
        auto& S = s.particles().sigma;
        S[1][p] = syy;
        S[0][p] = S[2][p] = nu/(1 - nu)*syy;
    }
    // p-wave Courant number 0.3
    const Real c = std::sqrt(E*(1 - nu)/((1 + nu)*(1 - 2*nu)*rho));
    const Real dt = 0.3*h/c;
    History r;
    const auto& P = s.particles();
    for (Real t = 0; t < tEnd; t += dt)
    {
        Real m = 0, mu0 = 0;
        for (Index p = 0; p < P.size(); ++p) { m += P.mass[p]; mu0 += P.mass[p]*P.v[0][p]; }
        r.t.push_back(t);
        r.u.push_back(mu0/m);
        s.step(dt);
    }
    return r;
}

} // namespace

TEST(FrictionWall, SlidingBlockDeceleratesAtMuG)
{
    // u0 = 2 m/s, mu = 0.3: u = u0 - mu g t until it stops at 0.68 s.
    const Real mu = 0.3, u0 = 2;
    for (const auto& [name, o] : algorithms())
    {
        const History r = slideBlock(mu, 0, u0, 0.5, o);
        const Real a = -slope(r, 0.05, 0.45);
        std::cout << "  " << name << ": deceleration " << a/(mu*g) << " mu g\n";
        EXPECT_NEAR(a/(mu*g), 1.0, 0.02) << name;
    }
}

TEST(FrictionWall, BlockOnInclineHoldsBelowFrictionAngle)
{
    // mu = 0.3: friction angle 16.7 deg. At 12 deg the block must stay at
    // rest; frictionless it would slide g sin(12 deg) tEnd^2/2 = 0.255 m in
    // 0.5 s. It only shears elastically (its top by ~1e-4 m) while the
    // floor's friction takes up the slope's pull.
    const Real mu = 0.3, theta = 12, tEnd = 0.5;
    for (const auto& [name, o] : algorithms())
    {
        const History r = slideBlock(mu, theta, 0, tEnd, o);
        Real x = 0;   // displacement of the centre of mass
        for (std::size_t i = 1; i < r.t.size(); ++i) x += 0.5*(r.u[i] + r.u[i - 1])*(r.t[i] - r.t[i - 1]);
        const Real free = 0.5*g*std::sin(theta*M_PI/180)*r.t.back()*r.t.back();
        std::cout << "  " << name << ": displacement " << x << " m = " << x/free
                  << " of the frictionless slide\n";
        EXPECT_LT(std::abs(x), 0.01*free) << name;
    }
}

TEST(FrictionWall, BlockOnInclineAcceleratesAboveFrictionAngle)
{
    // At 25 deg: a = g (sin 25 - 0.3 cos 25) = 1.478 m/s^2.
    const Real mu = 0.3, theta = 25, th = theta*M_PI/180;
    const Real expected = g*(std::sin(th) - mu*std::cos(th));
    for (const auto& [name, o] : algorithms())
    {
        const History r = slideBlock(mu, theta, 0, 0.5, o);
        const Real a = slope(r, 0.05, 0.5);
        std::cout << "  " << name << ": acceleration " << a << " m/s^2 = " << a/expected
                  << " g (sin theta - mu cos theta)\n";
        EXPECT_NEAR(a/expected, 1.0, 0.03) << name;
    }
}

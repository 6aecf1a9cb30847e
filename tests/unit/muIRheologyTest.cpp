// mu(I) rheology against closed forms: steady shear at a prescribed
// inertial number gives tau/p = mu(I) (Jop, Forterre & Pouliquen 2006), the
// limits I -> 0 (muS) and I -> infinity (mu2), zero stress in tension and
// when looser than critical packing, elasticity below muS p.
//
// mu(I) and I are written out here from the paper, not taken from the law,
// so a swapped muS/mu2, a wrong I (e.g. sqrt(p rhoS) or a missing d) or a
// wrong shear measure fails the steady-shear tests.
#include "constitutive/constitutiveLaw.hpp"
#include "constitutive/linearElastic.hpp"
#include "constitutive/muIRheology.hpp"
#include <gtest/gtest.h>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

using namespace mpm;

namespace {

using Arr6 = std::array<Real, 6>;
using Arr9 = std::array<Real, 9>;

// Glass beads (Jop, Forterre & Pouliquen 2006): tan 20.9 deg, tan 32.76 deg.
const Real muS = 0.381863, mu2 = 0.643468, I0 = 0.279, d = 0.53e-3, rhoS = 2450;
const Real E = 1e7, nu = 0.3, G = E/(2*(1 + nu));
const Real rhoBulk = 0.6*rhoS;   // points seeded at critical packing

Real muOfI(Real I) { return muS + (mu2 - muS)/(I0/I + 1); }

// Shear rate giving inertial number I at pressure p.
Real shearRateFor(Real I, Real p) { return I*std::sqrt(p/rhoS)/d; }

std::unique_ptr<ConstitutiveLaw> glassBeads(Real alphaCritical = 0.6)
{
    return makeLaw("muIRheology", {{"rho", rhoBulk}, {"E", E}, {"nu", nu}, {"muS", muS},
                                   {"mu2", mu2}, {"I0", I0}, {"d", d}, {"rhoS", rhoS},
                                   {"alphaCritical", alphaCritical}});
}

// Repeated updates with a constant velocity gradient and packing.
struct Driver
{
    Arr9 L{};
    Real dt = 1e-6;
    Real solidFraction = 1;     // mass/(rho V); 1: at the seeded (critical) packing
    Arr6 sigma{};
    Real eqPlasticStrain = 0;

    void step(const ConstitutiveLaw& law)
    {
        const Arr9 I{1, 0, 0, 0, 1, 0, 0, 0, 1};
        Arr9 Fn = I;
        for (int e = 0; e < 9; ++e) Fn[e] += dt*L[e];
        PointKinematics k{L.data(), I.data(), Fn.data(), dt, solidFraction};
        PointStress s{sigma.data(), &eqPlasticStrain};
        law.updateStress(k, s);
    }
};

Real pressure(const Arr6& s) { return -(s[XX] + s[YY] + s[ZZ])/3; }

Real equivalentShear(const Arr6& s)
{
    const Real p = pressure(s);
    const Real a = s[XX] + p, b = s[YY] + p, c = s[ZZ] + p;
    return std::sqrt(0.5*(a*a + b*b + c*c) + s[XY]*s[XY] + s[YZ]*s[YZ] + s[XZ]*s[XZ]);
}

// Shears an isotropically compressed point (pressure p) at the shear rate
// of inertial number I until the stress stops changing; returns the steady
// stress. simple: u_x = gammaDot y (L_xy = gammaDot, with spin); otherwise
// the irrotational pure shear with the same strain rate D_xy = gammaDot/2.
Arr6 steadyShear(Real I, Real p, bool simple)
{
    const auto law = glassBeads();
    const Real gammaDot = shearRateFor(I, p);
    Driver drv;
    if (simple) drv.L[ij(0, 1)] = gammaDot;
    else drv.L[ij(0, 1)] = drv.L[ij(1, 0)] = 0.5*gammaDot;
    // Elastic loading to the flow stress in ~50 steps.
    drv.dt = 0.02*muS*p/(G*gammaDot);
    for (int a = 0; a < 3; ++a) drv.sigma[a] = -p;
    Arr6 previous{};
    for (int n = 0; n < 20000; ++n)
    {
        previous = drv.sigma;
        drv.step(*law);
    }
    for (int a = 0; a < 6; ++a)
        EXPECT_NEAR(drv.sigma[a], previous[a], 1e-12*p) << "not steady, component " << a;
    EXPECT_GT(drv.eqPlasticStrain, 0);
    return drv.sigma;
}

} // namespace

TEST(ConstitutiveMuIRheology, DefaultsAreGlassBeadsOfJopEtAl)
{
    const auto law = makeLaw("muIRheology", {{"rho", 1500}, {"E", E}, {"nu", nu}});
    const auto& m = dynamic_cast<const MuIRheology&>(*law);
    EXPECT_NEAR(m.muS(), muS, 1e-6);
    EXPECT_NEAR(m.mu2(), mu2, 1e-6);
    EXPECT_EQ(m.I0(), I0);
    EXPECT_EQ(m.grainDiameter(), d);
    EXPECT_EQ(m.grainDensity(), rhoS);
    EXPECT_EQ(law->rho0(), 1500);
    EXPECT_NEAR(law->waveSpeed(1.0), std::sqrt(E*(1 - nu)/((1 + nu)*(1 - 2*nu))/1500), 1e-9);
}

TEST(ConstitutiveMuIRheology, SteadyPureShearGivesMuOfI)
{
    const Real p = 1000;
    for (const Real I : {0.01, 0.1, 0.279, 1.0, 5.0})
    {
        const Arr6 s = steadyShear(I, p, false);
        EXPECT_NEAR(pressure(s), p, 1e-9*p) << "I = " << I;
        EXPECT_NEAR(std::abs(s[XY])/p, muOfI(I), 1e-9) << "I = " << I;
        EXPECT_NEAR(equivalentShear(s)/p, muOfI(I), 1e-9) << "I = " << I;
    }
}

TEST(ConstitutiveMuIRheology, SteadySimpleShearGivesMuOfI)
{
    // With spin the Jaumann terms tilt the stress by O(tau/G) ~ 1e-4 here;
    // the shear rate and tau/p change only at second order.
    for (const Real p : {200.0, 5000.0})
    {
        for (const Real I : {0.03, 0.3, 3.0})
        {
            const Arr6 s = steadyShear(I, p, true);
            EXPECT_NEAR(pressure(s), p, 1e-9*p);
            EXPECT_NEAR(equivalentShear(s)/p, muOfI(I), 1e-6) << "p = " << p << ", I = " << I;
            EXPECT_NEAR(s[XY]/p, muOfI(I), 1e-6) << "p = " << p << ", I = " << I;
        }
    }
}

TEST(ConstitutiveMuIRheology, LimitsAreMuSAndMu2)
{
    const Real p = 1000;
    const Arr6 slow = steadyShear(1e-7, p, false);
    EXPECT_NEAR(equivalentShear(slow)/p, muS, 1e-6);
    const Arr6 fast = steadyShear(1e7, p, false);
    EXPECT_NEAR(equivalentShear(fast)/p, mu2, 1e-6);
}

TEST(ConstitutiveMuIRheology, ElasticBelowStaticFriction)
{
    const auto law = glassBeads();
    const auto elastic = makeLaw("linearElastic", {{"rho", rhoBulk}, {"E", E}, {"nu", nu}});
    Driver a, b;
    a.L = b.L = {1e-3, 2e-3, 0, 0, -3e-3, 1e-3, 0, 0, -1e-3};
    a.dt = b.dt = 1e-2;
    for (Driver* x : {&a, &b}) for (int c = 0; c < 3; ++c) x->sigma[c] = -1e4;
    a.step(*law);
    b.step(*elastic);
    ASSERT_LT(equivalentShear(a.sigma), muS*pressure(a.sigma));
    for (int c = 0; c < 6; ++c) EXPECT_NEAR(a.sigma[c], b.sigma[c], 1e-12*1e4);
    EXPECT_EQ(a.eqPlasticStrain, 0);
}

TEST(ConstitutiveMuIRheology, TensionIsStressFree)
{
    const auto law = glassBeads();
    Driver drv;
    for (int c = 0; c < 3; ++c) drv.sigma[c] = 50;         // tensile
    drv.sigma[XY] = 20;
    drv.step(*law);
    for (int c = 0; c < 6; ++c) EXPECT_EQ(drv.sigma[c], 0) << c;

    // Stretching a stress-free point keeps it stress-free.
    drv.L = {1, 0, 0, 0, 0.5, 0.3, 0, 0, 0};
    drv.dt = 1e-3;
    drv.step(*law);
    for (int c = 0; c < 6; ++c) EXPECT_EQ(drv.sigma[c], 0) << c;
}

TEST(ConstitutiveMuIRheology, LooserThanCriticalIsDisconnected)
{
    const auto law = glassBeads(0.6);
    Driver drv;
    drv.L = {-1, 0, 0, 0, -1, 0, 0, 0, 0};                  // compaction
    drv.dt = 1e-4;
    // Grain volume fraction 0.6 solidFraction: 0.5 < 0.6, disconnected.
    drv.solidFraction = 0.5/0.6;
    for (int c = 0; c < 3; ++c) drv.sigma[c] = -1e3;
    drv.step(*law);
    for (int c = 0; c < 6; ++c) EXPECT_EQ(drv.sigma[c], 0) << c;

    // At critical packing the same compaction builds pressure again.
    drv.solidFraction = 1.0;
    drv.step(*law);
    // tr D dt = -2e-4: p = -K tr D dt, and tau/p < muS (elastic)
    const Real K = E/(3*(1 - 2*nu)), pElastic = 2e-4*K;
    EXPECT_NEAR(pressure(drv.sigma), pElastic, 1e-12*pElastic);
}

TEST(ConstitutiveMuIRheology, BadParametersAreNamed)
{
    auto expectMessage = [](const Coefficients& c, const std::string& a, const std::string& b)
    {
        try
        {
            makeLaw("muIRheology", c);
            ADD_FAILURE() << "no exception";
        }
        catch (const std::invalid_argument& e)
        {
            const std::string what = e.what();
            EXPECT_NE(what.find(a), std::string::npos) << what;
            EXPECT_NE(what.find(b), std::string::npos) << what;
        }
    };
    expectMessage({{"rho", 1500}, {"E", E}, {"nu", nu}, {"muS", 0.6}, {"mu2", 0.4}}, "'mu2'", "'muS'");
    expectMessage({{"rho", 1500}, {"E", E}, {"nu", nu}, {"I0", 0}}, "'I0'", "(0, inf)");
    expectMessage({{"rho", 1500}, {"E", E}, {"nu", nu}, {"d", -1}}, "'d'", "grain diameter");
    expectMessage({{"rho", 1500}, {"E", E}, {"nu", nu}, {"alphaCritical", 1.2}}, "'alphaCritical'", "[0, 1]");
}

// Drag laws: each law against the published formula written out by hand,
// the Gidaspow switch, dilute Stokes limits, settling velocities (terminal
// velocity, Richardson-Zaki exponent as a check of the model-A
// normalisation), clamping, the SoA batch, and makeDragLaw error messages.
#include "drag/dragLaw.hpp"
#include "drag/dragLaws.hpp"
#include <gtest/gtest.h>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

using namespace mpm;

namespace {

// Water-like fluid, 1 mm grains.
const Real rhoF = 1000.0, muF = 1.0e-3, d = 1.0e-3;

// Three (alphaF, slip) points; superficial Re = alphaF rhoF u d / muF
// = 0.095, 10.2, 495 (single-particle Re_p = 0.1, 17, 1100).
struct Point { Real alphaF, slip; };
const Point points[] = {{0.95, 1.0e-4}, {0.6, 1.7e-2}, {0.45, 1.1}};

// ---- the formulas as published (not the Cd*Re form the code uses)

Real cdSchillerNaumann(Real Re)
{
    return Re < 1000 ? 24.0/Re*(1.0 + 0.15*std::pow(Re, 0.687)) : 0.44;
}

Real handSchillerNaumann(Real aF, Real u)
{
    const Real Rep = rhoF*u*d/muF;
    return 0.75*cdSchillerNaumann(Rep)*rhoF*u*(1.0 - aF)/d;
}

Real handWenYu(Real aF, Real u)
{
    const Real Re = aF*rhoF*u*d/muF;
    return 0.75*cdSchillerNaumann(Re)*(1.0 - aF)*aF*rhoF*u/d*std::pow(aF, -2.65);
}

Real handErgun(Real aF, Real u)
{
    const Real aS = 1.0 - aF;
    return 150.0*aS*aS*muF/(aF*d*d) + 1.75*aS*rhoF*u/d;
}

Real handGidaspow(Real aF, Real u)
{
    return aF < 0.8 ? handErgun(aF, u) : handWenYu(aF, u);
}

Real handDiFelice(Real aF, Real u)
{
    const Real Re = aF*rhoF*u*d/muF;
    const Real Cd = std::pow(0.63 + 4.8/std::sqrt(Re), 2);
    const Real chi = 3.7 - 0.65*std::exp(-std::pow(1.5 - std::log10(Re), 2)/2.0);
    return 0.75*Cd*rhoF*u*(1.0 - aF)/d*std::pow(aF, 2.0 - chi);
}

Real handBeetstra(Real aF, Real u)
{
    const Real aS = 1.0 - aF;
    const Real Re = aF*rhoF*u*d/muF;
    const Real F = 10.0*aS/(aF*aF) + aF*aF*(1.0 + 1.5*std::sqrt(aS))
        + 0.413*Re/(24.0*aF*aF)*(1.0/aF + 3.0*aF*aS + 8.4*std::pow(Re, -0.343))
         /(1.0 + std::pow(10.0, 3.0*aS)*std::pow(Re, -(1.0 + 4.0*aS)/2.0));
    return 18.0*muF*aF*aS*F/(d*d);
}

std::unique_ptr<DragLaw> law(const std::string& name, Real diameter = d)
{
    return makeDragLaw(name, {{"d", diameter}});
}

void expectMatchesHand(const std::string& name, const std::function<Real(Real, Real)>& hand)
{
    const auto l = law(name);
    for (const Point& p : points)
    {
        const Real expected = hand(p.alphaF, p.slip);
        EXPECT_NEAR(l->beta(p.alphaF, p.slip, rhoF, muF), expected, 1e-12*std::abs(expected))
            << name << " at alphaF " << p.alphaF << ", slip " << p.slip;
    }
}

Real stokes(Real alphaS, Real diameter = d) { return 18.0*muF*alphaS/(diameter*diameter); }

// Slip u with beta(alphaF, u) u = rhs, by fixed-point iteration
// u <- rhs / beta(u) (a contraction for these laws: beta grows sublinearly).
Real solveSlip(const DragLaw& l, Real alphaF, Real rhs)
{
    Real u = 0;
    for (int it = 0; it < 500; ++it)
    {
        const Real next = rhs/l.beta(alphaF, u, rhoF, muF);
        if (std::abs(next - u) <= 1e-15*next) return next;
        u = next;
    }
    ADD_FAILURE() << "fixed point did not converge";
    return u;
}

const Real g = 9.81, rhoS = 2650.0;

} // namespace

// ------------------------------------------------------- hand-computed values

TEST(DragLaws, SchillerNaumannMatchesFormula) { expectMatchesHand("SchillerNaumann", handSchillerNaumann); }
TEST(DragLaws, WenYuMatchesFormula) { expectMatchesHand("WenYu", handWenYu); }
TEST(DragLaws, ErgunMatchesFormula) { expectMatchesHand("Ergun", handErgun); }
TEST(DragLaws, GidaspowMatchesFormula) { expectMatchesHand("Gidaspow", handGidaspow); }
TEST(DragLaws, DiFeliceMatchesFormula) { expectMatchesHand("DiFelice", handDiFelice); }
TEST(DragLaws, BeetstraMatchesFormula) { expectMatchesHand("Beetstra", handBeetstra); }

TEST(DragLaws, SchillerNaumannNewtonBranchAndLiteralValue)
{
    // Re_p = 1100 > 1000: Cd = 0.44, beta = 0.75*0.44*1000*1.1*0.55/1e-3.
    const auto l = law("SchillerNaumann");
    EXPECT_NEAR(l->beta(0.45, 1.1, rhoF, muF), 199650.0, 1e-12*199650.0);
    // Ergun at alphaF = 0.45, u = 1.1: 150*0.3025e-3/(0.45e-6) + 1.75*0.55*1.1e6.
    const Real ergun = 150*0.3025e-3/0.45e-6 + 1.75*0.55*1.1e6;
    EXPECT_NEAR(law("Ergun")->beta(0.45, 1.1, rhoF, muF), ergun, 1e-12*ergun);
}

// ------------------------------------------------------------ Gidaspow switch

TEST(DragGidaspow, SwitchesFromErgunToWenYuAtPointEight)
{
    const auto gid = law("Gidaspow"), wen = law("WenYu"), erg = law("Ergun");
    const Real below = std::nextafter(0.8, 0.0), u = 0.05;
    EXPECT_EQ(gid->beta(0.8, u, rhoF, muF), wen->beta(0.8, u, rhoF, muF));
    EXPECT_EQ(gid->beta(below, u, rhoF, muF), erg->beta(below, u, rhoF, muF));
    EXPECT_EQ(gid->beta(0.9, u, rhoF, muF), wen->beta(0.9, u, rhoF, muF));
    EXPECT_EQ(gid->beta(0.5, u, rhoF, muF), erg->beta(0.5, u, rhoF, muF));
    // Plain switch, no blending: the jump at 0.8 is real (documented).
    const Real jump = gid->beta(0.8, u, rhoF, muF)/gid->beta(below, u, rhoF, muF);
    EXPECT_GT(std::abs(jump - 1.0), 0.1) << "jump ratio " << jump;
}

// --------------------------------------------------------------- Stokes limit

TEST(DragStokesLimit, DiluteLawsTendToStokes)
{
    // alphaS -> 0 and Re -> 0: beta -> 18 muF alphaS / d^2 for the laws built
    // on 24/Re (Beetstra converges like 1.5 sqrt(alphaS)).
    const Real alphaF = 1.0 - 1.0e-10, alphaS = 1.0 - alphaF;
    for (const char* name : {"SchillerNaumann", "WenYu", "Gidaspow", "Beetstra"})
    {
        const auto l = law(name);
        for (Real u : {0.0, 1.0e-10})
        {
            const Real ratio = l->beta(alphaF, u, rhoF, muF)/stokes(alphaS);
            EXPECT_NEAR(ratio, 1.0, 1.0e-4) << name << ", slip " << u;
        }
    }
}

TEST(DragStokesLimit, DiFeliceTendsToDallaValleNotStokes)
{
    // Dalla Valle's Cd -> 4.8^2/Re = 23.04/Re: 4% below Stokes.
    const Real alphaF = 1.0 - 1.0e-10, alphaS = 1.0 - alphaF;
    const auto l = law("DiFelice");
    for (Real u : {0.0, 1.0e-10})
        EXPECT_NEAR(l->beta(alphaF, u, rhoF, muF)/stokes(alphaS), 23.04/24.0, 1.0e-4) << "slip " << u;
}

TEST(DragStokesLimit, ErgunHasNoDiluteStokesLimit)
{
    // beta/stokes -> (150 alphaS/alphaF + 1.75 Re_p)/18 -> 0.
    const Real alphaF = 1.0 - 1.0e-10, alphaS = 1.0 - alphaF;
    EXPECT_LT(law("Ergun")->beta(alphaF, 1.0e-10, rhoF, muF)/stokes(alphaS), 1.0e-6);
}

TEST(DragStokesLimit, ZeroSlipIsFiniteEverywhere)
{
    for (const DragLawInfo& info : availableDragLaws())
    {
        const auto l = law(info.name);
        for (Real aF : {0.3, 0.6, 0.79, 0.8, 0.95, 1.0})
        {
            const Real b = l->beta(aF, 0.0, rhoF, muF);
            EXPECT_TRUE(std::isfinite(b) && b >= 0) << info.name << " alphaF " << aF << ": " << b;
            EXPECT_EQ(b > 0, aF < 1.0) << info.name << " alphaF " << aF;
        }
    }
}

// ----------------------------------------------------------------- settling

TEST(DragSettling, SchillerNaumannTerminalVelocityStokesRegime)
{
    // Single grain: beta/alphaS * Ut = (rhoS - rhoF) g.
    // d = 0.1 um: Re_t ~ 1e-9, the Schiller-Naumann correction ~1e-7: Stokes.
    const Real alphaF = 1.0 - 1.0e-6, alphaS = 1.0 - alphaF;
    {
        const Real dTiny = 1.0e-7;
        const Real ut = solveSlip(*law("SchillerNaumann", dTiny), alphaF, alphaS*(rhoS - rhoF)*g);
        const Real utStokes = (rhoS - rhoF)*g*dTiny*dTiny/(18.0*muF);
        EXPECT_NEAR(ut, utStokes, 2.0e-7*utStokes);
    }
    // d = 1 um: Re_t ~ 1e-6, first-order correction 0.15 Re^0.687 ~ 1e-5:
    // Ut = Ut_Stokes/(1 + 0.15 Re_Stokes^0.687) up to O(1e-10).
    const Real dSmall = 1.0e-6;
    const auto l = law("SchillerNaumann", dSmall);
    const Real ut = solveSlip(*l, alphaF, alphaS*(rhoS - rhoF)*g);
    const Real utStokes = (rhoS - rhoF)*g*dSmall*dSmall/(18.0*muF);
    const Real firstOrder = utStokes/(1.0 + 0.15*std::pow(rhoF*utStokes*dSmall/muF, 0.687));
    EXPECT_GT(utStokes - ut, 0.5e-5*utStokes);
    EXPECT_NEAR(ut, firstOrder, 1.0e-9*utStokes);

    // The relaxation time in the Stokes regime is rhoS d^2/(18 muF).
    EXPECT_NEAR(drag::relaxationTime(alphaS, rhoS, l->beta(alphaF, 0.0, rhoF, muF)),
                rhoS*dSmall*dSmall/(18.0*muF), 1.0e-12*rhoS*dSmall*dSmall/(18.0*muF));
    EXPECT_TRUE(std::isinf(drag::relaxationTime(0.0, rhoS, 0.0)));
}

TEST(DragSettling, SchillerNaumannTerminalVelocityIntermediateRe)
{
    // d = 0.1 mm sand: Ut = Ut_Stokes/(1 + 0.15 Re_t^0.687), Re_t ~ 0.8.
    // Hand solution by bisection on U (1 + 0.15 (rhoF U d/muF)^0.687) = Ut_Stokes.
    const Real dg = 1.0e-4, alphaF = 1.0 - 1.0e-6, alphaS = 1.0 - alphaF;
    const Real utStokes = (rhoS - rhoF)*g*dg*dg/(18.0*muF);
    Real lo = 0, hi = utStokes;
    for (int i = 0; i < 200; ++i)
    {
        const Real mid = 0.5*(lo + hi);
        (mid*(1.0 + 0.15*std::pow(rhoF*mid*dg/muF, 0.687)) < utStokes ? lo : hi) = mid;
    }
    const auto l = law("SchillerNaumann", dg);
    const Real ut = solveSlip(*l, alphaF, alphaS*(rhoS - rhoF)*g);
    EXPECT_NEAR(ut, 0.5*(lo + hi), 1.0e-10*ut);
    EXPECT_LT(ut, 0.9*utStokes);
}

TEST(DragSettling, ModelANormalisationGivesRichardsonZakiAtLowRe)
{
    // Homogeneous fluidisation with -alphaF grad p in the fluid and
    // -alphaS grad p on the solid: beta u = alphaF alphaS (rhoS - rhoF) g.
    // Superficial velocity over the single-grain terminal velocity is
    // alphaF^n with n = 4.65 for Wen-Yu (= 3.65 + 1) and n = chi + 1 = 4.7
    // for Di Felice at Re -> 0: close to Richardson-Zaki's 4.65, which
    // would not hold with the total-force (alphaF-divided) normalisation.
    const Real dSmall = 1.0e-7, dilute = 1.0 - 1.0e-9;
    for (const auto& [name, n] : {std::pair<std::string, Real>{"WenYu", 4.65}, {"DiFelice", 4.7}})
    {
        const auto l = law(name, dSmall);
        const Real ut = solveSlip(*l, dilute, dilute*(1 - dilute)*(rhoS - rhoF)*g);
        for (Real aF : {0.5, 0.7, 0.9})
        {
            const Real u = solveSlip(*l, aF, aF*(1 - aF)*(rhoS - rhoF)*g);
            EXPECT_NEAR(aF*u/ut, std::pow(aF, n), 1.0e-5*std::pow(aF, n)) << name << " alphaF " << aF;
        }
    }
}

// --------------------------------------------------------- clamping and batch

TEST(DragLaws, FluidFractionIsClampedToAlphaFMin)
{
    const auto l = makeDragLaw("Ergun", {{"d", d}, {"alphaFMin", 0.3}});
    EXPECT_EQ(l->alphaFMin(), 0.3);
    EXPECT_EQ(l->beta(-0.2, 0.1, rhoF, muF), l->beta(0.3, 0.1, rhoF, muF));
    EXPECT_EQ(l->beta(0.1, 0.1, rhoF, muF), l->beta(0.3, 0.1, rhoF, muF));
    EXPECT_EQ(l->beta(1.2, 0.1, rhoF, muF), 0.0);
    EXPECT_EQ(law("Ergun")->alphaFMin(), 0.2);   // default
}

TEST(DragLaws, BatchMatchesPointwise)
{
    const std::vector<Real> alphaF{0.95, 0.6, 0.45, 0.8, 1.0, 0.05};
    const std::vector<Real> slip{1.0e-4, 1.7e-2, 1.1, 0.0, 0.3, 2.0};
    std::vector<Real> out(alphaF.size());
    for (const DragLawInfo& info : availableDragLaws())
    {
        const auto l = law(info.name);
        l->beta(alphaF.size(), alphaF.data(), slip.data(), rhoF, muF, out.data());
        for (std::size_t i = 0; i < out.size(); ++i)
            EXPECT_EQ(out[i], l->beta(alphaF[i], slip[i], rhoF, muF)) << info.name << " i " << i;
    }
}

// ------------------------------------------------------------------ registry

TEST(DragRegistry, NamesAndTypeNames)
{
    const std::vector<std::string> expected
        {"SchillerNaumann", "WenYu", "Ergun", "Gidaspow", "DiFelice", "Beetstra"};
    ASSERT_EQ(availableDragLaws().size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
    {
        EXPECT_EQ(availableDragLaws()[i].name, expected[i]);
        EXPECT_EQ(std::string(law(expected[i])->typeName()), expected[i]);
        EXPECT_EQ(law(expected[i])->d(), d);
        EXPECT_NE(findDragLaw(expected[i]), nullptr);
    }
    EXPECT_EQ(findDragLaw("wenYu"), nullptr);   // case-sensitive, like dictionaries
}

TEST(DragRegistry, UnknownNameListsValidNames)
{
    try
    {
        makeDragLaw("Stokes", {{"d", d}});
        FAIL() << "expected std::invalid_argument";
    }
    catch (const std::invalid_argument& e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("unknown drag law 'Stokes'"), std::string::npos) << msg;
        for (const DragLawInfo& info : availableDragLaws())
            EXPECT_NE(msg.find(info.name), std::string::npos) << msg;
    }
}

namespace {

std::string errorOf(const std::string& name, const Coefficients& c)
{
    try { makeDragLaw(name, c); }
    catch (const std::invalid_argument& e) { return e.what(); }
    ADD_FAILURE() << "expected std::invalid_argument for " << name;
    return {};
}

} // namespace

TEST(DragRegistry, MissingOrInvalidDiameterNamesTheParameter)
{
    const std::string missing = errorOf("WenYu", {});
    EXPECT_NE(missing.find("drag law 'WenYu'"), std::string::npos) << missing;
    EXPECT_NE(missing.find("missing required parameter 'd'"), std::string::npos) << missing;
    EXPECT_NE(missing.find("grain diameter [m]"), std::string::npos) << missing;

    for (Real bad : {-1.0e-3, 0.0})
    {
        const std::string msg = errorOf("Beetstra", {{"d", bad}});
        EXPECT_NE(msg.find("parameter 'd'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("(0, inf)"), std::string::npos) << msg;
        EXPECT_NE(msg.find("invalid value"), std::string::npos) << msg;
    }

    const std::string clamp = errorOf("Ergun", {{"d", d}, {"alphaFMin", 1.0}});
    EXPECT_NE(clamp.find("parameter 'alphaFMin'"), std::string::npos) << clamp;

    const std::string typo = errorOf("Ergun", {{"diameter", d}});
    EXPECT_NE(typo.find("unknown parameter 'diameter'"), std::string::npos) << typo;
    EXPECT_NE(typo.find("d, alphaFMin"), std::string::npos) << typo;

    EXPECT_THROW(DragLaw("WenYu", &drag::wenYu, -1.0, 0.2), std::invalid_argument);
    EXPECT_THROW(DragLaw("WenYu", &drag::wenYu, 1.0e-3, 0.0), std::invalid_argument);
}

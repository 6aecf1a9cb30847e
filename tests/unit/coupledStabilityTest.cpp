// Spectral analysis of the coupled MPM-fluid step (coupledSymbol.hpp,
// docs/stabilityAnalysis.md "Coupled analysis"): the symbol is checked
// against the closed forms that hold in limits (long waves, stiff drag,
// one-way coupling), each of which a wrong derivation would break.
#include "stability/coupledSymbol.hpp"
#include "stability/fourierSymbol.hpp"
#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <string>

using namespace mpm;
using namespace mpm::stability;

namespace {

constexpr Real pi = 3.14159265358979323846;
constexpr Real longWave = 1e-3;   // theta: the FV operators' (kh)^2 terms ~1e-7

// Stress-free grains (diffusion model at Fo 0), PIC, linear hat, one point
// at the cell centre: the solid is pure drag.
CoupledSetup dilute(CouplingMode mode, DragVariant variant, bool pressureGradient, Real aS, Real dtOverTau, int n = 1)
{
    CoupledSetup c;
    c.solid.model = Model::diffusion;
    c.solid.shape = ShapeKind::linearHat;
    c.solid.alpha = 0;
    c.solid.offsets = {0.5};
    c.solidNumber = 0;
    c.mode = mode;
    c.variant = variant;
    c.pressureGradient = pressureGradient;
    c.alphaS = aS;
    c.dtOverTau = dtOverTau;
    c.subCycles = n;
    return c;
}

// Eigenvalues sorted by decreasing modulus
std::vector<Complex> sortedEigenvalues(const ComplexMatrix& A)
{
    std::vector<Complex> ev = eigenvalues(A);
    std::sort(ev.begin(), ev.end(), [](Complex a, Complex b) { return std::abs(a) > std::abs(b); });
    return ev;
}

// Long waves (theta -> 0) of stress-free grains: the FV operators tend to
// their continuum values and the step reduces to a 3x3 map of (v, U, Pi),
// Pi = (rho_f/rho_s) grad p, derived here from the algorithm's stages
// without any Fourier symbol. With d = Dt/tau, K and K_U the implicit
// coefficient and its share pulling to U (the rest pulls to v0 = v), per sub-step
//   v_{k+1} (1 + K/n) = v_k + (K_U U + (K - K_U) v0 - [pG] Pi)/n,
// Us the mean of v_1..v_n, and the fluid (aF_f = 1 - aS_f its fraction,
// aS_f = aS in twoWay, 0 otherwise) restores continuity and balances its
// momentum with implicit drag beta/rho_f = aS d/r:
//   U' = -(aS_f/aF_f) Us,
//   Pi' = r U + (r/aF_f) (beta/rho_f (1 + aS_f/aF_f) + aS_f) Us.
// The symbol has these three eigenvalues, the fluid's ddtCorr mode
// aF_f/(aF_f + beta/rho_f) (the face flux relaxing to the interpolated cell
// velocity), and zeros.
std::vector<Complex> longWaveEigenvalues(const CoupledSetup& c, Real K, Real KU)
{
    const int n = c.subCycles;
    const Real d = c.dtOverTau, r = c.densityRatio, aS = c.alphaS;
    const Real aSf = c.mode == CouplingMode::twoWay ? aS : 0.0, aFf = 1 - aSf;
    const Real betaByRho = c.mode == CouplingMode::oneWay ? 0.0 : aS*d/r;
    const Real pg = c.pressureGradient ? 1.0 : 0.0;
    // v and Us as combinations of the state (v, U, Pi)
    Real v[3] = {1, 0, 0}, Us[3] = {0, 0, 0};
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < 3; ++j)
        {
            const Real v0 = j == 0 ? 1.0 : 0.0, U = j == 1 ? 1.0 : 0.0, Pi = j == 2 ? 1.0 : 0.0;
            v[j] = (v[j] + (KU*U + (K - KU)*v0 - pg*Pi)/n)/(1 + K/n);
            Us[j] += v[j]/n;
        }
    ComplexMatrix M(3, 3);
    for (int j = 0; j < 3; ++j)
    {
        M(0, j) = v[j];
        M(1, j) = -(aSf/aFf)*Us[j];
        M(2, j) = (r/aFf)*(betaByRho*(1 + aSf/aFf) + aSf)*Us[j] + (j == 1 ? r : 0.0);
    }
    std::vector<Complex> ev = eigenvalues(M);
    ev.push_back(aFf/(aFf + betaByRho));
    return ev;
}

void expectLongWave(const CoupledSetup& c, Real K, Real KU, const std::string& what)
{
    std::vector<Complex> got = eigenvalues(coupledSymbol(c, longWave));
    for (const Complex& e : longWaveEigenvalues(c, K, KU))
    {
        if (std::abs(e) < 1e-9) continue;   // zero eigenvalues: ill-conditioned, checked below
        auto it = std::min_element(got.begin(), got.end(),
            [&](Complex a, Complex b) { return std::abs(a - e) < std::abs(b - e); });
        EXPECT_LT(std::abs(*it - e), 2e-6*std::max(1.0, std::abs(e))) << what << " expected " << e;
        got.erase(it);
    }
    for (const Complex& z : got) EXPECT_LT(std::abs(z), 1e-6) << what << " extra eigenvalue " << z;
}

} // namespace

// The closed form above, for both two-way modes, the frozen fluid and the
// linearised response, with and without buoyancy, 1 and 3 sub-cycles, light
// and dense suspensions, weak to stiff drag.
TEST(CoupledStability, LongWaveClosedForm)
{
    for (CouplingMode mode : {CouplingMode::twoWay, CouplingMode::twoWayMomentum})
    for (DragVariant var : {DragVariant::frozenFluid, DragVariant::linearised})
    for (bool pg : {false, true})
    for (int n : {1, 3})
    for (Real aS : {0.3, 0.6})
    for (Real d : {0.7, 5.0, 100.0})
    {
        const CoupledSetup c = dilute(mode, var, pg, aS, d, n);
        const Real aF = 1 - aS;
        Real K = d;   // frozen fluid: beta V/m
        if (var == DragVariant::linearised)
        {
            K = mode == CouplingMode::twoWay ? d/aF + (pg ? d*aS/(aF*aF) : 0.0) : d*(1 + (pg ? aS : 0.0));
        }
        expectLongWave(c, K, d, describe(c));
    }
}

// The documented bug: with the fluid frozen over the sub-cycles (implicit
// drag to U, no response) and stiff drag, the grains take the fluid's
// velocity and the fluid step restores aF U = -aS Us: a period-2 mode of
// gain -aS/aF (drag only). With the buoyancy force the frozen pressure
// gradient carries the drag reaction of the last step as well:
// -aS (1 + aF)/aF^2. (Dt/tau = 1e5: the O(tau/Dt) terms are ~1e-5.)
TEST(CoupledStability, FrozenFluidStiffDragGain)
{
    for (Real aS : {0.2, 0.5, 0.6})
    {
        const Real aF = 1 - aS;
        const Complex g = sortedEigenvalues(coupledSymbol(
            dilute(CouplingMode::twoWay, DragVariant::frozenFluid, false, aS, 1e5), longWave)).front();
        EXPECT_NEAR(g.real(), -aS/aF, 1e-4*aS/aF) << "aS " << aS;
        EXPECT_NEAR(g.imag(), 0, 1e-9);
        const Complex gp = sortedEigenvalues(coupledSymbol(
            dilute(CouplingMode::twoWay, DragVariant::frozenFluid, true, aS, 1e5), longWave)).front();
        EXPECT_NEAR(gp.real(), -aS*(1 + aF)/(aF*aF), 1e-4*aS*(1 + aF)/(aF*aF)) << "aS " << aS;
    }
}

// The current scheme (the linearised response) in the same limit: every
// mode of every wavenumber is damped to ~0 per fluid step, with and without
// the buoyancy force, in both two-way modes.
TEST(CoupledStability, LinearisedResponseStiffDragDamps)
{
    for (CouplingMode mode : {CouplingMode::twoWay, CouplingMode::twoWayMomentum})
        for (bool pg : {false, true})
            for (Real aS : {0.2, 0.5, 0.6})
            {
                const CoupledSetup c = dilute(mode, DragVariant::linearised, pg, aS, 1e7);
                EXPECT_LT(coupledMaxSpectralRadius(c, 90), 1e-3)
                    << couplingModeName(mode) << " pg " << pg << " aS " << aS;
            }
}

// The onset of the frozen fluid's period-2 instability (one sub-cycle, drag
// only, long waves): 1 + tr + det = 0 gives Dt/tau = 2 aF/(aS - aF), for
// aS > 1/2 only. The bisection in Dt/tau finds it.
TEST(CoupledStability, FrozenFluidOnset)
{
    LimitOptions o;
    o.maxNumber = 50;
    o.scanPoints = 200;
    for (Real aS : {0.55, 0.6, 0.7})
    {
        const CoupledSetup c = dilute(CouplingMode::twoWay, DragVariant::frozenFluid, false, aS, 1);
        const StabilityLimit lim = stabilityLimit([&](Real D) {
            CoupledSetup t = c;
            t.dtOverTau = D;
            return coupledSpectralRadius(t, longWave) <= 1 + 1e-12;
        }, o);
        const Real aF = 1 - aS;
        EXPECT_NEAR(lim.limit, 2*aF/(aS - aF), 1e-4*2*aF/(aS - aF)) << "aS " << aS;
    }
    // Below aS = 1/2 there is no onset at any drag
    const CoupledSetup c = dilute(CouplingMode::twoWay, DragVariant::frozenFluid, false, 0.45, 1);
    EXPECT_TRUE(coupledStabilityLimit(c, CoupledParameter::dtOverTau, o).reachedMax);
}

// One-way coupling: the fluid does not see the grains (its modes stay at
// rest), and with PIC the grains' block is the pure-MPM symbol of every
// sub-step divided by the drag relaxation 1 + dt K/m.
TEST(CoupledStability, OneWayIsPureSymbolRelaxed)
{
    CoupledSetup c = dilute(CouplingMode::oneWay, DragVariant::linearised, true, 0.3, 1.7, 3);
    c.solid.offsets = {0.25, 0.75};
    c.solidNumber = 0.3;
    const int n = c.solid.pointsPerCell();
    for (Real theta : {0.3, 1.7, pi})
    {
        const ComplexMatrix A = coupledSymbol(c, theta);
        const ComplexMatrix P = amplificationSymbol(c.solid, theta, c.solidNumber);
        // P^3 / (1 + D/3)^3
        std::vector<Complex> P3(n*n, 0), P2(n*n, 0);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k) P2[i*n + j] += P(i, k)*P(k, j);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k) P3[i*n + j] += P2[i*n + k]*P(k, j);
        const Real relax = std::pow(1 + c.dtOverTau/3, 3);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                EXPECT_NEAR(std::abs(A(i, j) - P3[i*n + j]/relax), 0, 1e-14) << "theta " << theta;
        // the grains do not act on the fluid
        for (int i = n; i < A.rows; ++i)
            for (int j = 0; j < n; ++j) EXPECT_EQ(std::abs(A(i, j)), 0) << "theta " << theta;
    }
}

// Explicit drag relaxes every sub-step by 1 - d, d = (Dt/tau)/n: the limit
// Dt/tau = 2 n, independent of kh (one-way, stress-free grains, PIC). The
// resolved kh (theta >= pi/180) shrink |G| by cos^2(theta/2)^n: the limit
// moves by < 1e-3 relative.
TEST(CoupledStability, ExplicitDragLimit)
{
    LimitOptions o;
    o.maxNumber = 20;
    o.scanPoints = 100;
    o.thetaIntervals = 180;
    for (int n : {1, 2, 5})
    {
        const CoupledSetup c = dilute(CouplingMode::oneWay, DragVariant::explicitDrag, false, 0.3, 1, n);
        const StabilityLimit lim = coupledStabilityLimit(c, CoupledParameter::dtOverTau, o);
        EXPECT_NEAR(lim.limit, 2.0*n, 2e-3*n) << "n " << n;
        // implicit drag: no limit
        CoupledSetup imp = c;
        imp.variant = DragVariant::linearised;
        EXPECT_TRUE(coupledStabilityLimit(imp, CoupledParameter::dtOverTau, o).reachedMax) << "n " << n;
    }
}

TEST(CoupledStability, RejectsWhatItDoesNotModel)
{
    CoupledSetup c = dilute(CouplingMode::twoWay, DragVariant::linearised, true, 0.3, 1);
    EXPECT_THROW(coupledSymbol(c, 0.0), std::invalid_argument);
    c.solid.mass = MassMatrix::consistent;
    try { coupledSymbol(c, 0.5); FAIL() << "no exception"; }
    catch (const std::invalid_argument& e) { EXPECT_NE(std::string(e.what()).find("lumped"), std::string::npos); }
}

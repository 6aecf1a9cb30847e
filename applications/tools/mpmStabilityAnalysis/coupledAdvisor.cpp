// mpmStabilityAnalysis --model coupled --advise: the coupled analysis in a
// case's physical parameters (adviseCoupledCase.py reads them from the
// dictionaries). beta and the wave speed come from the core's own drag and
// constitutive laws (no second copy of either); the shipped sub-cycle rule
// n = ceil(Dt/dt_MPM), dt_MPM = courant h/c, is applied at every fluid step
// tried. Prints the MPM step (with the pure-MPM limit and its margin), the
// sub-cycles, max |G| of each variant at the case's step, and the largest
// fluid step the product's scheme keeps stable (scanned up to 8x).
#include "coupledAnalysis.hpp"
#include "cliLists.hpp"
#include "constitutive/constitutiveLaw.hpp"
#include "drag/dragLaw.hpp"
#include "stability/coupledSymbol.hpp"
#include "stability/stabilityLimit.hpp"
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

using namespace mpm;
using namespace mpm::stability;
using cli::fail;
using cli::splitList;
using cli::toReal;

namespace {

Coefficients coefficients(const std::string& s)
{
    Coefficients c;
    for (const std::string& kv : splitList(s))
    {
        const auto eq = kv.find('=');
        if (eq == std::string::npos) fail("coefficients are key=value, got '" + kv + "'");
        c[kv.substr(0, eq)] = toReal(kv.substr(eq + 1));
    }
    return c;
}

struct Physical
{
    std::string law = "dilute", drag = "Ergun";
    Coefficients lawCoeffs, dragCoeffs;
    Real rhoF = 1000, nuF = 1e-6, h = 0, dt = 0, courant = 0.5;
    int thetaIntervals = 60;
};

// The dimensionless setup of fluid step dt, and the MPM step it implies
struct Mapped { CoupledSetup c; Real tau = 0, waveSpeed = 0, dtMpm = 0; };

Mapped mapToSetup(const CoupledSetup& base, const Physical& p, const ConstitutiveLaw& law, const DragLaw& drag, Real dt)
{
    Mapped m;
    m.c = base;
    const Real aS = base.alphaS;
    const Real rhoS = law.rho0();
    const Real beta = drag.beta(1 - aS, 0.0, p.rhoF, p.rhoF*p.nuF);
    m.tau = aS*rhoS/beta;
    m.c.dtOverTau = dt/m.tau;
    m.c.densityRatio = p.rhoF/rhoS;
    m.c.viscousNumber = p.nuF*dt/(p.h*p.h);
    // The solver's signal speed: the law's, for a parcel of aS rho0 (mpmSystem maxSignalSpeed)
    m.waveSpeed = law.waveSpeed(1.0)/std::sqrt(aS);
    if (m.waveSpeed > 0)
    {
        m.dtMpm = p.courant*p.h/m.waveSpeed;
        m.c.solid.model = Model::wave;
        m.c.subCycles = std::max(1, int(std::ceil(dt/m.dtMpm - 1e-9)));
        m.c.solidNumber = m.waveSpeed*(dt/m.c.subCycles)/p.h;
    }
    else
    {
        m.dtMpm = std::numeric_limits<Real>::infinity();
        m.c.solid.model = Model::diffusion;   // stress-free grains
        m.c.subCycles = 1;
        m.c.solidNumber = 0;
    }
    return m;
}

} // namespace

int runAdvisor(int argc, char** argv)
{
    CoupledSetup base;
    base.solid.offsets = {0.5};
    Physical p;
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) fail("missing value after " + a);
            return argv[++i];
        };
        if (a == "--model" || a == "--advise") { if (a == "--model") next(); }
        else if (a == "--law") p.law = next();
        else if (a == "--law-coeffs") p.lawCoeffs = coefficients(next());
        else if (a == "--drag") p.drag = next();
        else if (a == "--drag-coeffs") p.dragCoeffs = coefficients(next());
        else if (a == "--rho-f") p.rhoF = toReal(next());
        else if (a == "--nu-f") p.nuF = toReal(next());
        else if (a == "--h") p.h = toReal(next());
        else if (a == "--fluid-dt") p.dt = toReal(next());
        else if (a == "--courant") p.courant = toReal(next());
        else if (a == "--aS") base.alphaS = toReal(next());
        else if (a == "--theta-intervals") p.thetaIntervals = int(toReal(next()));
        else if (a == "--shape") { const std::string n = next(); if (!parseShape(n, base.solid.shape)) fail("unknown shape " + n); }
        else if (a == "--alpha") base.solid.alpha = toReal(next());
        else if (a == "--scheme") { if (!parseScheme(next(), base.solid.scheme)) fail("unknown scheme (USL USF MUSL)"); }
        else if (a == "--mode") { if (!parseCouplingMode(next(), base.mode)) fail("unknown mode; valid: oneWay twoWayMomentum twoWay"); }
        else if (a == "--forces")
        {
            base.pressureGradient = false;
            for (const auto& f : splitList(next())) if (f == "pressureGradient") base.pressureGradient = true;
        }
        else if (a == "--correctors") base.pisoCorrectors = int(toReal(next()));
        else fail("unknown option " + a + " with --advise");
    }
    if (!(p.h > 0) || !(p.dt > 0)) fail("--advise needs --h and --fluid-dt > 0");
    if (!(base.alphaS > 0 && base.alphaS < 1)) fail("--aS must lie in (0,1)");
    std::unique_ptr<ConstitutiveLaw> law;
    std::unique_ptr<DragLaw> drag;
    try
    {
        law = makeLaw(p.law, p.lawCoeffs);
        drag = makeDragLaw(p.drag, p.dragCoeffs);
    }
    catch (const std::exception& e) { fail(e.what()); }

    const Mapped m = mapToSetup(base, p, *law, *drag, p.dt);
    std::printf("Coupled time-step advice (1D, linearised about rest, kh in (0, pi], %s, %s)\n",
                couplingModeName(base.mode), base.pressureGradient ? "drag + pressureGradient" : "drag");
    std::printf("  drag %s at alpha.fluid %.4g, zero slip: tau_p = %.6g s, Dt/tau_p = %.6g\n",
                p.drag.c_str(), 1 - base.alphaS, m.tau, m.c.dtOverTau);
    if (m.waveSpeed > 0)
    {
        AnalysisSetup pure = m.c.solid;
        const StabilityLimit pureLimit = stabilityLimit(pure, defaultLimitOptions(Model::wave));
        std::printf("  MPM: %s wave speed %.6g m/s (parcel at aS %.4g): step courant %.3g h/c = %.6g s; "
                    "pure-MPM limit CFL %.6g (%s alpha %g %s): margin %.3g\n",
                    p.law.c_str(), m.waveSpeed, base.alphaS, p.courant, m.dtMpm, pureLimit.limit,
                    shapeShortName(pure.shape), pure.alpha, schemeName(pure.scheme), pureLimit.limit/p.courant);
    }
    else
        std::printf("  MPM: %s grains are stress-free: no MPM step limit, 1 sub-cycle\n", p.law.c_str());
    std::printf("  fluid step %.6g s: %d sub-cycles (auto), CFL per sub-step %.4g, nu Dt/h^2 %.4g\n",
                p.dt, m.c.subCycles, m.c.solidNumber, m.c.viscousNumber);
    for (DragVariant v : {DragVariant::linearised, DragVariant::frozenFluid, DragVariant::explicitDrag})
    {
        CoupledSetup c = m.c;
        c.variant = v;
        std::printf("  max |G| over kh, %-10s %s: %.6g\n", dragVariantName(v),
                    v == DragVariant::linearised ? "(the product)" : "             ",
                    coupledMaxSpectralRadius(c, p.thetaIntervals));
    }
    // The product's largest stable fluid step, every parameter following Dt
    LimitOptions o;
    o.maxNumber = 8;
    o.scanPoints = 32;
    o.relTolerance = 1e-4;
    const StabilityLimit L = stabilityLimit([&](Real f) {
        CoupledSetup c = mapToSetup(base, p, *law, *drag, f*p.dt).c;
        c.variant = DragVariant::linearised;
        return coupledMaxSpectralRadius(c, p.thetaIntervals) <= 1 + 1e-9;
    }, o);
    if (L.reachedMax)
        std::printf("  largest stable fluid step: >= %.6g s (stable up to 8x the step scanned; margin >= 8)\n", 8*p.dt);
    else
        std::printf("  largest stable fluid step: %.6g s (margin %.4g)\n", L.limit*p.dt, L.limit);
    return 0;
}

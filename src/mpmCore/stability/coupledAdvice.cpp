#include "coupledAdvice.hpp"
#include "constitutive/constitutiveLaw.hpp"
#include "drag/dragLaw.hpp"
#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>

namespace mpm {
namespace stability {

MappedCoupledStep mapCoupledStep(const CoupledCase& cc, const ConstitutiveLaw& law, const DragLaw& drag, Real dt)
{
    MappedCoupledStep m;
    m.setup = cc.base;
    const Real aS = cc.base.alphaS;
    const Real rhoS = law.rho0();
    const Real beta = drag.beta(1 - aS, 0.0, cc.rhoF, cc.rhoF*cc.nuF);
    m.tau = aS*rhoS/beta;
    m.setup.dtOverTau = dt/m.tau;
    m.setup.densityRatio = cc.rhoF/rhoS;
    m.setup.viscousNumber = cc.nuF*dt/(cc.h*cc.h);
    // The solver's signal speed: the law's, for a parcel of aS rho0 (mpmSystem maxSignalSpeed)
    m.waveSpeed = law.waveSpeed(1.0)/std::sqrt(aS);
    if (m.waveSpeed > 0)
    {
        m.dtMpm = cc.courant*cc.h/m.waveSpeed;
        m.setup.solid.model = Model::wave;
        m.setup.subCycles = std::max(1, int(std::ceil(dt/m.dtMpm - 1e-9)));
        m.setup.solidNumber = m.waveSpeed*(dt/m.setup.subCycles)/cc.h;
    }
    else
    {
        m.dtMpm = std::numeric_limits<Real>::infinity();
        m.setup.solid.model = Model::diffusion;   // stress-free grains
        m.setup.subCycles = 1;
        m.setup.solidNumber = 0;
    }
    return m;
}

CoupledAdvice adviseCoupled(const CoupledCase& cc, const ConstitutiveLaw& law, const DragLaw& drag)
{
    CoupledAdvice a;
    a.step = mapCoupledStep(cc, law, drag, cc.dt);
    if (a.step.waveSpeed > 0)
        a.pureMpm = stabilityLimit(a.step.setup.solid, defaultLimitOptions(Model::wave));
    auto maxG = [&](DragVariant v) {
        CoupledSetup c = a.step.setup;
        c.variant = v;
        return coupledMaxSpectralRadius(c, cc.thetaIntervals);
    };
    a.maxGLinearised = maxG(DragVariant::linearised);
    a.maxGFrozen = maxG(DragVariant::frozenFluid);
    a.maxGExplicit = maxG(DragVariant::explicitDrag);
    // The product's largest stable fluid step, every parameter following Dt
    LimitOptions o;
    o.maxNumber = 8;
    o.scanPoints = 32;
    o.relTolerance = 1e-4;
    a.fluidStepFactor = stabilityLimit([&](Real f) {
        CoupledSetup c = mapCoupledStep(cc, law, drag, f*cc.dt).setup;
        c.variant = DragVariant::linearised;
        return coupledMaxSpectralRadius(c, cc.thetaIntervals) <= 1 + 1e-9;
    }, o);
    return a;
}

namespace {

std::string format(const char* fmt, ...)
{
    char buf[512];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, args);
    va_end(args);
    return buf;
}

} // namespace

std::vector<std::string> adviceLines(const CoupledCase& cc, const CoupledAdvice& a)
{
    const CoupledSetup& c = a.step.setup;
    const Real aS = cc.base.alphaS;
    std::vector<std::string> l;
    l.push_back(format("Coupled time-step advice (1D, linearised about rest, kh in (0, pi], %s, %s)",
                       couplingModeName(c.mode), c.pressureGradient ? "drag + pressureGradient" : "drag"));
    l.push_back(format("  drag %s at alpha.fluid %.4g, zero slip: tau_p = %.6g s, Dt/tau_p = %.6g",
                       cc.dragName.c_str(), 1 - aS, a.step.tau, c.dtOverTau));
    if (a.step.waveSpeed > 0)
        l.push_back(format("  MPM: %s wave speed %.6g m/s (parcel at aS %.4g): step courant %.3g h/c = %.6g s; "
                           "pure-MPM limit CFL %.6g (%s alpha %g %s): margin %.3g",
                           cc.lawName.c_str(), a.step.waveSpeed, aS, cc.courant, a.step.dtMpm, a.pureMpm.limit,
                           shapeShortName(c.solid.shape), c.solid.alpha, stressUpdateName(c.solid.scheme),
                           a.pureMpm.limit/cc.courant));
    else
        l.push_back(format("  MPM: %s grains are stress-free: no MPM step limit, 1 sub-cycle", cc.lawName.c_str()));
    l.push_back(format("  fluid step %.6g s: %d sub-cycles (auto), CFL per sub-step %.4g, nu Dt/h^2 %.4g",
                       cc.dt, c.subCycles, c.solidNumber, c.viscousNumber));
    l.push_back(format("  max |G| over kh, %-10s %s: %.6g", dragVariantName(DragVariant::linearised),
                       "(the product)", a.maxGLinearised));
    l.push_back(format("  max |G| over kh, %-10s %s: %.6g", dragVariantName(DragVariant::frozenFluid),
                       "             ", a.maxGFrozen));
    l.push_back(format("  max |G| over kh, %-10s %s: %.6g", dragVariantName(DragVariant::explicitDrag),
                       "             ", a.maxGExplicit));
    if (a.fluidStepFactor.reachedMax)
        l.push_back(format("  largest stable fluid step: >= %.6g s (stable up to 8x the step scanned; margin >= 8)",
                           8*cc.dt));
    else
        l.push_back(format("  largest stable fluid step: %.6g s (margin %.4g)",
                           a.fluidStepFactor.limit*cc.dt, a.fluidStepFactor.limit));
    return l;
}

} // namespace stability
} // namespace mpm

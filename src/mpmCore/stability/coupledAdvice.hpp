// Time-step advice for a coupled case: the coupled analysis (coupledSymbol)
// in a case's physical parameters. One home for it: the solver's advice
// (src/mpmFoam/coupling/coupledTimeStepAdvice: a run's start-up print and
// mpmFoam -adviseTimeStep, i.e. mpmAdviseTimeStep <case>, the case advisor)
// and the tool's --advise (mpmStabilityAnalysis --model coupled --advise,
// adviseCoupledCase.py's parameter studies) both call adviseCoupled and
// print adviceLines (tests/cases/coupledSolverAdvice.sh).
//
// beta (zero slip) and the parcel's wave speed come from the core's own drag
// and constitutive laws; the shipped sub-cycle rule n = ceil(Dt/dt_MPM),
// dt_MPM = courant h/c, is applied at every fluid step tried. Stress-free
// grains (wave speed 0) are the diffusion model at Fo 0 with 1 sub-cycle.
#pragma once
#include "coupledSymbol.hpp"
#include <string>
#include <vector>

namespace mpm {
class ConstitutiveLaw;
class DragLaw;

namespace stability {

struct CoupledCase
{
    // mode, pressureGradient, alphaS, pisoCorrectors and the solid's shape,
    // FLIP fraction and stress update; the rest follows from the numbers below
    CoupledSetup base;
    std::string lawName, dragName;  // for the printed lines only
    Real rhoF = 1000, nuF = 1e-6;   // fluid density, kinematic viscosity
    Real h = 0;                     // cell size
    Real dt = 0;                    // fluid step
    Real courant = 0.5;             // the MPM step's courant (timeStep courant)
    int thetaIntervals = 60;        // kh samples in (0, pi]
};

// The dimensionless setup of fluid step dt and the MPM step it implies
struct MappedCoupledStep
{
    CoupledSetup setup;
    Real tau = 0;        // drag relaxation time aS rho_s/beta
    Real waveSpeed = 0;  // the parcel's: law.waveSpeed(1)/sqrt(aS); 0 stress-free
    Real dtMpm = 0;      // courant h/c (inf when stress-free)
};

MappedCoupledStep mapCoupledStep(const CoupledCase&, const ConstitutiveLaw&, const DragLaw&, Real dt);

struct CoupledAdvice
{
    MappedCoupledStep step;           // at the case's fluid step
    StabilityLimit pureMpm;           // pure-MPM CFL limit (elastic grains only)
    Real maxGLinearised = 0, maxGFrozen = 0, maxGExplicit = 0;
    StabilityLimit fluidStepFactor;   // largest stable fluid step / dt, scanned to 8
};

CoupledAdvice adviseCoupled(const CoupledCase&, const ConstitutiveLaw&, const DragLaw&);

// The advice as printed (no trailing newlines): a heading and indented lines
std::vector<std::string> adviceLines(const CoupledCase&, const CoupledAdvice&);

} // namespace stability
} // namespace mpm

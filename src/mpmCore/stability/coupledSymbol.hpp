// Fourier symbol of one fluid step of the coupled MPM-fluid update
// (fluidCoupling::advanceSolids + fluidPhase::solve), linearised about rest
// without gravity, on the periodic 1D lattice whose nodes are the fluid's
// cell centres (see docs/stabilityAnalysis.md, "Coupled analysis").
//
// Units: h = 1 (cell), fluid step Dt = 1. Per mode theta = k h the state is
//   x = (v_1..v_npc [, s_1..s_npc], U, phi, p)
// point velocities (and scaled stresses for the wave), the fluid's cell
// velocity U, face flux phi (per unit area, phase of the face x + h/2) and
// kinematic pressure p. The symbol is read off the algorithm applied to
// every basis state, operator by operator, as the product runs it:
//  * n MPM sub-steps with the forces' terms frozen at the start of the step:
//    (m + dt K) v = p + dt (f + V_s F + K U_K), F = -rho_f grad p,
//    K and U_K of the chosen variant and mode;
//  * the PIMPLE step (one outer, `pisoCorrectors` correctors, momentum
//    predictor): Euler ddt, implicit drag, laminar viscous terms (implicit
//    Laplacian + explicit dev2 part), Gauss linear gradients, linear
//    interpolation, the flux-reconstructed cell velocity, ddtCorr with its
//    coupling coefficient (ddtCorrCoefficient, 1 by default: see below),
//    and the mixture continuity div(aF phi) + div(aS_f Us_f) = 0 with Us
//    the solid's grid velocity averaged over the sub-steps.
// The lumped mass only (the product's consistent mass is an approximate
// Jacobi solve).
#pragma once
#include "stabilitySetup.hpp"
#include "stabilityLimit.hpp"

namespace mpm {
namespace stability {

enum class CouplingMode { oneWay, twoWayMomentum, twoWay };

// How the solids see the fluid during the sub-steps:
//  explicitDrag: beta V (U - v_o) explicit, v_o the sub-step's P2G velocity;
//  frozenFluid:  implicit K = beta V pulling to the frozen U (the scheme
//                before the linearised response);
//  linearised:   the product's current scheme: the drag's slip response
//                (K = beta V/aF, target beta V U + (K - beta V) v0) and, with
//                pressureGradient, K_p = (aS/aF) beta V/aF pulling to v0.
enum class DragVariant { explicitDrag, frozenFluid, linearised };

struct CoupledSetup
{
    AnalysisSetup solid;            // diffusion (Fo 0: stress-free grains) or wave
    CouplingMode mode = CouplingMode::twoWay;
    DragVariant variant = DragVariant::linearised;
    bool pressureGradient = true;   // the pressureGradient force is listed
    Real alphaS = 0.3;              // solid volume fraction (uniform)
    Real densityRatio = 1.0/2.5;    // rho_f / rho_s (grain density)
    int subCycles = 1;              // MPM steps per fluid step
    Real solidNumber = 0;           // Fo or CFL of one MPM sub-step
    Real dtOverTau = 1;             // Dt/tau_p, tau_p = aS rho_s/beta
    Real viscousNumber = 0;         // nu Dt/h^2 of the fluid
    int pisoCorrectors = 3;         // PIMPLE nCorrectors
    bool momentumPredictor = true;
    // OpenFOAM's Euler ddtCorr multiplies (phi^n - flux(U^n))/Dt by
    // 1 - min(|phi^n - flux(U^n)|/|phi^n|, 1) per face: scale-free but not
    // linear. For one real mode the ratio is uniform and real, ~ sin^2(kh/2)
    // times the pressure's share of the flux; the linear analysis takes 1
    // (its limit), a comparison with a run may pass the state's value.
    Real ddtCorrCoefficient = 1;

    int stateSize() const { return solid.stateSize() + 3; }
    Real alphaF() const { return 1 - alphaS; }
};

const char* couplingModeName(CouplingMode);
const char* dragVariantName(DragVariant);
bool parseCouplingMode(const std::string&, CouplingMode&);
bool parseDragVariant(const std::string&, DragVariant&);
std::string describe(const CoupledSetup&);

// Per unit solid mass, in 1/Dt: the implicit coefficient K/m and the share
// of it that pulls to the fluid velocity (the rest pulls to v0).
struct ImplicitDrag { Real K = 0, KtoU = 0; };
ImplicitDrag implicitDrag(const CoupledSetup&);

// Amplification symbol of one fluid step for theta in (0, pi] (theta = 0,
// the mean flow, has no pressure equation and is not a mode of this map).
ComplexMatrix coupledSymbol(const CoupledSetup&, Real theta);

Real coupledSpectralRadius(const CoupledSetup&, Real theta);
// max over theta_j = pi j/thetaIntervals, j = 1..thetaIntervals
Real coupledMaxSpectralRadius(const CoupledSetup&, int thetaIntervals = 180);

// The parameters a stability limit or a map can be taken in.
enum class CoupledParameter { dtOverTau, alphaS, solidNumber, densityRatio, viscousNumber };
const char* parameterName(CoupledParameter);
bool parseParameter(const std::string&, CoupledParameter&);
void setParameter(CoupledSetup&, CoupledParameter, Real);

// max |G| <= 1 + o.slack over theta_j = pi j/o.thetaIntervals, j >= 1
bool isStable(const CoupledSetup&, const LimitOptions&);
// sup of the stable interval (0, p] in one parameter (the scan and bisection
// of stabilityLimit.hpp)
StabilityLimit coupledStabilityLimit(const CoupledSetup&, CoupledParameter, const LimitOptions&);

} // namespace stability
} // namespace mpm

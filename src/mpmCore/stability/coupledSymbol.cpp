#include "coupledSymbol.hpp"
#include "../common/enumTable.hpp"
#include "stepSymbol.hpp"
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mpm {
namespace stability {

using namespace detail;

namespace
{
const auto couplingModes = enumTable<CouplingMode>
({{CouplingMode::oneWay, "oneWay"}, {CouplingMode::twoWayMomentum, "twoWayMomentum"}, {CouplingMode::twoWay, "twoWay"}});
const auto dragVariants = enumTable<DragVariant>
({{DragVariant::explicitDrag, "explicit"}, {DragVariant::frozenFluid, "frozen"}, {DragVariant::linearised, "linearised"}});
const auto parameters = enumTable<CoupledParameter>
({{CoupledParameter::dtOverTau, "dtOverTau"}, {CoupledParameter::alphaS, "alphaS"},
  {CoupledParameter::solidNumber, "number"}, {CoupledParameter::densityRatio, "densityRatio"},
  {CoupledParameter::viscousNumber, "viscousNumber"}});
}

const char* couplingModeName(CouplingMode m) { return couplingModes.name(m); }
const char* dragVariantName(DragVariant v) { return dragVariants.name(v); }
bool parseCouplingMode(const std::string& n, CouplingMode& m) { return couplingModes.parse(n, m); }
bool parseDragVariant(const std::string& n, DragVariant& v) { return dragVariants.parse(n, v); }

std::string describe(const CoupledSetup& c)
{
    std::ostringstream os;
    os << couplingModeName(c.mode) << ' ' << dragVariantName(c.variant)
       << (c.pressureGradient ? " drag+pressureGradient" : " drag")
       << " aS=" << c.alphaS << " rhoF/rhoS=" << c.densityRatio
       << " Dt/tau=" << c.dtOverTau << " subCycles=" << c.subCycles
       << (c.solid.model == Model::wave ? " CFL=" : " Fo=") << c.solidNumber
       << " nuDt/h2=" << c.viscousNumber << " | " << describe(c.solid);
    return os.str();
}

ImplicitDrag implicitDrag(const CoupledSetup& c)
{
    // Per unit solid mass m = aS rho_s V: beta V/m = 1/tau_p = dtOverTau.
    const Real d = c.dtOverTau, aS = c.alphaS, aF = c.alphaF();
    ImplicitDrag k;
    if (c.variant == DragVariant::explicitDrag) return k;
    k.KtoU = d;
    k.K = d;
    if (c.variant == DragVariant::frozenFluid) return k;
    // dragForce::addTo: K = beta V/aF (aF = 1 unless twoWay)
    // pressureGradientForce::addTo: K_p = beta V (slip per dv) aS/aF, two-way modes only
    switch (c.mode)
    {
        case CouplingMode::twoWay:
            k.K = d/aF + (c.pressureGradient ? d*aS/(aF*aF) : 0.0);
            break;
        case CouplingMode::twoWayMomentum:
            k.K = d + (c.pressureGradient ? d*aS : 0.0);
            break;
        case CouplingMode::oneWay:
            break;
    }
    return k;
}

ComplexMatrix coupledSymbol(const CoupledSetup& c, Real theta)
{
    if (c.solid.mass != MassMatrix::lumped)
        throw std::invalid_argument("coupled analysis: the lumped mass only");
    if (!(theta > 0))
        throw std::invalid_argument("coupled analysis: theta must be > 0 (the mean flow is not a mode)");
    if (c.subCycles < 1 || c.pisoCorrectors < 1)
        throw std::invalid_argument("coupled analysis: subCycles and pisoCorrectors must be >= 1");
    const AnalysisSetup& s = c.solid;
    const int n = s.pointsPerCell();
    const int Ks = s.stateSize();
    const int K = c.stateSize();
    const int iU = Ks, iPhi = Ks + 1, iP = Ks + 2;
    const TransferSymbols t = transferSymbols(s, theta);

    // Finite-volume symbols on the uniform 1D mesh (h = 1); a face value's
    // phase is that of its position x + 1/2.
    const Complex I(0, 1);
    const Real cf = std::cos(0.5*theta);          // linear interpolation, reconstruct
    const Real sg = 2*std::sin(0.5*theta);        // snGrad and div: i sg
    const Complex gradCell = I*std::sin(theta);   // Gauss linear cell gradient

    const bool twoWay = c.mode == CouplingMode::twoWay;
    const Real aS = c.alphaS;
    const Real r = c.densityRatio;
    const Real dts = 1.0/c.subCycles;
    const ImplicitDrag kd = implicitDrag(c);
    const bool explicitDrag = c.variant == DragVariant::explicitDrag;
    const Real pgFactor = c.pressureGradient ? r : 0.0;

    // Basis states as columns; the rows below are the quantities the step
    // computes, as linear combinations of the state.
    const Mat Id = Mat::Identity(K, K);
    const RowVec U0 = Id.row(iU), phi0 = Id.row(iPhi), p0 = Id.row(iP);
    Mat v = Id.topRows(n);
    Mat sig = s.model == Model::wave ? Mat(Id.middleRows(n, n)) : Mat();

    // 1. The forces' terms at the start of the step: v0 the P2G velocity
    //    (mapToGrid), U and grad p of the last fluid step.
    const RowVec v0 = gridVelocity(s, t, v);
    const RowVec pressureForce = -pgFactor*gradCell*p0;   // V_s F/m = -(rho_f/rho_s) grad p
    const RowVec pull = kd.KtoU*U0 + (kd.K - kd.KtoU)*v0;  // K U_K / m

    // 2. The sub-cycles: (m + dt K) v = m vnPure + dt (V_s F + K U_K)
    RowVec Us = RowVec::Zero(K);
    for (int k = 0; k < c.subCycles; ++k)
    {
        const NodalUpdate nodal = [&](const RowVec& vo, const RowVec& vnPure) -> RowVec
        {
            if (explicitDrag) return vnPure + dts*(c.dtOverTau*(U0 - vo) + pressureForce);
            return (vnPure + dts*(pull + pressureForce))/(1.0 + dts*kd.K);
        };
        const StepResult st = mpmStep(s, t, c.solidNumber, v, sig, nodal);
        v = st.v;
        sig = st.sigma;
        Us += dts*st.vGrid;    // velocityIntegral/time
    }

    // 3. The fluid step (fluidPhase::solve) against the averaged solid
    //    velocity. oneWay: alpha.fluid 1, beta zeroed for the fluid
    //    (dragForce::afterSolids), no solid flux; twoWayMomentum: alpha.fluid 1.
    const Real aF = twoWay ? c.alphaF() : 1.0;
    const Real aSf = twoWay ? aS : 0.0;                 // interpolate(1 - alpha.fluid)
    const Real betaByRho = c.mode == CouplingMode::oneWay ? 0.0 : aS*c.dtOverTau/r;
    const Real nu = c.viscousNumber;
    // UEqn: ddt(aF, U) + Sp(beta/rho) - laplacian(aF nu, U) - div(aF nu dev2(T(grad U)))
    const Real diag = aF + betaByRho + 2*aF*nu;
    const Real offDiagSum = -2*aF*nu*std::cos(theta);       // both neighbours, per mode
    const Real rAU = 1.0/diag;
    // source: aF U^n + div(aF nu (1/3) grad U^n) (the dev2 part in 1D)
    const RowVec b = aF*U0 + (1.0/3.0)*aF*nu*(I*sg)*cf*gradCell*U0;
    auto H = [&](const RowVec& Ucur) -> RowVec { return b - offDiagSum*Ucur; };

    const RowVec phiForces = cf*rAU*betaByRho*Us;           // flux(rAU beta/rho Us)
    RowVec U = U0;
    if (c.momentumPredictor)
    {
        U = (b + cf*(phiForces/rAU - aF*(I*sg)*p0))/(diag + offDiagSum);
    }
    RowVec phi = phi0, p = p0;
    for (int corr = 0; corr < c.pisoCorrectors; ++corr)
    {
        const RowVec HbyA = rAU*H(U);
        // ddtCorr(U, phi) (Euler, Dt = 1)
        const RowVec phiHbyA = cf*HbyA + c.ddtCorrCoefficient*aF*rAU*(phi0 - cf*U0) + phiForces;
        // laplacian(aF^2 rAU, p) = div(aF phiHbyA) + div(aS_f flux(Us))
        p = -I*(aF*phiHbyA + aSf*cf*Us)/(sg*aF*aF*rAU);
        phi = phiHbyA - aF*rAU*(I*sg)*p;
        U = HbyA + rAU*cf*(phiForces/rAU - aF*(I*sg)*p);
    }

    Mat A(K, K);
    A.topRows(n) = v;
    if (s.model == Model::wave) A.middleRows(n, n) = sig;
    A.row(iU) = U;
    A.row(iPhi) = phi;
    A.row(iP) = p;
    return fromEigen(A);
}

Real coupledSpectralRadius(const CoupledSetup& c, Real theta)
{
    const Mat A = toEigen(coupledSymbol(c, theta));
    Eigen::ComplexEigenSolver<Mat> es(A, false);
    Real rho = 0;
    for (int i = 0; i < es.eigenvalues().size(); ++i) rho = std::max(rho, std::abs(es.eigenvalues()(i)));
    return rho;
}

Real coupledMaxSpectralRadius(const CoupledSetup& c, int thetaIntervals)
{
    constexpr Real pi = 3.14159265358979323846;
    Real rho = 0;
    for (int j = 1; j <= thetaIntervals; ++j) rho = std::max(rho, coupledSpectralRadius(c, pi*j/thetaIntervals));
    return rho;
}

const char* parameterName(CoupledParameter p) { return parameters.name(p); }
bool parseParameter(const std::string& n, CoupledParameter& p) { return parameters.parse(n, p); }

void setParameter(CoupledSetup& c, CoupledParameter p, Real x)
{
    switch (p)
    {
        case CoupledParameter::dtOverTau: c.dtOverTau = x; break;
        case CoupledParameter::alphaS: c.alphaS = x; break;
        case CoupledParameter::solidNumber: c.solidNumber = x; break;
        case CoupledParameter::densityRatio: c.densityRatio = x; break;
        case CoupledParameter::viscousNumber: c.viscousNumber = x; break;
    }
}

bool isStable(const CoupledSetup& c, const LimitOptions& o)
{
    return coupledMaxSpectralRadius(c, o.thetaIntervals) <= 1.0 + o.slack;
}

StabilityLimit coupledStabilityLimit(const CoupledSetup& c, CoupledParameter p, const LimitOptions& o)
{
    return stabilityLimit([&](Real x) { CoupledSetup t = c; setParameter(t, p, x); return isStable(t, o); }, o);
}

} // namespace stability
} // namespace mpm

#include "druckerPrager.hpp"
#include "tensorOps.hpp"
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mpm {

namespace {

Real degToRad(Real deg) { return deg*M_PI/180.0; }

// Common denominator of the plane-strain match, sqrt(9 + 12 tan^2).
Real planeStrainDenominator(Real angleDeg)
{
    const Real t = std::tan(degToRad(angleDeg));
    return std::sqrt(9.0 + 12.0*t*t);
}

} // namespace

Real DruckerPrager::planeStrainEta(Real angleDeg)
{
    return 3.0*std::sqrt(3.0)*std::tan(degToRad(angleDeg))/planeStrainDenominator(angleDeg);
}

Real DruckerPrager::planeStrainXi(Real angleDeg)
{
    return 3.0*std::sqrt(3.0)/planeStrainDenominator(angleDeg);
}

DruckerPrager::DruckerPrager(Real rho, Real E, Real nu, Real phiDeg, Real c, Real psiDeg,
                             Real alphaContact)
:
    IsotropicElasticLaw(rho, E, nu),
    cohesion_(c),
    eta_(planeStrainEta(phiDeg)),
    xi_(planeStrainXi(phiDeg)),
    etaBar_(planeStrainEta(psiDeg)),
    alphaContact_(alphaContact)
{
    // The only constraint between parameters; ranges are checked by makeLaw.
    if (!(psiDeg <= phiDeg))
    {
        std::ostringstream msg;
        msg << "constitutive law 'druckerPrager': parameter 'psi' (dilatancy angle) = "
            << psiDeg << " must not exceed the friction angle 'phi' = " << phiDeg;
        throw std::invalid_argument(msg.str());
    }
}

std::unique_ptr<ConstitutiveLaw> DruckerPrager::create(const Coefficients& c)
{
    return std::make_unique<DruckerPrager>
    (
        c.at("rho"), c.at("E"), c.at("nu"), c.at("phi"), c.at("c"), c.at("psi"),
        c.at("alphaContact")
    );
}

Real DruckerPrager::yieldFunction(const Real* sigma) const
{
    using namespace tensor;
    Sym6 s{sigma[0], sigma[1], sigma[2], sigma[3], sigma[4], sigma[5]};
    const Real p = -trace(s.data())/3.0;
    makeDeviatoric(s.data());
    const Real q = std::sqrt(1.5*ddot(s.data(), s.data()));
    return q - eta_*p - xi_*cohesion_;
}

Real DruckerPrager::returnMap(Real* sigma) const
{
    using namespace tensor;
    const Sym6 trial{sigma[0], sigma[1], sigma[2], sigma[3], sigma[4], sigma[5]};
    const Real f = yieldFunction(sigma);
    if (f <= 0) return 0;

    const Real G = el_.mu;
    const Real K = el_.bulkModulus();
    Sym6 s = trial;
    const Real p = -trace(s.data())/3.0;
    makeDeviatoric(s.data());
    const Real q = std::sqrt(1.5*ddot(s.data(), s.data()));

    // Cone return: with perfect plasticity and the stress correction
    // -dgamma C:dg/dsigma = -dgamma (3G s/q - K etaBar I), f is linear in
    // dgamma, so the consistency condition is solved in closed form.
    const Real dgamma = f/(3.0*G + eta_*etaBar_*K);
    const Real qNew = q - 3.0*G*dgamma;
    if (qNew > 0 || eta_ <= 0)
    {
        const Real scale = qNew/q;
        const Real pNew = p + K*etaBar_*dgamma;
        for (int a = 0; a < 6; ++a) sigma[a] = scale*s[a];
        for (int a = 0; a < 3; ++a) sigma[a] -= pNew;
    }
    else
    {
        // The cone return would cross the axis: the trial lies beyond the
        // apex (tension), return to the apex. This is the tension cut-off.
        const Real pApex = -xi_*cohesion_/eta_;
        for (int a = 0; a < 6; ++a) sigma[a] = 0;
        for (int a = 0; a < 3; ++a) sigma[a] = -pApex;
    }

    // Plastic strain increment = elastic compliance of the stress correction.
    Sym6 dStrain;
    for (int a = 0; a < 6; ++a) dStrain[a] = trial[a] - sigma[a];
    const Real volumetric = trace(dStrain.data())/(9.0*K);
    makeDeviatoric(dStrain.data());
    for (int a = 0; a < 6; ++a) dStrain[a] /= 2.0*G;
    for (int a = 0; a < 3; ++a) dStrain[a] += volumetric;
    return std::sqrt(2.0/3.0*ddot(dStrain.data(), dStrain.data()));
}

void DruckerPrager::updateStress(const PointKinematics& k, PointStress& s) const
{
    if (k.solidFraction < alphaContact_)
    {
        for (int a = 0; a < 6; ++a) s.sigma[a] = 0;
        return;
    }
    jaumannElasticUpdate(el_, k.L, k.dt, s.sigma);
    const Real dEqPlastic = returnMap(s.sigma);
    if (s.eqPlasticStrain) *s.eqPlasticStrain += dEqPlastic;
}

Real DruckerPrager::waveSpeed(Real) const
{
    // Elastic wave speed: plastic flow only softens the material.
    return std::sqrt(el_.pWaveModulus()/rho0_);
}

Real DruckerPrager::storedEnergy(const Real* sigma, const Real* F) const
{
    return el_.complementaryEnergy(sigma)*tensor::det(F);
}

} // namespace mpm

#include "druckerPrager.hpp"
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

Real DruckerPrager::shearStrengthRatio() const
{
    return cohesion_ > 0 ? ConstitutiveLaw::shearStrengthRatio() : eta_/std::sqrt(3.0);
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

DruckerPragerParams DruckerPrager::kernelParams() const
{
    return {el_, el_.bulkModulus(), cohesion_, eta_, xi_, etaBar_, alphaContact_};
}

LawParams DruckerPrager::params() const
{
    LawParams p = baseParams(LawType::druckerPrager);
    p.druckerPrager = kernelParams();
    return p;
}

Real DruckerPrager::yieldFunction(const Real* sigma) const
{
    const DruckerPragerInvariants v = druckerPragerInvariants(sigma);
    return druckerPragerYield(kernelParams(), v.p, v.q);
}

void DruckerPrager::updateStress(const PointKinematics& k, PointStress& s) const
{
    druckerPragerStress(kernelParams(), k, s);
}

Real DruckerPrager::storedEnergy(const Real* sigma, const Real* F) const
{
    return el_.complementaryEnergy(sigma)*tensor::det(F);
}

} // namespace mpm

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
    phiDeg_(phiDeg),
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

Real DruckerPrager::phiForSimpleShear(Real mu)
{
    return std::atan(3*mu/std::sqrt(9 - 12*mu*mu))*180.0/M_PI;
}

std::unique_ptr<ConstitutiveLaw> DruckerPrager::create(const Coefficients& c)
{
    const Real phi = c.at("phi"), mu = c.at("mu");
    if (std::isnan(phi) == std::isnan(mu))
    {
        throw std::invalid_argument
        (
            std::string("constitutive law 'druckerPrager': give the friction as 'phi' (angle [deg], ")
            + "matched to Mohr-Coulomb in plane strain) or as 'mu' (the coefficient mobilised in "
            + "simple shear, tau <= mu p), " + (std::isnan(phi) ? "not neither" : "not both")
        );
    }
    auto law = std::make_unique<DruckerPrager>
    (
        c.at("rho"), c.at("E"), c.at("nu"), std::isnan(phi) ? phiForSimpleShear(mu) : phi, c.at("c"),
        c.at("psi"), c.at("alphaContact")
    );
    law->givenAsMu_ = !std::isnan(mu);
    return law;
}

std::string DruckerPrager::note() const
{
    std::ostringstream s;
    s.precision(4);
    const Real mu = eta_/std::sqrt(3.0);
    if (givenAsMu_)
    {
        s << "mu " << mu << " in simple shear: phi = " << phiDeg_
          << " deg in the plane-strain Mohr-Coulomb match";
    }
    else
    {
        s << "phi " << phiDeg_ << " deg (plane-strain Mohr-Coulomb match) mobilises mu = " << mu
          << " (" << std::atan(mu)*180.0/M_PI << " deg) in simple shear, not tan(phi) = "
          << std::tan(phiDeg_*M_PI/180.0);
    }
    return s.str() + " (docs/druckerPrager.md)";
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

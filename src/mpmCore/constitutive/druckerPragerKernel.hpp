// Per-point stress update of DruckerPrager (host and device): Jaumann-rate
// elastic trial, then the closed-form return map onto the cone or the apex
// (see druckerPrager.hpp for the model).
#pragma once
#include "isotropicElasticity.hpp"
#include "pointState.hpp"
#include <cmath>

namespace mpm {

struct DruckerPragerParams
{
    IsotropicElasticity el;
    Real K;              // bulk modulus, el.bulkModulus()
    Real cohesion;
    Real eta, xi, etaBar;
    Real alphaContact;   // solid fraction below which the grains are stress-free
};

// Invariants of sigma: p = -tr/3, the deviator s and q = sqrt(3 J2).
struct DruckerPragerInvariants
{
    Real p, q;
    Real s[6];
};

MPM_HOST_DEVICE inline DruckerPragerInvariants druckerPragerInvariants(const Real* sigma)
{
    DruckerPragerInvariants v;
    tensor::copy6(sigma, v.s);
    v.p = -tensor::trace(v.s)/3.0;
    tensor::makeDeviatoric(v.s);
    v.q = std::sqrt(1.5*tensor::ddot(v.s, v.s));
    return v;
}

// f = q - eta p - xi c, in stress units (<= 0 is admissible).
MPM_HOST_DEVICE inline Real druckerPragerYield(const DruckerPragerParams& c, Real p, Real q)
{
    return q - c.eta*p - c.xi*c.cohesion;
}

// Projects an elastic trial stress onto the yield surface; returns the
// equivalent plastic strain increment (0 if the trial is admissible).
MPM_HOST_DEVICE inline Real druckerPragerReturnMap(const DruckerPragerParams& c, Real* sigma)
{
    const DruckerPragerInvariants v = druckerPragerInvariants(sigma);
    const Real f = druckerPragerYield(c, v.p, v.q);
    if (f <= 0) return 0;

    Real trial[6];
    tensor::copy6(sigma, trial);
    const Real G = c.el.mu;
    const Real K = c.K;

    // Cone return: with perfect plasticity and the stress correction
    // -dgamma C:dg/dsigma = -dgamma (3G s/q - K etaBar I), f is linear in
    // dgamma, so the consistency condition is solved in closed form.
    const Real dgamma = f/(3.0*G + c.eta*c.etaBar*K);
    const Real qNew = v.q - 3.0*G*dgamma;
    if (qNew > 0 || c.eta <= 0)
    {
        const Real scale = qNew/v.q;
        const Real pNew = v.p + K*c.etaBar*dgamma;
        for (int a = 0; a < 6; ++a) sigma[a] = scale*v.s[a];
        for (int a = 0; a < 3; ++a) sigma[a] -= pNew;
    }
    else
    {
        // The cone return would cross the axis: the trial lies beyond the
        // apex (tension), return to the apex. This is the tension cut-off.
        const Real pApex = -c.xi*c.cohesion/c.eta;
        for (int a = 0; a < 6; ++a) sigma[a] = 0;
        for (int a = 0; a < 3; ++a) sigma[a] = -pApex;
    }

    // Plastic strain increment = elastic compliance of the stress correction.
    Real dStrain[6];
    for (int a = 0; a < 6; ++a) dStrain[a] = trial[a] - sigma[a];
    const Real volumetric = tensor::trace(dStrain)/(9.0*K);
    tensor::makeDeviatoric(dStrain);
    for (int a = 0; a < 6; ++a) dStrain[a] /= 2.0*G;
    for (int a = 0; a < 3; ++a) dStrain[a] += volumetric;
    return std::sqrt(2.0/3.0*tensor::ddot(dStrain, dStrain));
}

MPM_HOST_DEVICE inline void druckerPragerStress
(
    const DruckerPragerParams& c, const PointKinematics& k, PointStress& s
)
{
    if (k.solidFraction < c.alphaContact)
    {
        for (int a = 0; a < 6; ++a) s.sigma[a] = 0;
        return;
    }
    jaumannElasticUpdate(c.el, k.L, k.dt, s.sigma);
    const Real dEqPlastic = druckerPragerReturnMap(c, s.sigma);
    if (s.eqPlasticStrain) *s.eqPlasticStrain += dEqPlastic;
}

} // namespace mpm

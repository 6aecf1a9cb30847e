// Per-point stress update of MuIRheology (host and device): disconnected
// state, Jaumann-rate elastic trial, tension cut-off and the closed-form
// return to tau = mu(I) p (see muIRheology.hpp for the model).
#pragma once
#include "isotropicElasticity.hpp"
#include "pointState.hpp"
#include <cmath>

namespace mpm {

struct MuIRheologyParams
{
    IsotropicElasticity el;
    Real rho0;            // reference density of the law
    Real muS, mu2, I0;
    Real d;               // grain diameter
    Real rhoS;            // grain density
    Real alphaCritical;   // grain volume fraction below which it is stress-free
};

// Projects an elastic trial stress (p > 0) onto tau = mu(I) p over a step
// dt; returns the equivalent plastic strain increment.
MPM_HOST_DEVICE inline Real muIReturnToFlowSurface(const MuIRheologyParams& c, Real* sigma, Real dt)
{
    Real s[6];
    tensor::copy6(sigma, s);
    const Real p = -tensor::trace(s)/3.0;
    tensor::makeDeviatoric(s);
    const Real tau = std::sqrt(0.5*tensor::ddot(s, s));
    const Real S0 = tau - c.muS*p;
    if (S0 <= 0) return 0;

    const Real G = c.el.mu;
    const Real dMu = c.mu2 - c.muS;
    // Stress relaxed per unit inertial number of plastic flow over dt.
    const Real alpha = G*dt*std::sqrt(p/c.rhoS)/c.d;
    Real tauNew;
    if (alpha > 0)
    {
        const Real B = alpha*c.I0 + dMu*p - S0;
        const Real root = std::sqrt(B*B + 4.0*alpha*S0*c.I0);
        // The positive root without cancellation for either sign of B.
        const Real I = B >= 0 ? 2.0*S0*c.I0/(B + root) : (root - B)/(2.0*alpha);
        tauNew = tau - alpha*I;
    }
    else
    {
        // dt = 0: any finite plastic rate relaxes nothing; the stress may
        // stand up to the infinite-rate limit mu2 p (std::min's order).
        const Real limit = c.mu2*p;
        tauNew = limit < tau ? limit : tau;
    }

    const Real scale = tauNew/tau;
    for (int a = 0; a < 6; ++a) sigma[a] = scale*s[a];
    for (int a = 0; a < 3; ++a) sigma[a] -= p;
    // gammaDotP dt = (tau - tauNew)/G
    return (tau - tauNew)/(G*std::sqrt(3.0));
}

MPM_HOST_DEVICE inline void muIRheologyStress
(
    const MuIRheologyParams& c, const PointKinematics& k, PointStress& s
)
{
    // Grain volume fraction: solidFraction is mass/(rho0 V).
    const Real phi = k.solidFraction*c.rho0/c.rhoS;
    const bool disconnected = phi < c.alphaCritical;
    if (!disconnected) jaumannElasticUpdate(c.el, k.L, k.dt, s.sigma);
    const Real p = -tensor::trace(s.sigma)/3.0;
    if (disconnected || p <= 0)
    {
        for (int a = 0; a < 6; ++a) s.sigma[a] = 0;
        return;
    }
    const Real dEqPlastic = muIReturnToFlowSurface(c, s.sigma, k.dt);
    if (s.eqPlasticStrain) *s.eqPlasticStrain += dEqPlastic;
}

} // namespace mpm

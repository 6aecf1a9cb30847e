#include "muIRheology.hpp"
#include "tensorOps.hpp"
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mpm {

Real MuIRheology::defaultMuS() { return std::tan(20.9*M_PI/180.0); }
Real MuIRheology::defaultMu2() { return std::tan(32.76*M_PI/180.0); }

MuIRheology::MuIRheology(Real rho, Real E, Real nu, Real muS, Real mu2, Real I0, Real d,
                         Real rhoS, Real alphaCritical)
:
    IsotropicElasticLaw(rho, E, nu),
    muS_(muS), mu2_(mu2), I0_(I0), d_(d), rhoS_(rhoS), alphaCritical_(alphaCritical)
{
    if (!(mu2 >= muS))
    {
        std::ostringstream msg;
        msg << "constitutive law 'muIRheology': parameter 'mu2' (friction at large I) = "
            << mu2 << " must not be below 'muS' (friction at I -> 0) = " << muS;
        throw std::invalid_argument(msg.str());
    }
}

std::unique_ptr<ConstitutiveLaw> MuIRheology::create(const Coefficients& c)
{
    return std::make_unique<MuIRheology>
    (
        c.at("rho"), c.at("E"), c.at("nu"), c.at("muS"), c.at("mu2"), c.at("I0"), c.at("d"),
        c.at("rhoS"), c.at("alphaCritical")
    );
}

Real MuIRheology::returnToFlowSurface(Real* sigma, Real dt) const
{
    using namespace tensor;
    Sym6 s{sigma[0], sigma[1], sigma[2], sigma[3], sigma[4], sigma[5]};
    const Real p = -trace(s.data())/3.0;
    makeDeviatoric(s.data());
    const Real tau = std::sqrt(0.5*ddot(s.data(), s.data()));
    const Real S0 = tau - muS_*p;
    if (S0 <= 0) return 0;

    const Real G = el_.mu;
    const Real dMu = mu2_ - muS_;
    // Stress relaxed per unit inertial number of plastic flow over dt.
    const Real alpha = G*dt*std::sqrt(p/rhoS_)/d_;
    Real tauNew;
    if (alpha > 0)
    {
        const Real B = alpha*I0_ + dMu*p - S0;
        const Real root = std::sqrt(B*B + 4.0*alpha*S0*I0_);
        // The positive root without cancellation for either sign of B.
        const Real I = B >= 0 ? 2.0*S0*I0_/(B + root) : (root - B)/(2.0*alpha);
        tauNew = tau - alpha*I;
    }
    else
    {
        // dt = 0: any finite plastic rate relaxes nothing; the stress may
        // stand up to the infinite-rate limit mu2 p.
        tauNew = std::min(tau, mu2_*p);
    }

    const Real scale = tauNew/tau;
    for (int a = 0; a < 6; ++a) sigma[a] = scale*s[a];
    for (int a = 0; a < 3; ++a) sigma[a] -= p;
    // gammaDotP dt = (tau - tauNew)/G
    return (tau - tauNew)/(G*std::sqrt(3.0));
}

void MuIRheology::updateStress(const PointKinematics& k, PointStress& s) const
{
    // Grain volume fraction: solidFraction is mass/(rho0 V).
    const Real phi = k.solidFraction*rho0_/rhoS_;
    const bool disconnected = phi < alphaCritical_;
    if (!disconnected) jaumannElasticUpdate(el_, k.L, k.dt, s.sigma);
    const Real p = -tensor::trace(s.sigma)/3.0;
    if (disconnected || p <= 0)
    {
        for (int a = 0; a < 6; ++a) s.sigma[a] = 0;
        return;
    }
    const Real dEqPlastic = returnToFlowSurface(s.sigma, k.dt);
    if (s.eqPlasticStrain) *s.eqPlasticStrain += dEqPlastic;
}

Real MuIRheology::waveSpeed(Real) const
{
    // Elastic wave speed: plastic flow only softens the material.
    return std::sqrt(el_.pWaveModulus()/rho0_);
}

Real MuIRheology::storedEnergy(const Real* sigma, const Real* F) const
{
    return el_.complementaryEnergy(sigma)*tensor::det(F);
}

} // namespace mpm

#include "muIRheology.hpp"
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

LawParams MuIRheology::params() const
{
    LawParams p = baseParams(LawType::muIRheology);
    p.muIRheology = kernelParams();
    return p;
}

void MuIRheology::updateStress(const PointKinematics& k, PointStress& s) const
{
    muIRheologyStress(kernelParams(), k, s);
}

Real MuIRheology::storedEnergy(const Real* sigma, const Real* F) const
{
    return el_.complementaryEnergy(sigma)*tensor::det(F);
}

} // namespace mpm

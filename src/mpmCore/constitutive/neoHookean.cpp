#include "neoHookean.hpp"
#include "tensorOps.hpp"
#include <algorithm>
#include <cmath>

namespace mpm {

NeoHookean::NeoHookean(Real rho, Real E, Real nu)
:
    IsotropicElasticLaw(rho, E, nu)
{}

std::unique_ptr<ConstitutiveLaw> NeoHookean::create(const Coefficients& c)
{
    return std::make_unique<NeoHookean>(c.at("rho"), c.at("E"), c.at("nu"));
}

LawParams NeoHookean::params() const
{
    LawParams p = baseParams(LawType::neoHookean);
    p.neoHookean = {el_};
    return p;
}

void NeoHookean::updateStress(const PointKinematics& k, PointStress& s) const
{
    neoHookeanStress({el_}, k, s);
}

Real NeoHookean::storedEnergy(const Real*, const Real* F) const
{
    Real I1 = 0;
    for (int e = 0; e < 9; ++e) I1 += F[e]*F[e];
    const Real lnJ = std::log(tensor::det(F));
    return 0.5*el_.mu*(I1 - 3.0) - el_.mu*lnJ + 0.5*el_.lambda*lnJ*lnJ;
}

} // namespace mpm

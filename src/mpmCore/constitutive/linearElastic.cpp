#include "linearElastic.hpp"
#include "tensorOps.hpp"
#include <cmath>

namespace mpm {

LinearElastic::LinearElastic(Real rho, Real E, Real nu)
:
    IsotropicElasticLaw(rho, E, nu)
{}

std::unique_ptr<ConstitutiveLaw> LinearElastic::create(const Coefficients& c)
{
    return std::make_unique<LinearElastic>(c.at("rho"), c.at("E"), c.at("nu"));
}

LawParams LinearElastic::params() const
{
    LawParams p = baseParams(LawType::linearElastic);
    p.linearElastic = {el_};
    return p;
}

void LinearElastic::updateStress(const PointKinematics& k, PointStress& s) const
{
    linearElasticStress({el_}, k, s);
}

Real LinearElastic::storedEnergy(const Real* sigma, const Real* F) const
{
    return el_.complementaryEnergy(sigma)*tensor::det(F);
}

} // namespace mpm

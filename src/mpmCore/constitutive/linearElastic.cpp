#include "linearElastic.hpp"
#include "tensorOps.hpp"
#include <cmath>

namespace mpm {

IsotropicElasticity IsotropicElasticity::fromYoungPoisson(Real E, Real nu)
{
    return {E*nu/((1.0 + nu)*(1.0 - 2.0*nu)), E/(2.0*(1.0 + nu))};
}

void jaumannElasticUpdate(const IsotropicElasticity& el, const Real* L, Real dt, Real* sigma)
{
    using namespace tensor;
    const Sym6 D = symPart(L);
    const Mat3 W = skewPart(L);
    const Mat3 S = symToFull(sigma);

    // Co-rotational terms from sigma_n: W S - S W is symmetric because W is
    // skew and S symmetric.
    const Mat3 WS = mul(W, S);
    const Mat3 SW = mul(S, W);
    Mat3 spin;
    for (int a = 0; a < 9; ++a) spin[a] = WS[a] - SW[a];
    Sym6 rotation;
    storeSym(spin, rotation.data());

    const Real lambdaTrD = el.lambda*trace(D.data());
    for (int a = 0; a < 6; ++a)
    {
        const Real elastic = 2.0*el.mu*D[a] + (a < 3 ? lambdaTrD : 0.0);
        sigma[a] += dt*(elastic + rotation[a]);
    }
}

LinearElastic::LinearElastic(Real rho, Real E, Real nu)
:
    IsotropicElasticLaw(rho, E, nu)
{}

std::unique_ptr<ConstitutiveLaw> LinearElastic::create(const Coefficients& c)
{
    return std::make_unique<LinearElastic>(c.at("rho"), c.at("E"), c.at("nu"));
}

void LinearElastic::updateStress(const PointKinematics& k, PointStress& s) const
{
    jaumannElasticUpdate(el_, k.L, k.dt, s.sigma);
}

Real LinearElastic::waveSpeed(Real) const
{
    return std::sqrt(el_.pWaveModulus()/rho0_);
}

Real IsotropicElasticity::complementaryEnergy(const Real* s) const
{
    const Real tr = s[XX] + s[YY] + s[ZZ];
    const Real ss = s[XX]*s[XX] + s[YY]*s[YY] + s[ZZ]*s[ZZ]
                  + 2.0*(s[XY]*s[XY] + s[YZ]*s[YZ] + s[XZ]*s[XZ]);
    return (ss - lambda/(3.0*lambda + 2.0*mu)*tr*tr)/(4.0*mu);
}

Real LinearElastic::storedEnergy(const Real* sigma, const Real* F) const
{
    return el_.complementaryEnergy(sigma)*tensor::det(F);
}

} // namespace mpm

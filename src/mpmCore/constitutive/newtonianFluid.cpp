#include "newtonianFluid.hpp"
#include "tensorOps.hpp"
#include <cmath>
#include <limits>

namespace mpm {

NewtonianFluid::NewtonianFluid(Real rho, Real K, Real gamma, Real mu)
:
    K_(K), gamma_(gamma), mu_(mu)
{
    rho0_ = rho;
}

std::unique_ptr<ConstitutiveLaw> NewtonianFluid::create(const Coefficients& c)
{
    return std::make_unique<NewtonianFluid>(c.at("rho"), c.at("K"), c.at("gamma"), c.at("mu"));
}

Real NewtonianFluid::pressure(Real J) const
{
    return newtonianFluidPressure(kernelParams(), J);
}

LawParams NewtonianFluid::params() const
{
    LawParams p = baseParams(LawType::newtonianFluid);
    p.newtonianFluid = kernelParams();
    return p;
}

void NewtonianFluid::updateStress(const PointKinematics& k, PointStress& s) const
{
    newtonianFluidStress(kernelParams(), k, s);
}

Real NewtonianFluid::maxStableDt(Real h) const
{
    if (mu_ <= 0) return std::numeric_limits<Real>::infinity();
    return rho0_*h*h/(8.0*mu_);
}

Real NewtonianFluid::storedEnergy(const Real*, const Real* F) const
{
    const Real J = tensor::det(F);
    if (std::abs(gamma_ - 1.0) < 1e-9) return K_*(J - 1.0 - std::log(J));
    return K_*((std::pow(J, 1.0 - gamma_) - 1.0)/(gamma_ - 1.0) + J - 1.0);
}

} // namespace mpm

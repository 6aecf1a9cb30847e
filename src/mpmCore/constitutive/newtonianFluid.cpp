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
    return K_*(std::pow(J, -gamma_) - 1.0);
}

void NewtonianFluid::updateStress(const PointKinematics& k, PointStress& s) const
{
    using namespace tensor;
    Sym6 devD = symPart(k.L);
    makeDeviatoric(devD.data());
    const Real p = pressure(det(k.Fnew));
    for (int a = 0; a < 6; ++a) s.sigma[a] = 2.0*mu_*devD[a];
    for (int a = 0; a < 3; ++a) s.sigma[a] -= p;
}

Real NewtonianFluid::waveSpeed(Real J) const
{
    return std::sqrt(gamma_*K_/rho0_*std::pow(J, 1.0 - gamma_));
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

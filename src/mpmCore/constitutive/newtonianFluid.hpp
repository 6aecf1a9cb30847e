// Weakly compressible Newtonian fluid.
//
//   p     = K (J^-gamma - 1)                 (Tait-type equation of state)
//   sigma = -p I + 2 mu dev(D)
//
// with J = det F_new (so rho = rho0/J) and D the symmetric part of L.
// Note: with this form the bulk modulus at rest is rho dp/drho = gamma*K,
// i.e. K is the Tait coefficient (often called B), not the bulk modulus.
// Tension (J > 1, p < 0) is not clipped.
#pragma once
#include "constitutiveLaw.hpp"
#include "newtonianFluidKernel.hpp"

namespace mpm {

class NewtonianFluid : public ConstitutiveLaw
{
public:
    NewtonianFluid(Real rho, Real K, Real gamma, Real mu);
    static std::unique_ptr<ConstitutiveLaw> create(const Coefficients& c);

    const char* typeName() const override { return "newtonianFluid"; }
    void updateStress(const PointKinematics& k, PointStress& s) const override;
    LawParams params() const override;

    Real pressure(Real J) const;

    // Sound speed c^2 = dp/drho = (gamma K/rho0) J^(1 - gamma): stiffens as
    // the fluid is compressed (J < 1).

    // Explicit viscous bound dt <= rho0 h^2/(8 mu) (+inf for mu = 0).
    // Why 1/8: 2 mu dev(D) makes longitudinal modes diffuse with kinematic
    // viscosity (4/3) mu/rho; the largest eigenvalue of the 3D grid
    // Laplacian is 12/h^2, and forward Euler needs dt*lambda_max <= 2, so
    // dt <= 2 rho h^2/((4/3) mu 12) = rho h^2/(8 mu).
    Real maxStableDt(Real h) const override;

    // Compression energy -int_1^J p dJ = K ((J^(1-gamma) - 1)/(gamma - 1) + J - 1)
    Real storedEnergy(const Real* sigma, const Real* F) const override;

private:
    NewtonianFluidParams kernelParams() const { return {K_, gamma_, mu_}; }

    Real K_, gamma_, mu_;
};

} // namespace mpm

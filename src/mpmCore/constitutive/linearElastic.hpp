// Isotropic linear (hypo)elasticity.
//
// The stress is integrated in rate form with the Jaumann (co-rotational)
// rate, which makes the update objective: a rigid-body spin rotates the
// stress instead of creating spurious stress,
//
//   sigma_{n+1} = sigma_n + dt*(C:D + W sigma_n - sigma_n W),
//   C:D = lambda tr(D) I + 2 mu D,
//
// with D, W the symmetric and skew parts of the velocity gradient L. The
// elastic trial of the plasticity models reuses jaumannElasticUpdate()
// (isotropicElasticity.hpp); the per-point update is linearElasticKernel.hpp.
#pragma once
#include "constitutiveLaw.hpp"
#include "isotropicElasticity.hpp"
#include "linearElasticKernel.hpp"

namespace mpm {

// Base of the laws whose elasticity is isotropic, given by rho, E and nu.
class IsotropicElasticLaw : public ConstitutiveLaw
{
public:
    const IsotropicElasticity& elasticity() const { return el_; }

protected:
    IsotropicElasticLaw(Real rho, Real E, Real nu)
    :
        el_(IsotropicElasticity::fromYoungPoisson(E, nu))
    {
        rho0_ = rho;
    }

    IsotropicElasticity el_;
};

class LinearElastic : public IsotropicElasticLaw
{
public:
    LinearElastic(Real rho, Real E, Real nu);
    static std::unique_ptr<ConstitutiveLaw> create(const Coefficients& c);

    const char* typeName() const override { return "linearElastic"; }
    void updateStress(const PointKinematics& k, PointStress& s) const override;
    LawParams params() const override;
    // Dilatational wave speed sqrt((lambda + 2 mu)/rho0); J is ignored
    // because the hypoelastic tangent does not depend on the deformation.

    Real storedEnergy(const Real* sigma, const Real* F) const override;
};

} // namespace mpm

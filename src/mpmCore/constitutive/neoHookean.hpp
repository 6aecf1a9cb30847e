// Compressible neo-Hookean hyperelasticity.
//
//   sigma = (mu/J)(B - I) + (lambda ln J / J) I,   B = F F^T,  J = det F,
//
// evaluated from F_new only (path independent, objective by construction
// since B -> R B R^T under F -> R F). Lame coefficients from E and nu as in
// linear elasticity, so the two laws agree for small strains. An inverted
// point (J <= 0) gives a non-finite stress, which the step's checks catch.
#pragma once
#include "linearElastic.hpp"
#include "neoHookeanKernel.hpp"

namespace mpm {

class NeoHookean : public IsotropicElasticLaw
{
public:
    NeoHookean(Real rho, Real E, Real nu);
    static std::unique_ptr<ConstitutiveLaw> create(const Coefficients& c);

    const char* typeName() const override { return "neoHookean"; }
    void updateStress(const PointKinematics& k, PointStress& s) const override;
    LawParams params() const override;

    // Longitudinal speed from the spatial tangent moduli at volume ratio J:
    // c^2 = (lambda + 2(mu - lambda ln J))/rho0 (the 1/J of the tangent
    // cancels the current density rho0/J). Never below the reference speed,
    // so the CFL bound is not relaxed in tension.

    // W = mu/2 (tr(F F^T) - 3) - mu ln J + lambda/2 (ln J)^2
    Real storedEnergy(const Real* sigma, const Real* F) const override;
};

} // namespace mpm

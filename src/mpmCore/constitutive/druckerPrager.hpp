// Drucker-Prager elasto-plasticity for granular materials (perfectly
// plastic, non-associated).
//
// Invariants: p = -tr(sigma)/3 (positive in compression), q = sqrt(3 J2).
// Yield function and plastic potential:
//
//   f = q - eta p - xi c      <= 0
//   g = q - etaBar p
//
// (compression raises the admissible q, hence "- eta p" with this sign of p).
// Coefficients match Mohr-Coulomb under PLANE STRAIN (de Souza Neto, Peric &
// Owen, Computational Methods for Plasticity, sec. 6.4.1, rewritten for q
// instead of sqrt(J2), i.e. times sqrt(3)):
//
//   eta    = 3 sqrt(3) tan(phi) / sqrt(9 + 12 tan^2(phi))
//   xi     = 3 sqrt(3)          / sqrt(9 + 12 tan^2(phi))
//   etaBar = 3 sqrt(3) tan(psi) / sqrt(9 + 12 tan^2(psi))
//
// Plane strain is chosen because the usual granular benchmarks (column
// collapse, slopes, footings) are plane-strain problems; with these values
// the plane-strain collapse loads equal the Mohr-Coulomb ones.
//
// Update: Jaumann-rate elastic trial (shared with LinearElastic), then a
// closed-form return map: onto the cone along C:dg/dsigma, or, when that
// would overshoot the axis q = 0 (tension), to the apex
// sigma = (xi c/eta) I, which acts as the tension cut-off (stress free for
// cohesionless material). The equivalent plastic strain grows by
// sqrt(2/3 de_p:de_p) with de_p = C^-1:(sigma_trial - sigma_new).
#pragma once
#include "druckerPragerKernel.hpp"
#include "linearElastic.hpp"

namespace mpm {

class DruckerPrager : public IsotropicElasticLaw
{
public:
    // Angles in degrees; requires 0 <= psi <= phi < 90 and c >= 0.
    DruckerPrager(Real rho, Real E, Real nu, Real phiDeg, Real c, Real psiDeg,
                  Real alphaContact = 0);
    static std::unique_ptr<ConstitutiveLaw> create(const Coefficients& c);

    const char* typeName() const override { return "druckerPrager"; }
    void updateStress(const PointKinematics& k, PointStress& s) const override;
    LawParams params() const override;

    // f(sigma) = q - eta p - xi c, in stress units (<= 0 is admissible).
    Real yieldFunction(const Real* sigma) const;

    Real eta() const { return eta_; }
    // tau/sigma_n = eta/sqrt(3) in simple shear (the plane-strain match:
    // 3 tan(phi)/sqrt(9 + 12 tan^2(phi))); infinite with cohesion
    Real shearStrengthRatio() const override;
    std::string note() const override;

    // The friction angle of the plane-strain match that mobilises mu in
    // simple shear: tan(phi) = 3 mu / sqrt(9 - 12 mu^2), mu < sqrt(3)/2
    static Real phiForSimpleShear(Real mu);
    Real xi() const { return xi_; }
    Real etaBar() const { return etaBar_; }
    Real storedEnergy(const Real* sigma, const Real* F) const override;

    // Plane-strain Mohr-Coulomb match, eta(phi) (= xi(phi) tan(phi)).
    static Real planeStrainEta(Real angleDeg);
    static Real planeStrainXi(Real angleDeg);

private:
    DruckerPragerParams kernelParams() const;

    Real phiDeg_;
    bool givenAsMu_ = false;
    Real cohesion_;
    Real eta_, xi_, etaBar_;
    // Packing below which the grains are not in contact: the skeleton is
    // stress-free (expanded beds, suspensions); stress builds again from
    // zero once it is compacted past it. 0: always in contact.
    Real alphaContact_;
};

} // namespace mpm

// mu(I) rheology of dense granular flows (Jop, Forterre & Pouliquen 2006,
// Nature 441), with the elastic predictor and the disconnected state of
// Dunatunga & Kamrin (2015, J. Fluid Mech. 779).
//
// Invariants: p = -tr(sigma)/3 (compression positive), the equivalent shear
// stress tau = sqrt(s:s/2) (s = dev sigma) and the equivalent shear rate
// gammaDot = sqrt(2 D':D'), both equal to the xy components in simple shear.
// The flowing material satisfies
//
//   tau = mu(I) p,   mu(I) = muS + (mu2 - muS)/(I0/I + 1),
//   I   = gammaDot d / sqrt(p/rhoS)                  (inertial number)
//
// and below tau = muS p it is elastic (E, nu): a rate-dependent
// Drucker-Prager-like yield surface without dilatancy.
//
// Update per point and step:
//  1. Disconnected: the grain volume fraction phi = mass/(rhoS V) is below
//     alphaCritical, the grains do not touch: sigma = 0. A re-compacting
//     loose region carries no stress until it is back at critical packing.
//  2. Jaumann-rate elastic trial (shared with LinearElastic).
//  3. Tension (p_trial <= 0): sigma = 0, grains separate freely.
//  4. tau_trial <= muS p: elastic, accepted.
//  5. Otherwise the deviatoric stress is reduced along its own direction by
//     a plastic shear rate gammaDotP over the step,
//        tau = tau_trial - G dt gammaDotP,   p unchanged (isochoric flow),
//     with gammaDotP chosen such that tau = mu(I(gammaDotP)) p. With
//     I = gammaDotP d sqrt(rhoS/p) and alpha = G dt sqrt(p/rhoS)/d this is
//     the quadratic (Dunatunga & Kamrin's closed form)
//        alpha I^2 + (alpha I0 + (mu2 - muS) p - S0) I - S0 I0 = 0,
//        S0 = tau_trial - muS p > 0,
//     with exactly one positive root, taken in the cancellation-free form.
//     The equivalent plastic strain grows by gammaDotP dt/sqrt(3), the
//     sqrt(2/3 de_p:de_p) measure of DruckerPrager.
#pragma once
#include "linearElastic.hpp"
#include "muIRheologyKernel.hpp"

namespace mpm {

class MuIRheology : public IsotropicElasticLaw
{
public:
    // Requires mu2 >= muS (checked; ranges are checked by makeLaw).
    MuIRheology(Real rho, Real E, Real nu, Real muS, Real mu2, Real I0, Real d, Real rhoS,
                Real alphaCritical);
    static std::unique_ptr<ConstitutiveLaw> create(const Coefficients& c);

    const char* typeName() const override { return "muIRheology"; }
    void updateStress(const PointKinematics& k, PointStress& s) const override;
    LawParams params() const override;
    Real storedEnergy(const Real* sigma, const Real* F) const override;

    // Glass beads of Jop, Forterre & Pouliquen (2006), Fig. 1: the defaults.
    static Real defaultMuS();    // tan(20.9 deg)
    static Real defaultMu2();    // tan(32.76 deg)

    Real muS() const { return muS_; }
    Real mu2() const { return mu2_; }
    // The largest friction the rheology reaches, at high inertial number
    Real shearStrengthRatio() const override { return mu2_; }
    Real I0() const { return I0_; }
    Real grainDiameter() const { return d_; }
    Real grainDensity() const { return rhoS_; }

private:
    MuIRheologyParams kernelParams() const
    {
        return {el_, rho0_, muS_, mu2_, I0_, d_, rhoS_, alphaCritical_};
    }

    Real muS_, mu2_, I0_, d_, rhoS_, alphaCritical_;
};

} // namespace mpm

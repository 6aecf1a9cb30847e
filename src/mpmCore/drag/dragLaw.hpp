// Fluid-particle drag laws in the core (plain C++17, no OpenFOAM).
//
// A drag law returns the momentum-exchange coefficient beta [kg/(m^3 s)]
// per unit MIXTURE volume such that the drag force per unit mixture volume is
//
//     on the solid:  F_s =  beta (U_f - U_s)
//     on the fluid:       -beta (U_f - U_s)
//
// Pressure-term convention ("model A", Gidaspow 1994; Zhou et al. 2010):
//
//     fluid:  d(alphaF rhoF U_f)/dt + ... = -alphaF grad p + ... - F_s
//     solid:  d(alphaS rhoS U_s)/dt + ... = -alphaS grad p + ... + F_s
//
// i.e. the solid receives the (generalised) buoyancy -alphaS grad p
// separately, and beta is the DRAG-ONLY coefficient: it does not contain the
// pressure-gradient part of the total fluid-particle force. In uniform
// steady flow through a bed (-grad p = beta |U_f - U_s| / alphaF) the total
// force the fluid exerts on the solid is beta |U_f - U_s| / alphaF, so a
// correlation given for the total force is converted by beta = alphaF *
// beta_total; see docs/dragLaws.md for each law's normalisation.
//
// Inputs per evaluation: fluid volume fraction alphaF (alphaS = 1 - alphaF),
// slip speed |U_f - U_s| >= 0 [m/s], fluid density rhoF [kg/m^3] and
// dynamic viscosity muF [Pa s]. The grain diameter d [m] is a parameter of
// the law. alphaF is clamped to [alphaFMin, 1] before evaluation (alphaFMin
// defaults to 0.2, below any sphere packing, so it only catches unphysical
// projected fractions such as alphaS > 1 from overlapping particle volumes).
// No allocation, no exceptions per call; slip = 0 gives the finite Re -> 0
// limit.
#pragma once
#include "../common/modelRegistry.hpp"
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace mpm {

// Helpers shared by the laws (and usable by the OpenFOAM layer).
namespace drag {

// Reynolds number alphaF rhoF |Ur| d / muF. Pass alphaF = 1 for the
// single-particle Re_p = rhoF |Ur| d / muF; with alphaF < 1 it is the Re of
// the superficial slip velocity alphaF |Ur| (Gidaspow, Wen-Yu, Di Felice,
// Beetstra).
inline Real reynolds(Real alphaF, Real slip, Real rhoF, Real muF, Real d)
{
    return alphaF*rhoF*slip*d/muF;
}

// Cd*Re of a single sphere, Schiller & Naumann (1933):
// Cd = 24/Re (1 + 0.15 Re^0.687) for Re < 1000, 0.44 above. Returned as the
// product Cd*Re so that it stays finite (= 24) at Re = 0.
inline Real cdReSchillerNaumann(Real Re)
{
    return Re < 1000 ? 24*(1 + 0.15*std::pow(Re, 0.687)) : 0.44*Re;
}

// Cd*Re of a single sphere, Dalla Valle (1948), as used by Di Felice (1994):
// Cd = (0.63 + 4.8/sqrt(Re))^2, so Cd*Re = (0.63 sqrt(Re) + 4.8)^2
// (-> 23.04, not 24, at Re = 0).
inline Real cdReDallaValle(Real Re)
{
    const Real s = 0.63*std::sqrt(Re) + 4.8;
    return s*s;
}

// Stokes coefficient of a dilute suspension, 18 muF alphaS / d^2: the
// per-volume form of 3 pi muF d |Ur| on alphaS/(pi d^3/6) spheres.
inline Real stokesBeta(Real alphaS, Real muF, Real d)
{
    return 18*muF*alphaS/(d*d);
}

// Particle relaxation time tau = alphaS rhoS / beta [s]: the e-folding time
// of the slip of a grain of density rhoS in a fluid at rest, from
// alphaS rhoS dU_s/dt = beta (U_f - U_s) (no added mass; beta frozen).
// In the Stokes regime it is the classical rhoS d^2/(18 muF). +inf for
// beta = 0. An explicit update of the drag needs dt < 2 tau (dt < tau for
// no overshoot), which is why the coupling is normally implicit in beta.
inline Real relaxationTime(Real alphaS, Real rhoS, Real beta)
{
    return beta > 0 ? alphaS*rhoS/beta : std::numeric_limits<Real>::infinity();
}

} // namespace drag

// A correlation beta(alphaF, slip, rhoF, muF, d); alphaF already clamped.
using DragFormula = Real (*)(Real alphaF, Real slip, Real rhoF, Real muF, Real d);

// A selected drag law: one correlation (dragLaws.hpp) and its coefficients.
class DragLaw
{
public:
    // Throws std::invalid_argument unless d > 0 and 0 < alphaFMin < 1.
    DragLaw(const char* name, DragFormula formula, Real d, Real alphaFMin);

    const char* typeName() const { return name_; }

    // beta [kg/(m^3 s)] at one point (alphaF clamped to [alphaFMin, 1]).
    Real beta(Real alphaF, Real slip, Real rhoF, Real muF) const
    {
        const Real aF = std::min(std::max(alphaF, alphaFMin_), Real(1));
        return formula_(aF, slip, rhoF, muF, d_);
    }

    // SoA batch for a fluid of uniform rhoF, muF: betaOut[i] = beta(alphaF[i],
    // slip[i], rhoF, muF) for i < n. betaOut may alias neither input. The
    // caller parallelises (the loop is independent per i).
    void beta(std::size_t n, const Real* alphaF, const Real* slip, Real rhoF, Real muF,
              Real* betaOut) const;

    Real d() const { return d_; }
    Real alphaFMin() const { return alphaFMin_; }

private:
    const char* name_;
    DragFormula formula_;
    Real d_;
    Real alphaFMin_;
};

// Registry, same pattern as the constitutive laws (constitutiveLaw.hpp):
// the OpenFOAM layer lists valid names and parameters from this table and
// turns std::invalid_argument into a FatalIOError.
using DragLawInfo = ModelInfo<DragLaw>;

const std::vector<DragLawInfo>& availableDragLaws();
const DragLawInfo* findDragLaw(const std::string& name);

// Throws std::invalid_argument naming the law and parameter if a required
// parameter is missing, a value is out of range or a name is not one of the
// law's parameters; for an unknown law the message lists the valid names.
// Optional parameters absent from c take their default.
std::unique_ptr<DragLaw> makeDragLaw(const std::string& name, const Coefficients& c);

} // namespace mpm

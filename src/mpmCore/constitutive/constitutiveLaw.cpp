// The law registry: one table of law names, summaries, parameters (with
// units, defaults and ranges) and factories. The OpenFOAM layer lists valid
// choices and reads coefficients from this table, so adding a law here is
// all that is needed to make it selectable.
#include "constitutiveLaw.hpp"
#include "dilute.hpp"
#include "druckerPrager.hpp"
#include "linearElastic.hpp"
#include "muIRheology.hpp"
#include "neoHookean.hpp"
#include "newtonianFluid.hpp"
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mpm {

Real ConstitutiveLaw::shearStrengthRatio() const
{
    return std::numeric_limits<Real>::infinity();
}

Real ConstitutiveLaw::maxStableDt(Real) const
{
    return std::numeric_limits<Real>::infinity();
}

namespace {

constexpr Real inf = std::numeric_limits<Real>::infinity();

Parameter required(const std::string& name, const std::string& description,
                   Real minValue, Real maxValue, bool minExclusive, bool maxExclusive)
{
    Parameter p{name, description, true, 0.0, minValue, maxValue};
    p.minExclusive = minExclusive;
    p.maxExclusive = maxExclusive;
    return p;
}

Parameter optional(const std::string& name, const std::string& description, Real defaultValue,
                   Real minValue, Real maxValue, bool minExclusive, bool maxExclusive)
{
    Parameter p = required(name, description, minValue, maxValue, minExclusive, maxExclusive);
    p.required = false;
    p.defaultValue = defaultValue;
    return p;
}

Parameter density() { return required("rho", "reference density [kg/m^3]", 0, inf, true, false); }
Parameter youngModulus() { return required("E", "Young's modulus [Pa]", 0, inf, true, false); }
Parameter poissonRatio() { return required("nu", "Poisson's ratio [-]", 0, 0.5, false, true); }

std::vector<LawInfo> buildRegistry()
{
    std::vector<LawInfo> laws;
    laws.push_back
    ({
        "linearElastic",
        "hypoelastic isotropic solid, objective Jaumann stress rate",
        {density(), youngModulus(), poissonRatio()},
        &LinearElastic::create
    });
    laws.push_back
    ({
        "neoHookean",
        "compressible neo-Hookean hyperelastic solid",
        {density(), youngModulus(), poissonRatio()},
        &NeoHookean::create
    });
    laws.push_back
    ({
        "newtonianFluid",
        "weakly compressible Newtonian fluid, p = K (J^-gamma - 1)",
        {
            density(),
            required("K", "Tait pressure coefficient [Pa] (bulk modulus at rest is gamma*K)",
                     0, inf, true, false),
            optional("gamma", "Tait exponent [-]", 7.0, 0, inf, true, false),
            required("mu", "dynamic viscosity [Pa s]", 0, inf, false, false)
        },
        &NewtonianFluid::create
    });
    laws.push_back
    ({
        "druckerPrager",
        "granular Drucker-Prager plasticity (plane-strain Mohr-Coulomb match), "
        "non-associated, tension cut-off at the apex",
        {
            density(), youngModulus(), poissonRatio(),
            // The friction as an angle (plane-strain Mohr-Coulomb match) or
            // as the coefficient it mobilises in simple shear: one of them
            optional("phi", "friction angle [deg], matched to Mohr-Coulomb in plane strain "
                     "(or give mu)", std::nan(""), 0, 90, false, true),
            optional("mu", "friction coefficient mobilised in simple shear, tau <= mu p, as "
                     "granular-flow codes write it (instead of phi) [-]", std::nan(""), 0,
                     std::sqrt(3.0)/2, false, true),
            optional("c", "cohesion [Pa]", 0.0, 0, inf, false, false),
            optional("psi", "dilatancy angle [deg], at most phi", 0.0, 0, 90, false, true),
            optional("alphaContact", "solid fraction below which the grains are out of contact "
                     "and stress-free (0: always in contact) [-]", 0.0, 0, 1, false, true)
        },
        &DruckerPrager::create
    });
    laws.push_back
    ({
        "muIRheology",
        "dense granular flow, mu(I) rheology (Jop, Forterre & Pouliquen 2006) with an "
        "elastic predictor; stress-free in tension and below critical packing",
        {
            density(), youngModulus(), poissonRatio(),
            // Glass beads of Jop, Forterre & Pouliquen (2006)
            optional("muS", "friction coefficient at I -> 0 (static) [-]",
                     MuIRheology::defaultMuS(), 0, inf, false, false),
            optional("mu2", "friction coefficient at I -> infinity [-], at least muS",
                     MuIRheology::defaultMu2(), 0, inf, false, false),
            optional("I0", "inertial number of the mid-way friction (muS + mu2)/2 [-]",
                     0.279, 0, inf, true, false),
            optional("d", "grain diameter [m]", 0.53e-3, 0, inf, true, false),
            optional("rhoS", "grain (solid) density [kg/m^3]", 2450, 0, inf, true, false),
            optional("alphaCritical", "critical grain volume fraction mass/(rhoS volume): "
                     "looser grains are disconnected and stress-free [-]", 0.6, 0, 1, false, false)
        },
        &MuIRheology::create
    });
    laws.push_back
    ({
        "dilute",
        "stress-free grains of a dilute suspension (moved by gravity and the fluid)",
        {density()},
        &Dilute::create
    });
    return laws;
}

} // namespace

const std::vector<LawInfo>& availableLaws()
{
    static const std::vector<LawInfo> laws = buildRegistry();
    return laws;
}

const LawInfo* findLaw(const std::string& name)
{
    return findInRegistry(availableLaws(), name);
}

// Constraints between parameters (e.g. psi <= phi) are checked by the law's
// constructor, which throws std::invalid_argument in the same style.
std::unique_ptr<ConstitutiveLaw> makeLaw(const std::string& name, const Coefficients& c)
{
    return makeFromRegistry("constitutive law", availableLaws(), name, c);
}

} // namespace mpm

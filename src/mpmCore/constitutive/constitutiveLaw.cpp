// The law registry: one table of law names, summaries, parameters (with
// units, defaults and ranges) and factories. The OpenFOAM layer lists valid
// choices and reads coefficients from this table, so adding a law here is
// all that is needed to make it selectable.
#include "constitutiveLaw.hpp"
#include "druckerPrager.hpp"
#include "linearElastic.hpp"
#include "neoHookean.hpp"
#include "newtonianFluid.hpp"
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mpm {

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
            required("phi", "friction angle [deg]", 0, 90, false, true),
            optional("c", "cohesion [Pa]", 0.0, 0, inf, false, false),
            optional("psi", "dilatancy angle [deg], at most phi", 0.0, 0, 90, false, true)
        },
        &DruckerPrager::create
    });
    return laws;
}

std::string validLawNames()
{
    std::string names;
    for (const LawInfo& law : availableLaws())
        names += (names.empty() ? "" : ", ") + law.name;
    return names;
}

std::string parameterNames(const LawInfo& law)
{
    std::string names;
    for (const Parameter& p : law.parameters)
        names += (names.empty() ? "" : ", ") + p.name;
    return names;
}

[[noreturn]] void fail(const LawInfo& law, const std::string& what)
{
    throw std::invalid_argument("constitutive law '" + law.name + "': " + what);
}

std::string describe(const Parameter& p)
{
    return "parameter '" + p.name + "' (" + p.description + ", valid range " + rangeText(p) + ")";
}

} // namespace

// An infinite bound is always open: an infinite coefficient is never valid.
static bool minOpen(const Parameter& p) { return p.minExclusive || std::isinf(p.minValue); }
static bool maxOpen(const Parameter& p) { return p.maxExclusive || std::isinf(p.maxValue); }

bool inRange(const Parameter& p, Real v)
{
    const bool aboveMin = minOpen(p) ? v > p.minValue : v >= p.minValue;
    const bool belowMax = maxOpen(p) ? v < p.maxValue : v <= p.maxValue;
    return aboveMin && belowMax;    // both false for NaN
}

std::string rangeText(const Parameter& p)
{
    std::ostringstream s;
    s << (minOpen(p) ? "(" : "[") << p.minValue << ", " << p.maxValue
      << (maxOpen(p) ? ")" : "]");
    return s.str();
}

const std::vector<LawInfo>& availableLaws()
{
    static const std::vector<LawInfo> laws = buildRegistry();
    return laws;
}

const LawInfo* findLaw(const std::string& name)
{
    for (const LawInfo& law : availableLaws())
        if (law.name == name) return &law;
    return nullptr;
}

std::unique_ptr<ConstitutiveLaw> makeLaw(const std::string& name, const Coefficients& c)
{
    const LawInfo* law = findLaw(name);
    if (!law)
    {
        throw std::invalid_argument
        (
            "unknown constitutive law '" + name + "'; valid laws are: " + validLawNames()
        );
    }

    for (const auto& entry : c)
    {
        bool known = false;
        for (const Parameter& p : law->parameters) known = known || p.name == entry.first;
        if (!known)
        {
            fail(*law, "unknown parameter '" + entry.first + "'; its parameters are: "
                 + parameterNames(*law));
        }
    }

    Coefficients complete;
    for (const Parameter& p : law->parameters)
    {
        const auto given = c.find(p.name);
        if (given == c.end())
        {
            if (p.required) fail(*law, "missing required " + describe(p));
            complete[p.name] = p.defaultValue;
            continue;
        }
        if (!inRange(p, given->second))
        {
            std::ostringstream value;
            value << given->second;
            fail(*law, describe(p) + " has invalid value " + value.str());
        }
        complete[p.name] = given->second;
    }
    // Constraints between parameters (e.g. psi <= phi) are checked by the
    // law's constructor, which throws std::invalid_argument in the same style.
    return law->create(complete);
}

} // namespace mpm

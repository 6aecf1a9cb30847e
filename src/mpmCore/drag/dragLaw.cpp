// The drag-law registry: names, summaries, parameters (with units, defaults
// and ranges) and factories, like the constitutive-law registry. Adding a
// law here is all that is needed to make it selectable.
#include "dragLaw.hpp"
#include "dragLaws.hpp"
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mpm {

namespace {

constexpr Real inf = std::numeric_limits<Real>::infinity();

// Parameters common to every law (rhoF and muF come from the fluid).
Parameter diameter()
{
    Parameter p{"d", "grain diameter [m]", true, 0.0, 0, inf};
    p.minExclusive = true;
    return p;
}

Parameter alphaFMin()
{
    Parameter p{"alphaFMin", "smallest fluid fraction used in the evaluation (alphaF is clamped "
                "to [alphaFMin, 1]) [-]", false, 0.2, 0, 1};
    p.minExclusive = true;
    p.maxExclusive = true;
    return p;
}

template<class Law>
std::unique_ptr<DragLaw> create(const Coefficients& c)
{
    return std::make_unique<Law>(c.at("d"), c.at("alphaFMin"));
}

std::vector<DragLawInfo> buildRegistry()
{
    const std::vector<Parameter> common{diameter(), alphaFMin()};
    return
    {
        {"SchillerNaumann", "single sphere (Schiller-Naumann 1933), dilute, no hindrance",
         common, &create<SchillerNaumannDrag>},
        {"WenYu", "Wen-Yu (1966): Schiller-Naumann Cd times alphaF^-2.65, dilute to moderate",
         common, &create<WenYuDrag>},
        {"Ergun", "Ergun (1952) packed-bed pressure drop, dense",
         common, &create<ErgunDrag>},
        {"Gidaspow", "Gidaspow (1994): Ergun for alphaF < 0.8, Wen-Yu above (discontinuous)",
         common, &create<GidaspowDrag>},
        {"DiFelice", "Di Felice (1994) voidage function alphaF^-chi(Re), Dalla Valle Cd",
         common, &create<DiFeliceDrag>},
        {"Beetstra", "Beetstra, van der Hoef & Kuipers (2007) lattice-Boltzmann fit, monodisperse",
         common, &create<BeetstraDrag>}
    };
}

std::string validNames()
{
    std::string names;
    for (const DragLawInfo& law : availableDragLaws())
        names += (names.empty() ? "" : ", ") + law.name;
    return names;
}

std::string parameterNames(const DragLawInfo& law)
{
    std::string names;
    for (const Parameter& p : law.parameters)
        names += (names.empty() ? "" : ", ") + p.name;
    return names;
}

[[noreturn]] void fail(const DragLawInfo& law, const std::string& what)
{
    throw std::invalid_argument("drag law '" + law.name + "': " + what);
}

std::string describe(const Parameter& p)
{
    return "parameter '" + p.name + "' (" + p.description + ", valid range " + rangeText(p) + ")";
}

} // namespace

DragLaw::DragLaw(Real d, Real alphaFMin)
:
    d_(d),
    alphaFMin_(alphaFMin)
{
    if (!(d > 0))
    {
        throw std::invalid_argument("drag law: grain diameter 'd' must be > 0");
    }
    if (!(alphaFMin > 0 && alphaFMin < 1))
    {
        throw std::invalid_argument("drag law: 'alphaFMin' must lie in (0, 1)");
    }
}

void DragLaw::beta(std::size_t n, const Real* alphaF, const Real* slip, Real rhoF, Real muF,
                   Real* betaOut) const
{
    for (std::size_t i = 0; i < n; ++i) betaOut[i] = beta(alphaF[i], slip[i], rhoF, muF);
}

const std::vector<DragLawInfo>& availableDragLaws()
{
    static const std::vector<DragLawInfo> laws = buildRegistry();
    return laws;
}

const DragLawInfo* findDragLaw(const std::string& name)
{
    for (const DragLawInfo& law : availableDragLaws())
        if (law.name == name) return &law;
    return nullptr;
}

std::unique_ptr<DragLaw> makeDragLaw(const std::string& name, const Coefficients& c)
{
    const DragLawInfo* law = findDragLaw(name);
    if (!law)
    {
        throw std::invalid_argument
        (
            "unknown drag law '" + name + "'; valid drag laws are: " + validNames()
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
    return law->create(complete);
}

} // namespace mpm

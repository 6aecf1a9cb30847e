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

template<const char* Name, DragFormula Formula>
std::unique_ptr<DragLaw> create(const Coefficients& c)
{
    return std::make_unique<DragLaw>(Name, Formula, c.at("d"), c.at("alphaFMin"));
}

constexpr char schillerNaumannName[] = "SchillerNaumann";
constexpr char wenYuName[] = "WenYu";
constexpr char ergunName[] = "Ergun";
constexpr char gidaspowName[] = "Gidaspow";
constexpr char diFeliceName[] = "DiFelice";
constexpr char beetstraName[] = "Beetstra";

std::vector<DragLawInfo> buildRegistry()
{
    const std::vector<Parameter> common{diameter(), alphaFMin()};
    return
    {
        {"SchillerNaumann", "single sphere (Schiller-Naumann 1933), dilute, no hindrance",
         common, &create<schillerNaumannName, &drag::schillerNaumann>},
        {"WenYu", "Wen-Yu (1966): Schiller-Naumann Cd times alphaF^-2.65, dilute to moderate",
         common, &create<wenYuName, &drag::wenYu>},
        {"Ergun", "Ergun (1952) packed-bed pressure drop, dense",
         common, &create<ergunName, &drag::ergun>},
        {"Gidaspow", "Gidaspow (1994): Ergun for alphaF < 0.8, Wen-Yu above (discontinuous)",
         common, &create<gidaspowName, &drag::gidaspow>},
        {"DiFelice", "Di Felice (1994) voidage function alphaF^-chi(Re), Dalla Valle Cd",
         common, &create<diFeliceName, &drag::diFelice>},
        {"Beetstra", "Beetstra, van der Hoef & Kuipers (2007) lattice-Boltzmann fit, monodisperse",
         common, &create<beetstraName, &drag::beetstra>}
    };
}

} // namespace

DragLaw::DragLaw(const char* name, DragFormula formula, Real d, Real alphaFMin)
:
    name_(name),
    formula_(formula),
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
    return findInRegistry(availableDragLaws(), name);
}

std::unique_ptr<DragLaw> makeDragLaw(const std::string& name, const Coefficients& c)
{
    return makeFromRegistry("drag law", availableDragLaws(), name, c);
}

} // namespace mpm

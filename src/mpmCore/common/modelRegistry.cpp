#include "modelRegistry.hpp"
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mpm {

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

Coefficients completeCoefficients
(
    const std::string& kind,
    const std::string& model,
    const std::vector<Parameter>& parameters,
    const Coefficients& given
)
{
    auto fail = [&](const std::string& what)
    {
        throw std::invalid_argument(kind + " '" + model + "': " + what);
    };
    auto describe = [](const Parameter& p)
    {
        return "parameter '" + p.name + "' (" + p.description + ", valid range " + rangeText(p) + ")";
    };

    for (const auto& entry : given)
    {
        bool known = false;
        for (const Parameter& p : parameters) known = known || p.name == entry.first;
        if (!known)
        {
            std::string names;
            for (const Parameter& p : parameters) names += (names.empty() ? "" : ", ") + p.name;
            fail("unknown parameter '" + entry.first + "'; its parameters are: " + names);
        }
    }

    Coefficients complete;
    for (const Parameter& p : parameters)
    {
        const auto it = given.find(p.name);
        if (it == given.end())
        {
            if (p.required) fail("missing required " + describe(p));
            complete[p.name] = p.defaultValue;
            continue;
        }
        if (!inRange(p, it->second))
        {
            std::ostringstream value;
            value << it->second;
            fail(describe(p) + " has invalid value " + value.str());
        }
        complete[p.name] = it->second;
    }
    return complete;
}

} // namespace mpm

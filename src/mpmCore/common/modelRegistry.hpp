// What every run-time-selected model family of the core shares (constitutive
// laws, drag laws): a parameter table with ranges and defaults, a registry of
// named models, and one place that validates coefficients against the table
// and words the errors. The OpenFOAM layer reads dictionaries from the same
// tables, so its FatalIOErrors list the same names and ranges.
#pragma once
#include "../types.hpp"
#include <map>
#include <stdexcept>
#include <memory>
#include <string>
#include <vector>

namespace mpm {

struct Parameter
{
    std::string name;
    std::string description;  // with units, for the log and the error text
    bool required;
    Real defaultValue;
    Real minValue;            // lower bound (inclusive unless minExclusive)
    Real maxValue;            // upper bound (inclusive unless maxExclusive)
    bool minExclusive = false;
    bool maxExclusive = false;
};

// True when v lies in the parameter's range (false for NaN).
bool inRange(const Parameter& p, Real v);

// The range in interval notation, e.g. "(0, inf)" or "[0, 0.5)".
std::string rangeText(const Parameter& p);

using Coefficients = std::map<std::string, Real>;

// A named model: summary, parameter table and factory.
template<class Base>
struct ModelInfo
{
    std::string name;
    std::string summary;
    std::vector<Parameter> parameters;
    std::unique_ptr<Base> (*create)(const Coefficients&);
};

// "a, b, c" from the names of a registry.
template<class Info>
std::string registryNames(const std::vector<Info>& registry)
{
    std::string names;
    for (const Info& m : registry) names += (names.empty() ? "" : ", ") + m.name;
    return names;
}

template<class Info>
const Info* findInRegistry(const std::vector<Info>& registry, const std::string& name)
{
    for (const Info& m : registry) if (m.name == name) return &m;
    return nullptr;
}

// Checks `given` against a model's parameter table and fills in defaults.
// Throws std::invalid_argument "<kind> '<model>': ..." naming the parameter,
// its description and valid range, for a missing required parameter, a
// value out of range, or a name that is not a parameter (a typo).
Coefficients completeCoefficients
(
    const std::string& kind,
    const std::string& model,
    const std::vector<Parameter>& parameters,
    const Coefficients& given
);

// Looks a model up and creates it with validated coefficients; an unknown
// name throws std::invalid_argument listing the valid names.
template<class Base>
std::unique_ptr<Base> makeFromRegistry
(
    const std::string& kind,
    const std::vector<ModelInfo<Base>>& registry,
    const std::string& name,
    const Coefficients& given
)
{
    const ModelInfo<Base>* m = findInRegistry(registry, name);
    if (!m)
    {
        throw std::invalid_argument
        (
            "unknown " + kind + " '" + name + "'; valid " + kind + "s are: " + registryNames(registry)
        );
    }
    return m->create(completeCoefficients(kind, name, m->parameters, given));
}

} // namespace mpm

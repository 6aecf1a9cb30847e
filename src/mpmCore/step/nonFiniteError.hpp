// The error that stops a step whose points stopped being finite.
#pragma once
#include "../types.hpp"
#include <cstdint>
#include <stdexcept>
#include <string>

namespace mpm {

// Thrown when a point's velocity or stress stops being finite: nothing is
// written after it, and the message names the step and point id, and for
// a stress its material (index), which the error carries so that a caller
// can name it (the OpenFOAM layer: by its dictionary name).
class NonFiniteError : public std::runtime_error
{
public:
    NonFiniteError(const std::string& base, Index step, std::int64_t id, int material = -1)
    : std::runtime_error(material >= 0 ? base + " (material " + std::to_string(material) + ")" : base),
      step(step), pointId(id), material(material), base(base) {}
    Index step;
    std::int64_t pointId;
    int material;        // -1: not a material's (a velocity)
    std::string base;    // the message without the material
};

} // namespace mpm

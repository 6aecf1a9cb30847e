// The constitutive phase: every point's deformation and stress updated by
// its material's law (kernels/stressPoint.hpp holds the body per point),
// the non-finite stop, and the count of inverted points (J <= 0 or volume
// <= 0) with the one of lowest id.
#pragma once
#include "../step/systemState.hpp"

namespace mpm {

// Throws NonFiniteError (step/nonFiniteError.hpp) on NaN/inf
void updateStress(SystemState& s, Real dt);

} // namespace mpm

// The explicit step's stability limit: the Courant condition on the
// points' signal speed, and each law's own bound.
#pragma once
#include "../step/systemState.hpp"

namespace mpm {

// Largest signal speed max_p (c_p + |v_p|) over every rank
Real maxSignalSpeed(const SystemState& s);
// Explicit stable step for Courant number `courant`, also honouring each
// law's own bound (e.g. viscous diffusion)
Real stableDeltaT(const SystemState& s, Real courant);

} // namespace mpm

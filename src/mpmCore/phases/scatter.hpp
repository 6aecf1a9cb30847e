// The P2G phase: the points binned, and their mass, volume, momentum and
// internal force scattered to the nodes (kernels/p2g.hpp holds the body
// per point). Blocks of one colour run in parallel, so the node sums do
// not depend on the number of threads.
#pragma once
#include "../step/systemState.hpp"

namespace mpm {

// Bins the points (reordering them when fragmented and reorderPoints) and
// builds this step's active region, which leaves every grid array zero on it
void binPoints(SystemState& s);

// What one P2G scatters: massMomentum, mass, volume and momentum (a fresh
// P2G: right after binPoints); force, the internal force (alone: added to
// the gravity already there, USF); velocityOnly, the momentum anew from
// the new point velocities (the MUSL re-map)
struct ScatterWhat
{
    bool massMomentum = false;
    bool force = false;
    bool velocityOnly = false;
};
void scatter(SystemState& s, ScatterWhat what);

} // namespace mpm

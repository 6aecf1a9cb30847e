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

// The fresh P2G of a step or map, right after binPoints: mass, volume and
// momentum, and with withForce the internal force too (USL, MUSL)
void scatterMassMomentum(SystemState& s, bool withForce);
// USF: the internal force alone, added to the gravity already there
void scatterForce(SystemState& s);
// MUSL: the momentum anew, from the new point velocities
void remapMomentum(SystemState& s);

} // namespace mpm

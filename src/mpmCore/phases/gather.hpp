// The G2P phase: the points' new velocity (PIC/FLIP blend or APIC), their
// displacement over the step, and the velocity gradient from a grid
// velocity (kernels/g2p.hpp holds the bodies per point). Independent per
// point, so the results do not depend on the number of threads.
#pragma once
#include "../step/systemState.hpp"

namespace mpm {

// From the updated grid velocity (and v^n for FLIP)
void gather(SystemState& s, Real dt);
// The velocity gradient alone, from the grid velocity v (USF: v^n; MUSL:
// the re-mapped velocity)
void gradientFromGrid(SystemState& s, const std::array<StaggeredArray<Real>, 3>& v);

} // namespace mpm

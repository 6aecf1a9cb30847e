// The node work of a step: from the scattered mass and momentum to the
// velocities the G2P reads. Gravity, the halo sums, the ghost folds with
// the walls' contact decision, the mass solve (lumped, or consistent by
// Jacobi sweeps), the implicit fluid coupling, friction and level-set
// walls, the ghosts and halo filled (kernels/nodal.hpp: the bodies per
// node that the resident device step shares).
#pragma once
#include "../step/systemState.hpp"

namespace mpm {

// Nodes lighter than a 1e-10 of the mean point mass (a point at the far
// edge of a stencil) get zero velocity rather than a ratio of round-off
void updateMassTolerance(SystemState& s);

// v = M^-1 p from the folded momentum (lumped or consistent mass)
void massToVelocity(SystemState& s, std::array<StaggeredArray<Real>, 3>& v);

// After the step's fresh P2G (host and host-assisted steps alike):
// gravity, the halo sums, the ghost folds with the wall-contact decision,
// and the old velocity v^n with its ghosts. withForce: the P2G scattered
// the internal force too (USL, MUSL), so it is summed and folded here.
void nodalAfterScatter(SystemState& s, Real dt, bool withForce);

// USF: the internal force scattered after the stress update, summed over
// the halo and folded from the ghosts
void foldScatteredForce(SystemState& s);

// (M + D) v = p + dt f: the new velocity, with the implicit drag and added
// mass of the fluid coupling (step/fluidCoupling.hpp), friction and
// level-set walls, the ghosts and halo; integrates v for the coupling
void nodalUpdate(SystemState& s, Real dt);

// After the MUSL re-map: the re-scattered momentum summed and folded, the
// velocity it gives (walls and friction, no force: dt = 0)
void nodalAfterRemap(SystemState& s);

} // namespace mpm

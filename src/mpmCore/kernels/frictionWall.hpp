// Kernel bodies of the Coulomb friction of the box's friction walls
// (Bardenhagen et al. 2000), on one node: MpmSystem::applyFriction runs them
// over the boundary's node lists on the host, the resident device step
// (backend/residentStepImpl.hpp) one thread per node. J[a][I] is the normal
// impulse the wall normal to axis a delivers to node I in this step: from
// the mirror fold of its contact ghosts (frictionGhostImpulse, summed into
// the image), and on the first node layer from removing a normal velocity
// still approaching the wall (frictionFirstLayer).
#pragma once
#include "views.hpp"
#include <cmath>

namespace mpm {

// A contact ghost's normal momentum and force enter its image with the sign
// reversed instead of added: an impulse 2 (p_g + dt f_g).n away from the
// wall (n pointing into it). dt = 0 (the MUSL re-map): the momentum's alone.
MPM_HOST_DEVICE inline Real frictionGhostImpulse(const GridView& g, Index ghost, int a, Real outward, Real dt)
{
    return 2*(g.momentum[a][ghost] + dt*g.force[a][ghost])*outward;
}

// Coulomb on node I against the wall normal to axis a: the tangential
// speed is reduced by mu times the normal impulse over the node's mass,
// never reversed. Clears J[a][I], so a node listed twice (first layer and
// image) is treated once.
MPM_HOST_DEVICE inline void frictionSlide
(
    Real* const J[3], const Real* mass, Real* const v[3], Real massTolerance, Index I, int a, Real mu
)
{
    const Real Jn = J[a][I];
    J[a][I] = 0;
    if (Jn <= 0 || mass[I] <= massTolerance) return;
    Real vt2 = 0;
    for (int d = 0; d < 3; ++d) if (d != a) vt2 += v[d][I]*v[d][I];
    const Real vt = std::sqrt(vt2), dv = mu*Jn/mass[I];
    const Real scale = vt > dv ? 1.0 - dv/vt : 0.0;
    for (int d = 0; d < 3; ++d) if (d != a) v[d][I] *= scale;
}

// A first-layer node of a friction wall: a normal velocity approaching the
// wall is removed and its impulse added to J, then the slide
MPM_HOST_DEVICE inline void frictionFirstLayer
(
    Real* const J[3], const Real* mass, Real* const v[3], Real massTolerance, Index I, int a, Real outward,
    Real mu
)
{
    const Real vn = v[a][I]*outward;
    if (vn > 0)
    {
        J[a][I] += mass[I]*vn;
        v[a][I] = 0;
    }
    frictionSlide(J, mass, v, massTolerance, I, a, mu);
}

} // namespace mpm

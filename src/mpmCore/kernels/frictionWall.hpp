// Kernel bodies of the Coulomb friction of the box's friction walls
// (Bardenhagen et al. 2000), on one node: applyFriction (phases/walls.hpp)
// runs them over the boundary's node lists on the host, the resident device
// step (backend/residentStepImpl.hpp) one thread per node. J[a][I] is the normal
// impulse the wall normal to axis a delivers to node I in this step: from
// the mirror fold of its contact ghosts (frictionGhostImpulse, summed into
// the image), and on the first node layer from removing a normal velocity
// still approaching the wall (frictionFirstLayer).
//
// Stick or slide is decided first, with the contact (frictionSticks): a
// node that sticks has its wall's ghosts mirror it as a noSlip wall's do
// for this step (the wall face at rest, the material free to shear above
// it), and only a sliding node gets the Coulomb impulse. A wall rougher
// than the material therefore acts as the noSlip wall. (Issue 29: stopping
// the image nodes themselves, which lie h/2 and 3h/2 inside the wall, stuck
// a layer that a noSlip wall leaves free to shear, and stopped a column
// collapse 31 % short of the noSlip floor's runout at mu = 1.)
#pragma once
#include "views.hpp"
#include <cmath>

namespace mpm {

// Does the image node I stick to the wall normal to axis a over this step?
// Bardenhagen et al.'s (2000) test on its trial momentum T (its momentum
// and the force, or gravity, over the step): the wall stops the normal
// part that approaches it, T.n, and can then hold the tangential part when
// mu T.n >= |T_t|.
MPM_HOST_DEVICE inline bool frictionSticks(const GridView& g, Index I, int a, Real outward, Real mu, Real dt,
                                          bool withForce, const Real gravity[3])
{
    Real T[3];
    for (int d = 0; d < 3; ++d)
    {
        T[d] = g.momentum[d][I] + dt*(withForce ? g.force[d][I] : g.mass[I]*gravity[d]);
    }
    const Real n = T[a]*outward;
    Real t2 = 0;
    for (int d = 0; d < 3; ++d) if (d != a) t2 += T[d]*T[d];
    return n >= 0 && mu*mu*n*n >= t2;
}

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

// Per-node bodies of the nodal phase that need no neighbour: gravity on the
// P2G masses and the lumped velocity p/m. The ghost folds, fills and the
// wall contact are bodies over the boundary's ghost list in the resident
// device step (backend/residentStepImpl.hpp) and loops over it in
// MpmSystem; halos, friction, open faces and the coupled and
// consistent-mass solves are the host phases' alone (phases/nodalUpdate.cpp).
#pragma once
#include "views.hpp"

namespace mpm {

// m g on a node, before the halo sum and the wall fold, like the internal
// force: a ghost's weight is reflected onto its image with its momentum.
MPM_HOST_DEVICE inline void gravityNode(const GridView& g, const Real gravity[3], Index I)
{
    const Real m = g.mass[I];
    for (int d = 0; d < 3; ++d) g.force[d][I] += m*gravity[d];
}

// v = p/m, zero below the mass tolerance (a node a point touches only at
// the far edge of its stencil has a ratio of round-off).
MPM_HOST_DEVICE inline void lumpedVelocityNode
(
    const GridView& g, Real* const v[3], Real massTolerance, Index I
)
{
    const Real m = g.mass[I];
    const Real inv = m > massTolerance ? 1.0/m : 0.0;
    for (int d = 0; d < 3; ++d) v[d][I] = g.momentum[d][I]*inv;
}

} // namespace mpm

// Nodal fields on the padded lattice, one flat array per component.
#pragma once
#include "../types.hpp"
#include <array>
#include <vector>
#include "../common/staggeredArray.hpp"

namespace mpm {

struct GridState
{
    StaggeredArray<Real> mass;
    StaggeredArray<Real> volume;                     // sum N V_p: solid fraction
    std::array<StaggeredArray<Real>, 3> momentum;
    std::array<StaggeredArray<Real>, 3> force;
    std::array<StaggeredArray<Real>, 3> velocityOld; // v^n, from P2G
    std::array<StaggeredArray<Real>, 3> velocity;    // v^{n+1}
    // G2P's packed copy of velocity and velocity - velocityOld, 8 values
    // per node, valid on the active region's nodes during the gather
    // (GridView::velocityPack; the allocator's 64-byte alignment keeps each
    // record's two 4-wide loads within one cache line)
    StaggeredArray<Real> velocityPack;

    void resize(Index n)
    {
        mass.assign(n, 0); volume.assign(n, 0);
        for (int d = 0; d < 3; ++d)
        {
            momentum[d].assign(n, 0); force[d].assign(n, 0);
            velocityOld[d].assign(n, 0); velocity[d].assign(n, 0);
        }
    }
};

} // namespace mpm

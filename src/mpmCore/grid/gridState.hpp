// Nodal fields on the padded lattice, one flat array per component.
#pragma once
#include "../types.hpp"
#include <array>
#include <cstdint>
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
    // (GridView::velocityPack)
    std::vector<Real> velocityPack;

    // A pack of 8 values per node (zero-filled when the lattice changes),
    // its records aligned to 64 bytes so that no 4-wide load straddles a
    // cache line
    Real* pack(std::vector<Real>& p) const
    {
        const std::size_t n = 8*mass.size() + 8;
        if (p.size() != n) p.assign(n, 0.0);
        const std::size_t offset = (64 - reinterpret_cast<std::uintptr_t>(p.data()) % 64) % 64;
        return p.data() + offset/sizeof(Real);
    }

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

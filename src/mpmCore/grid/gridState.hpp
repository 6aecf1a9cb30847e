// Nodal fields on the padded lattice, one flat array per component.
#pragma once
#include "../types.hpp"
#include <array>
#include <vector>

namespace mpm {

struct GridState
{
    std::vector<Real> mass;
    std::vector<Real> volume;                     // sum N V_p: solid fraction
    std::array<std::vector<Real>, 3> momentum;
    std::array<std::vector<Real>, 3> force;
    std::array<std::vector<Real>, 3> velocityOld; // v^n, from P2G
    std::array<std::vector<Real>, 3> velocity;    // v^{n+1}

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

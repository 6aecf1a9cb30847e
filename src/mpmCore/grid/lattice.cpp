#include "lattice.hpp"
#include <stdexcept>
#include <string>

namespace mpm {

void Lattice::finalise()
{
    dim = 0;
    int u = 0;
    std::array<int, 3> unsolved{};
    for (int a = 0; a < 3; ++a)
    {
        if (solved[a]) axes[dim++] = a; else unsolved[u++] = a;
    }
    for (int i = 0; i < u; ++i) axes[dim + i] = unsolved[i];

    for (int a = 0; a < 3; ++a)
    {
        if (solved[a] && nCells[a] < (checkGhostLayers ? pad : 1))
        {
            throw std::invalid_argument
            (
                "lattice: direction " + std::to_string(a) + " has "
              + std::to_string(nCells[a]) + " cells; at least "
              + std::to_string(pad) + " are needed for the ghost layers"
            );
        }
        nodes[a] = solved[a] ? nCells[a] + 2*pad : 1;
    }
    stride = {1, nodes[0], Index(nodes[0])*nodes[1]};
    nNodes = Index(nodes[0])*nodes[1]*nodes[2];
    nRealNodes = Index(nCells[0])*nCells[1]*nCells[2];
}

} // namespace mpm

// The MPM background lattice: a uniform Cartesian grid whose nodes are the
// centres of the finite-volume cells (see docs/gridDesign.md for why).
//
// Solved directions get `pad` ghost layers on each side so that every
// stencil, whatever the shape function, reads and writes inside the array;
// ghosts are folded back onto real nodes by the boundary conditions.
// Unsolved directions (1D/2D cases) have exactly one node and no stencil.
#pragma once
#include "../types.hpp"
#include "../common/hostDevice.hpp"
#include <array>

namespace mpm {

struct Lattice
{
    std::array<Real, 3> origin{0, 0, 0};   // low corner of the box (a face)
    Real h = 1;                            // uniform spacing
    std::array<int, 3> nCells{1, 1, 1};    // real nodes per direction
    std::array<bool, 3> solved{true, true, true};
    int pad = 2;                           // ghost layers (enough for CBS)
    // Whole domains need pad cells to mirror their ghosts; a decomposed
    // rank's box lattice (parallel/subdomain.hpp) mirrors nothing.
    bool checkGhostLayers = true;

    // Derived by finalise()
    int dim = 3;                           // number of solved directions
    std::array<int, 3> axes{0, 1, 2};      // solved axes first
    std::array<int, 3> nodes{1, 1, 1};     // padded node counts
    std::array<Index, 3> stride{0, 0, 0};
    Index nNodes = 0;
    Index nRealNodes = 0;

    void finalise();

    MPM_HOST_DEVICE int padOf(int axis) const { return solved[axis] ? pad : 0; }

    // Padded node index from padded (i, j, k).
    MPM_HOST_DEVICE Index node(int i, int j, int k) const
    {
        return i*stride[0] + j*stride[1] + k*stride[2];
    }

    // Padded node index of the real node (= FV cell) with real indices.
    MPM_HOST_DEVICE Index realNode(int i, int j, int k) const
    {
        return node(i + padOf(0), j + padOf(1), k + padOf(2));
    }

    // Linear cell index (x fastest) of real (i,j,k): the mesh's cell order
    // for a blockMesh box, used by the OpenFOAM layer's cell map.
    MPM_HOST_DEVICE Index cellIndex(int i, int j, int k) const
    {
        return i + Index(nCells[0])*(j + Index(nCells[1])*k);
    }

    MPM_HOST_DEVICE Real length(int axis) const { return nCells[axis]*h; }
};

} // namespace mpm

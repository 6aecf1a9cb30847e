// Sorts material points into blocks of cells and colours the blocks so that
// blocks of one colour have disjoint stencils. P2G then runs blocks of one
// colour in parallel with plain stores: no atomics, no per-thread grids, and
// every node sums its contributions in the same order whatever the thread
// count, so results are bitwise independent of the number of threads.
//
// Block edge 4 cells: a cubic B-spline point touches nodes up to two cells
// away, so two same-colour blocks (one block apart) never share a node.
// Along x (the contiguous direction of the node arrays) blocks are 16 cells
// long, so that the node ranges two threads write are at least 8 nodes (a
// 64-byte cache line) apart: no false sharing between concurrent blocks.
#pragma once
#include "../grid/lattice.hpp"
#include "../particles/particles.hpp"
#include <vector>

namespace mpm {

class Binning
{
public:
    static constexpr int blockSize = 4;
    static constexpr int blockSizeX = 16;
    static int blockEdge(int axis) { return axis == 0 ? blockSizeX : blockSize; }

    void build(const Lattice& L, const Particles& p);

    int nColours() const { return nColours_; }

    // Blocks of colour c are keys [colourBegin(c), colourBegin(c+1)).
    Index colourBegin(int c) const { return Index(c)*blocksPerColourKey_; }

    // Points of block key b are order()[start(b) .. start(b+1)).
    Index start(Index key) const { return start_[key]; }
    const std::vector<Index>& order() const { return order_; }

private:
    int nColours_ = 1;
    Index blocksPerColourKey_ = 1;
    std::vector<Index> start_;
    std::vector<Index> order_;
    std::vector<Index> key_;
};

} // namespace mpm

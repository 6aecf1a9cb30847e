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
#include <algorithm>
#include <array>
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

    // Whether the storage order is far from the block order: the runs of
    // consecutive indices in order() are shorter than 8 on average
    bool fragmented() const
    {
        Index breaks = 0;
        for (std::size_t q = 1; q < order_.size(); ++q) breaks += order_[q] != order_[q - 1] + 1;
        return 8*breaks > Index(order_.size());
    }

    // After the points were permuted into order(): they are in block order
    void setIdentityOrder() { for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = Index(i); }

    // Calls f(lo, hi) with the real cell range (inclusive, per axis; 0 in
    // unsolved directions) of every block that holds points.
    template<class Fn>
    void forEachOccupiedBlock(Fn&& f) const
    {
        const Index nKeys = Index(nColours_)*blocksPerColourKey_;
        for (Index key = 0; key < nKeys; ++key)
        {
            if (start_[key + 1] == start_[key]) continue;
            Index b = key % blocksPerColourKey_;
            int lo[3], hi[3];
            for (int a = 0; a < 3; ++a)
            {
                const Index ba = b % nb_[a];
                b /= nb_[a];
                lo[a] = int(ba)*blockEdge(a);
                hi[a] = std::min(lo[a] + blockEdge(a), nCells_[a]) - 1;
            }
            f(lo, hi);
        }
    }

private:
    int nColours_ = 1;
    Index blocksPerColourKey_ = 1;
    std::array<Index, 3> nb_{1, 1, 1};     // blocks per axis
    std::array<int, 3> nCells_{1, 1, 1};   // real cells per axis
    std::vector<Index> start_;
    std::vector<Index> order_;
    std::vector<Index> key_;
};

} // namespace mpm

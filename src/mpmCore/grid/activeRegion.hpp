// The part of the lattice the material touches this step: the nodes that
// the stencils of the points reach (per occupied binning block, dilated by
// the stencil reach), the wall ghosts and images and the periodic copies
// paired with them, and, decomposed, every halo node. Clearing, folding and
// the nodal updates loop over these lists instead of the whole lattice, so
// a small body in a large box costs what the body costs (Claymore's sparse
// grid of active blocks, on the dense arrays).
//
// Every node outside the region holds zero: build() zeroes the previous
// region's nodes before marking the new one. Since a node outside the
// region has no mass, the dense step would give it zero velocity too. A
// ghost (or periodic copy) outside the region adds zero to its image and
// nobody reads what is filled into it, so only the pairs whose ghost is in
// the region are listed, in the dense order of the sums: the sparse step is
// bitwise the dense one (tests/unit/activeRegionTest.cpp).
#pragma once
#include "boundary.hpp"
#include "lattice.hpp"
#include "../transfer/binning.hpp"
#include <vector>

namespace mpm {

class ActiveRegion
{
public:
    // dense: every node, ghost and periodic copy, always (the reference)
    void setDense(bool dense) { dense_ = dense; valid_ = false; }
    bool dense() const { return dense_; }

    // Zeroes `arrays` (each of L.nNodes values) on the previous region's
    // nodes, then builds the region of the binned points. alwaysActive:
    // nodes in the region whatever the points (decomposed: the halo).
    void build
    (
        const Lattice& L, const Binning& bins, int reach,
        const Boundary& boundary, const std::vector<Index>& alwaysActive,
        const std::vector<Real*>& arrays
    );

    // Node indices (padded lattice), each once
    const std::vector<Index>& nodes() const { return nodes_; }
    // Indices into boundary.ghosts() and boundary.periodicCopies(),
    // ascending (the dense summation order)
    const std::vector<Index>& ghosts() const { return ghosts_; }
    const std::vector<Index>& periodicCopies() const { return periodic_; }

    // Sets every listed node of each array to zero
    void zero(const std::vector<Real*>& arrays) const;

private:
    void mark(Index I);
    // Per node, the ghost-list entries whose ghost (or periodic copy) it is,
    // as linked lists: built once per lattice, so a step scans only the
    // region's nodes, never the whole boundary
    void indexPairs(const Boundary& boundary);

    bool dense_ = false;
    bool valid_ = false;            // dense lists built for this lattice
    Index nNodes_ = 0;
    std::vector<char> active_;      // per node
    std::vector<Index> nodes_, ghosts_, periodic_;
    std::vector<int> ghostHead_, ghostNext_, periodicHead_, periodicNext_;
};

} // namespace mpm

#include "activeRegion.hpp"
#include <algorithm>
#include <numeric>

namespace mpm {

void ActiveRegion::mark(Index I)
{
    if (active_[I]) return;
    active_[I] = 1;
    nodes_.push_back(I);
}

void ActiveRegion::indexPairs(const Boundary& boundary)
{
    const auto& ghostList = boundary.ghosts();
    const auto& periodicList = boundary.periodicCopies();
    ghostHead_.assign(nNodes_, -1);
    ghostNext_.assign(ghostList.size(), -1);
    // Prepended in reverse: each node's list is ascending
    for (std::size_t g = ghostList.size(); g-- > 0; )
    {
        ghostNext_[g] = ghostHead_[ghostList[g].ghost];
        ghostHead_[ghostList[g].ghost] = int(g);
    }
    periodicHead_.assign(nNodes_, -1);
    periodicNext_.assign(periodicList.size(), -1);
    for (std::size_t c = periodicList.size(); c-- > 0; )
    {
        periodicNext_[c] = periodicHead_[periodicList[c].first];
        periodicHead_[periodicList[c].first] = int(c);
    }
}

void ActiveRegion::zero(const std::vector<Real*>& arrays) const
{
    for (Real* a : arrays) for (const Index I : nodes_) a[I] = 0;
}

void ActiveRegion::build
(
    const Lattice& L, const Binning& bins, int reach,
    const Boundary& boundary, const std::vector<Index>& alwaysActive,
    const std::vector<Real*>& arrays
)
{
    const auto& ghostList = boundary.ghosts();
    const auto& periodicList = boundary.periodicCopies();
    if (dense_)
    {
        if (valid_ && nNodes_ == L.nNodes) { zero(arrays); return; }
        nNodes_ = L.nNodes;
        nodes_.resize(nNodes_);
        std::iota(nodes_.begin(), nodes_.end(), Index(0));
        ghosts_.resize(ghostList.size());
        std::iota(ghosts_.begin(), ghosts_.end(), Index(0));
        periodic_.resize(periodicList.size());
        std::iota(periodic_.begin(), periodic_.end(), Index(0));
        valid_ = true;
        zero(arrays);
        return;
    }
    valid_ = false;
    if (nNodes_ != L.nNodes)
    {
        // A new lattice: everything is zero'd once, nothing is listed yet
        nNodes_ = L.nNodes;
        active_.assign(nNodes_, 0);
        nodes_.clear();
        for (Real* a : arrays) std::fill(a, a + nNodes_, 0.0);
        indexPairs(boundary);
    }
    zero(arrays);
    for (const Index I : nodes_) active_[I] = 0;
    nodes_.clear();

    // Nodes a point of cell c reaches: c + pad - reach .. c + pad + reach
    bins.forEachOccupiedBlock([&](const int lo[3], const int hi[3])
    {
        int n0[3], n1[3];
        for (int a = 0; a < 3; ++a)
        {
            if (!L.solved[a]) { n0[a] = n1[a] = 0; continue; }
            n0[a] = std::max(0, lo[a] + L.pad - reach);
            n1[a] = std::min(L.nodes[a] - 1, hi[a] + L.pad + reach);
        }
        for (int k = n0[2]; k <= n1[2]; ++k)
        for (int j = n0[1]; j <= n1[1]; ++j)
        for (int i = n0[0]; i <= n1[0]; ++i)
        {
            mark(L.node(i, j, k));
        }
    });
    for (const Index I : alwaysActive) mark(I);

    // The serial halo (periodic copies) and the wall ghosts whose ghost
    // node is in bring their image in; an image may itself be a periodic
    // copy (a corner), so the nodes brought in are visited too
    periodic_.clear();
    ghosts_.clear();
    for (std::size_t k = 0; k < nodes_.size(); ++k)
    {
        const Index I = nodes_[k];
        for (int c = periodicHead_[I]; c >= 0; c = periodicNext_[c])
        {
            periodic_.push_back(c);
            mark(periodicList[c].second);
        }
        for (int g = ghostHead_[I]; g >= 0; g = ghostNext_[g])
        {
            ghosts_.push_back(g);
            mark(ghostList[g].image);
        }
    }
    // The dense order of the sums (an image may receive from several)
    std::sort(periodic_.begin(), periodic_.end());
    std::sort(ghosts_.begin(), ghosts_.end());
}

} // namespace mpm

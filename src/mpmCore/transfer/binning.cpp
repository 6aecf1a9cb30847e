#include "binning.hpp"
#include <algorithm>
#include <cmath>

namespace mpm {

void Binning::build(const Lattice& L, const Particles& p)
{
    std::array<Index, 3> nb{1, 1, 1};
    for (int a = 0; a < 3; ++a)
    {
        if (L.solved[a]) nb[a] = (L.nCells[a] + blockEdge(a) - 1)/blockEdge(a);
    }
    nb_ = nb;
    for (int a = 0; a < 3; ++a) nCells_[a] = L.solved[a] ? L.nCells[a] : 1;
    nColours_ = 1 << L.dim;
    blocksPerColourKey_ = nb[0]*nb[1]*nb[2];
    const Index nKeys = Index(nColours_)*blocksPerColourKey_;

    const Index n = p.size();
    key_.resize(n);
    start_.assign(nKeys + 1, 0);
    const Real invh = 1.0/L.h;

    for (Index i = 0; i < n; ++i)
    {
        Index b[3] = {0, 0, 0};
        int colour = 0, bit = 0;
        for (int a = 0; a < 3; ++a)
        {
            if (!L.solved[a]) continue;
            Index c = Index(std::floor((p.x[a][i] - L.origin[a])*invh));
            c = std::min<Index>(std::max<Index>(c, 0), L.nCells[a] - 1);
            b[a] = c/blockEdge(a);
            colour |= int(b[a] & 1) << bit++;
        }
        const Index k = colour*blocksPerColourKey_ + b[0] + nb[0]*(b[1] + nb[1]*b[2]);
        key_[i] = k;
        ++start_[k + 1];
    }
    for (Index k = 0; k < nKeys; ++k) start_[k + 1] += start_[k];

    // Stable counting sort: points keep their relative order within a block.
    order_.resize(n);
    std::vector<Index> fill(start_.begin(), start_.end() - 1);
    for (Index i = 0; i < n; ++i) order_[fill[key_[i]]++] = i;
}

} // namespace mpm

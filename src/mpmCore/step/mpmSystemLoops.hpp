// MpmSystem's loop helpers (member templates), for the translation units
// that define its phases: step/mpmSystem.cpp, walls.cpp, pointTransfer.cpp,
// residentLauncher.cpp. Not a public header.
#pragma once
#include "mpmSystem.hpp"
#include <type_traits>

namespace mpm {

template<class Fn>
void MpmSystem::dispatch(Fn&& f) const
{
    dispatchShape(options_.shape, [&](auto k)
    {
        switch (lattice_.dim)
        {
            case 1: f(k, std::integral_constant<int, 1>{}); break;
            case 2: f(k, std::integral_constant<int, 2>{}); break;
            default: f(k, std::integral_constant<int, 3>{}); break;
        }
    });
}

// Runs fn(p) for every point, blocks of one colour in parallel, so that fn
// may scatter to its stencil's nodes with plain stores (transfer/binning.hpp).
template<class Fn>
void MpmSystem::forEachPointColoured(Fn&& fn) const
{
    const std::vector<Index>& order = binning_.order();
    for (int c = 0; c < binning_.nColours(); ++c)
    {
        const Index k0 = binning_.colourBegin(c), k1 = binning_.colourBegin(c + 1);
        #pragma omp parallel for schedule(dynamic, 1) if(worthThreads(Index(order.size())))
        for (Index key = k0; key < k1; ++key)
        {
            for (Index q = binning_.start(key); q < binning_.start(key + 1); ++q)
            {
                fn(order[q]);
            }
        }
    }
}

template<class Fn>
void MpmSystem::forEachActiveNode(Fn&& fn) const
{
    const std::vector<Index>& list = region_.nodes();
    const Index n = Index(list.size());
    #pragma omp parallel for if(worthThreads(n))
    for (Index k = 0; k < n; ++k) fn(list[k]);
}

} // namespace mpm

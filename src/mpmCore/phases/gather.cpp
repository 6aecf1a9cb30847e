#include "gather.hpp"
#include "../kernels/g2p.hpp"

namespace mpm {

namespace {

// GridView::velocityPack on the active region's nodes (the only nodes a
// point's stencil reaches); zero-filled when the lattice changes, so each
// record's fourth and eighth values are zero
const Real* packVelocities(SystemState& s)
{
    StaggeredArray<Real>& packed = s.grid.velocityPack;
    if (packed.size() != 8*s.grid.mass.size()) packed.assign(8*s.grid.mass.size(), 0.0);
    Real* pack = packed.data();
    const GridView g = gridView(s.grid);
    s.forEachActiveNode([&](Index I) { packNodeVelocity(g, pack, I); });
    return pack;
}

template<class K, int D, bool Apic>
void gatherAs(SystemState& s, Real dt)
{
    const PointView P = s.points();
    GridView g = gridView(s.grid);
    const Lattice& L = s.lattice;
    const Index n = P.n;
    const Real alpha = s.options.flipRatio;
#ifdef MPM_HOST_LANES
    if constexpr (D == 3 && !Apic)
    {
        // Two points at a time (kernels/g2p.hpp: their sums overlap)
        g.velocityPack = packVelocities(s);
        constexpr int Np = 2;
        const Index groups = n/Np;
        #pragma omp parallel for schedule(static) if(s.worthThreads(n))
        for (Index q = 0; q < groups; ++q)
        {
            Index p[Np];
            for (int r = 0; r < Np; ++r) p[r] = Np*q + r;
            g2pPackedPoints<K, Np>(L, P, g, alpha, dt, p);
        }
        for (Index p = Np*groups; p < n; ++p) g2pPoint<K, D, Apic>(L, P, g, alpha, dt, p);
        return;
    }
#endif
    #pragma omp parallel for schedule(static) if(s.worthThreads(n))
    for (Index p = 0; p < n; ++p) g2pPoint<K, D, Apic>(L, P, g, alpha, dt, p);
}

template<class K, int D>
void gradientAs(SystemState& s, const std::array<StaggeredArray<Real>, 3>& v)
{
    const PointView P = s.points();
    const Real* const vp[3] = {v[0].data(), v[1].data(), v[2].data()};
    const Lattice& L = s.lattice;
    const Index n = P.n;
    #pragma omp parallel for schedule(static) if(s.worthThreads(n))
    for (Index p = 0; p < n; ++p) gradientPoint<K, D>(L, P, vp, p);
}

} // namespace

void gather(SystemState& s, Real dt)
{
    const bool apic = s.options.transfer == Transfer::apic;
    s.dispatch([&](auto k, auto d)
    {
        using K = decltype(k);
        constexpr int D = decltype(d)::value;
        if (apic) gatherAs<K, D, true>(s, dt);
        else gatherAs<K, D, false>(s, dt);
    });
}

void gradientFromGrid(SystemState& s, const std::array<StaggeredArray<Real>, 3>& v)
{
    s.dispatch([&](auto k, auto d) { gradientAs<decltype(k), decltype(d)::value>(s, v); });
}

} // namespace mpm

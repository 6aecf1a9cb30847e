#include "gather.hpp"
#include "../kernels/g2p.hpp"

namespace mpm {

namespace {

template<class K, int D, bool Apic>
void gatherAs(SystemState& s, Real dt)
{
    const PointView P = s.points();
    const GridView g = gridView(s.grid);
    const Lattice& L = s.lattice;
    const Index n = P.n;
    const Real alpha = s.options.flipRatio;
    #pragma omp parallel for schedule(static) if(s.worthThreads(n))
    for (Index p = 0; p < n; ++p) g2pPoint<K, D, Apic>(L, P, g, alpha, dt, p);
}

template<class K, int D>
void gradientAs(SystemState& s, const std::array<std::vector<Real>, 3>& v)
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

void gradientFromGrid(SystemState& s, const std::array<std::vector<Real>, 3>& v)
{
    s.dispatch([&](auto k, auto d) { gradientAs<decltype(k), decltype(d)::value>(s, v); });
}

} // namespace mpm

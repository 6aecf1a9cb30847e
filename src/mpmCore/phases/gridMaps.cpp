#include "gridMaps.hpp"
#include "halo.hpp"
#include "nodalUpdate.hpp"
#include "scatter.hpp"
#include "walls.hpp"
#include "../transfer/stencil.hpp"
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mpm {

void mapToGrid(SystemState& s, std::vector<Real>* grainVolume)
{
    s.pullPoints();
    updateMassTolerance(s);
    auto& g = s.grid;
    binPoints(s);
    scatterMassMomentum(s, false);
    if (grainVolume) grainVolume->assign(g.volume.begin(), g.volume.end());
    sumHalo(s, foldMass | foldMomentum);
    foldGhosts(s, foldMass);
    decideWallContact(s, 0, false);
    foldGhosts(s, foldMomentum);
    massToVelocity(s, g.velocity);
    fillGhosts(s, g.velocity);
}

GridSample sampleGrid(SystemState& s)
{
    auto& g = s.grid;
    if (!s.subdomain) return {g.mass.data(), g.volume.data(), {g.velocity[0].data(), g.velocity[1].data(), g.velocity[2].data()}};
    auto& sample = s.sample;
    sample[0] = g.mass;
    sample[1] = g.volume;
    for (int d = 0; d < 3; ++d) sample[2 + d] = g.velocity[d];
    std::vector<Real*> all;
    for (auto& a : sample) all.push_back(a.data());
    copyHalo(s, all, Subdomain::HaloKind::exchange);
    return {sample[0].data(), sample[1].data(), {sample[2].data(), sample[3].data(), sample[4].data()}};
}

void materialGrainVolume(SystemState& s, std::vector<std::vector<Real>>& out)
{
    s.pullPoints();
    out.assign(s.materials.size(), std::vector<Real>(s.lattice.nNodes, 0.0));
    const std::vector<Real> invRho0 = s.inverseDensities();
    const auto& P = s.particles;
    // The P2G loop: blocks of one colour in parallel (plain stores into
    // node arrays are safe)
    s.dispatch([&](auto k, auto d)
    {
        using K = decltype(k);
        constexpr int D = decltype(d)::value;
        s.binning.build(s.lattice, s.particles);
        s.forEachPointColoured([&](Index p)
        {
            Stencil<K, D> st;
            st.compute(s.lattice, P.x[0][p], P.x[1][p], P.x[2][p]);
            const int m = P.material[p];
            const Real v = P.mass[p]*invRho0[m];
            Real* o = out[m].data();
            st.forEachWeight(s.lattice, [&](Index I, Real N) { o[I] += N*v; });
        });
    });
    for (auto& o : out)
    {
        sumHalo(s, {o.data()});
        foldScalar(s, o.data());
        if (s.subdomain) copyHalo(s, {o.data()}, Subdomain::HaloKind::exchange);
    }
}

void setCoverage(SystemState& s, const std::vector<double>& coverage)
{
    const Lattice& L = s.lattice;
    if (coverage.size() != std::size_t(L.nNodes))
    {
        throw std::invalid_argument("setCoverage: one value per node of the lattice");
    }
    s.coverage = coverage;
    int width = 0;
    s.dispatch([&](auto k, auto) { width = decltype(k)::width; });
    auto& full = s.coveredStencil;
    full.resize(coverage.size());
    for (std::size_t I = 0; I < full.size(); ++I)
    {
        full[I] = std::abs(coverage[I] - 1) <= fullCoverage;
    }
    // Whether the W nodes from I on are all full, along each solved axis
    // in turn: then the stencil whose first node is I is (a stencil past
    // the padded lattice counts as uncovered)
    std::vector<unsigned char> in;
    for (int a = 0; a < 3; ++a)
    {
        if (!L.solved[a]) continue;
        in = full;
        const Index n = L.nodes[a], stride = L.stride[a];
        for (Index I = 0; I < L.nNodes; ++I)
        {
            const Index i = (I/stride) % n;
            unsigned char f = i + width <= n;
            for (int o = 0; f && o < width; ++o) f = in[std::size_t(I + o*stride)];
            full[std::size_t(I)] = f;
        }
    }
}

namespace {

template<class K, int D>
void spreadOverCoverage(const SystemState& s, std::vector<Real>& spread)
{
    const Lattice& L = s.lattice;
    const auto& P = s.particles;
    const std::vector<Real> invRho0 = s.inverseDensities();
    Real* o = spread.data();
    const double* cov = s.coverage.data();
    const Real invh = 1.0/L.h;
    for (Index p = 0; p < P.size(); ++p)
    {
        // The first node of the point's stencil (Stencil::compute's base)
        Index first = 0;
        for (int a = 0; a < 3; ++a)
        {
            if (!L.solved[a]) continue;
            // The same expression as Stencil::compute's, so the same bits
            const Index b = K::baseOf((P.x[a][p] - L.origin[a])*invh - 0.5 + L.pad);
            first += std::min(std::max(b, Index(0)), Index(L.nodes[a] - 1))*L.stride[a];
        }
        if (s.coveredStencil[std::size_t(first)]) continue;
        Stencil<K, D> st;
        st.compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
        const Real v = P.mass[p]*invRho0[P.material[p]];
        // By rows of W nodes, as the P2G's rows: short sums rather than
        // one chain of W^D dependent additions
        const Index s0 = L.stride[L.axes[0]];
        Real covered = 0;
        st.forEachRow(L, [&](Index first, Real wjk)
        {
            Real row = 0;
            for (int i = 0; i < K::width; ++i) row += st.w[0][i]*cov[first + i*s0];
            covered += wjk*row;
        });
        // The P2G gave N v; the spread is N v/covered. A point with no
        // covered node (outside the mesh) gives nothing.
        const Real extra = covered > 0 ? v/covered - v : -v;
        st.forEachRow(L, [&](Index first, Real wjk)
        {
            const Real e = wjk*extra;
            for (int i = 0; i < K::width; ++i) o[first + i*s0] += st.w[0][i]*e;
        });
    }
}

} // namespace

void spreadGrainVolume(const SystemState& s, std::vector<Real>& spread)
{
    if (s.coverage.size() != std::size_t(s.lattice.nNodes) || spread.size() != s.coverage.size())
    {
        throw std::logic_error("spreadGrainVolume: needs setCoverage and mapToGrid(&spread) on this lattice");
    }
    if (!s.options.constantGrainVolume)
    {
        throw std::logic_error("spreadGrainVolume: the grid volume is not the grain volume (setConstantGrainVolume)");
    }
    // The P2G's grain volume is the spread for every point whose stencil
    // is fully covered: the others are corrected
    s.dispatch([&](auto k, auto d) { spreadOverCoverage<decltype(k), decltype(d)::value>(s, spread); });
}

} // namespace mpm

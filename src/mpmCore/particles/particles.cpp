#include "particles.hpp"
#include "../parallel/communicator.hpp"

namespace mpm {

namespace {

template<class V>
void permuteArray(V& a, const std::vector<Index>& order, V& tmp)
{
    tmp.resize(a.size());
    for (std::size_t i = 0; i < order.size(); ++i) tmp[i] = a[order[i]];
    a.swap(tmp);
}

// Applies f to every per-point array, so new fields need one line here only.
template<class P, class Fn>
void forEachArray(P& p, Fn&& f)
{
    for (auto& a : p.x) f(a);
    for (auto& a : p.v) f(a);
    f(p.mass); f(p.volume0); f(p.volume);
    for (auto& a : p.F) f(a);
    for (auto& a : p.sigma) f(a);
    for (auto& a : p.C) f(a);
    f(p.eqPlasticStrain);
}

} // namespace

void Particles::resize(Index n)
{
    forEachArray(*this, [n](StaggeredArray<Real>& a) { a.resize(n, 0.0); });
    material.resize(n, 0);
    id.resize(n, 0);
}

Index Particles::add
(
    const std::array<Real, 3>& pos, const std::array<Real, 3>& vel,
    Real m, Real vol, int mat
)
{
    const Index p = size();
    resize(p + 1);
    for (int d = 0; d < 3; ++d) { x[d][p] = pos[d]; v[d][p] = vel[d]; }
    mass[p] = m;
    volume0[p] = vol;
    volume[p] = vol;
    F[0][p] = F[4][p] = F[8][p] = 1.0;
    material[p] = mat;
    id[p] = p;
    return p;
}

void Particles::permute(const std::vector<Index>& order)
{
    StaggeredArray<Real> tmp;
    forEachArray(*this, [&](StaggeredArray<Real>& a) { permuteArray(a, order, tmp); });
    StaggeredArray<int> ti; permuteArray(material, order, ti);
    std::vector<std::int64_t> tl; permuteArray(id, order, tl);
}

void Particles::pack(Index p, std::vector<char>& buf) const
{
    forEachArray(*this, [&](const StaggeredArray<Real>& a) { appendBytes(buf, &a[p], 1); });
    appendBytes(buf, &material[p], 1);
    appendBytes(buf, &id[p], 1);
}

void Particles::unpack(const std::vector<char>& buf)
{
    std::size_t nReal = 0;
    forEachArray(*this, [&](const StaggeredArray<Real>&) { ++nReal; });
    const std::size_t bytes = nReal*sizeof(Real) + sizeof(int) + sizeof(std::int64_t);
    const Index n0 = size(), n = Index(buf.size()/bytes);
    resize(n0 + n);
    std::size_t at = 0;
    for (Index p = n0; p < n0 + n; ++p)
    {
        forEachArray(*this, [&](StaggeredArray<Real>& a) { readBytes(buf, at, &a[p], 1); });
        readBytes(buf, at, &material[p], 1);
        readBytes(buf, at, &id[p], 1);
    }
}

void Particles::remove(const std::vector<Index>& ascending)
{
    Index n = size();
    for (auto it = ascending.rbegin(); it != ascending.rend(); ++it)
    {
        const Index p = *it, last = --n;
        if (p == last) continue;
        forEachArray(*this, [&](StaggeredArray<Real>& a) { a[p] = a[last]; });
        material[p] = material[last];
        id[p] = id[last];
    }
    resize(n);
}

Real Particles::J(Index p) const
{
    const Real a = F[0][p], b = F[1][p], c = F[2][p];
    const Real d = F[3][p], e = F[4][p], f = F[5][p];
    const Real g = F[6][p], h = F[7][p], i = F[8][p];
    return a*(e*i - f*h) - b*(d*i - f*g) + c*(d*h - e*g);
}

} // namespace mpm

#include "particles.hpp"

namespace mpm {

namespace {

template<class T>
void permuteArray(std::vector<T>& a, const std::vector<Index>& order, std::vector<T>& tmp)
{
    tmp.resize(a.size());
    for (std::size_t i = 0; i < order.size(); ++i) tmp[i] = a[order[i]];
    a.swap(tmp);
}

// Applies f to every per-point array, so new fields need one line here only.
template<class Fn>
void forEachArray(Particles& p, Fn&& f)
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
    forEachArray(*this, [n](std::vector<Real>& a) { a.resize(n, 0.0); });
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
    std::vector<Real> tmp;
    forEachArray(*this, [&](std::vector<Real>& a) { permuteArray(a, order, tmp); });
    std::vector<int> ti; permuteArray(material, order, ti);
    std::vector<std::int64_t> tl; permuteArray(id, order, tl);
}

Real Particles::J(Index p) const
{
    const Real a = F[0][p], b = F[1][p], c = F[2][p];
    const Real d = F[3][p], e = F[4][p], f = F[5][p];
    const Real g = F[6][p], h = F[7][p], i = F[8][p];
    return a*(e*i - f*h) - b*(d*i - f*g) + c*(d*h - e*g);
}

} // namespace mpm

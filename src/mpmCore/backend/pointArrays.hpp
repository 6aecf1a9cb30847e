// The point arrays a device step moves each way, in one list for every
// device back-end (deviceStep.cu, residentStep.hpp): fn(device, host, name)
// for each array the step reads (up) or writes (down). The materials (int)
// go up separately.
#pragma once
#include "../kernels/views.hpp"

namespace mpm {

enum class PointDirection { up, down };

template<class Fn>
void forEachPointArray(const PointView& d, const PointView& h, PointDirection dir, bool apic, Fn&& fn)
{
    for (int a = 0; a < 3; ++a) { fn(d.x[a], h.x[a], "x"); fn(d.v[a], h.v[a], "v"); }
    fn(d.volume, h.volume, "volume");
    for (int e = 0; e < 9; ++e) fn(d.F[e], h.F[e], "F");
    for (int c = 0; c < 6; ++c) fn(d.sigma[c], h.sigma[c], "sigma");
    fn(d.eqPlasticStrain, h.eqPlasticStrain, "eqPlasticStrain");
    if (apic) for (int e = 0; e < 9; ++e) fn(d.C[e], h.C[e], "C");
    if (dir == PointDirection::up)
    {
        fn(d.mass, h.mass, "mass");
        fn(d.volume0, h.volume0, "volume0");
    }
}

// Reals per point in a device mirror: x v mass volume0 volume F sigma C
// eqPlasticStrain L dx
constexpr int realsPerPoint = 3 + 3 + 1 + 1 + 1 + 9 + 6 + 9 + 1 + 9 + 3;

// Lays a mirror's point arrays out in one block of n*realsPerPoint reals
inline PointView layPoints(Real* r, int* material, Index n)
{
    auto take = [&]() { Real* a = r; r += n; return a; };
    PointView P;
    P.n = n;
    for (int a = 0; a < 3; ++a) { P.x[a] = take(); P.v[a] = take(); P.dx[a] = take(); }
    P.mass = take(); P.volume0 = take(); P.volume = take();
    for (int e = 0; e < 9; ++e) { P.F[e] = take(); P.C[e] = take(); P.L[e] = take(); }
    for (int c = 0; c < 6; ++c) P.sigma[c] = take();
    P.eqPlasticStrain = take();
    P.material = material;
    return P;
}

// Lays a mirror's grid arrays out in one block of n*14 reals
inline GridView layGrid(Real* r, Index n)
{
    auto take = [&]() { Real* a = r; r += n; return a; };
    GridView g;
    g.n = n;
    g.mass = take(); g.volume = take();
    for (int d = 0; d < 3; ++d)
    {
        g.momentum[d] = take(); g.force[d] = take();
        g.velocityOld[d] = take(); g.velocity[d] = take();
    }
    return g;
}
constexpr int realsPerNode = 14;

} // namespace mpm

// P2G body of one material point: mass, grain or current volume, momentum
// (with the APIC affine part) and the internal force -V sigma grad N, added
// to the nodes of the point's stencil.
//
// `add(array, node, value)` performs array[node] += value: a plain store on
// the CPU, where the launcher runs the points of one colour at a time so no
// two threads share a node (transfer/binning.hpp), an atomicAdd on the GPU.
// The choices are template arguments, so the node loop has no branches.
#pragma once
#include "../transfer/stencil.hpp"
#include "views.hpp"

namespace mpm {

// Rows: 3D without APIC, each row of W nodes along x as one vector loop
// (same terms, same order, same bits as node by node; step/p2gRowChoice.hpp
// chooses it per run by timing).
template<class K, int D, bool MassMomentum, bool Force, bool Apic, bool Rows = true, class Add>
MPM_HOST_DEVICE inline void p2gPoint
(
    const Lattice& L, const PointView& P, const GridView& g,
    const Real* invRho0, bool grainVolume, Index p, Add add
)
{
    // Momentum is scattered with the mass, or alone (MUSL re-map).
    constexpr bool Momentum = MassMomentum || !Force;
    Stencil<K, D> s;
    s.compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
    const Real m = P.mass[p], vol = P.volume[p];
    const Real solidVol = grainVolume ? m*invRho0[P.material[p]] : vol;
    const Real v0 = P.v[0][p], v1 = P.v[1][p], v2 = P.v[2][p];
    Real Cp[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    if constexpr (Apic) for (int e = 0; e < 9; ++e) Cp[e] = P.C[e][p];
    const Real sxx = P.sigma[XX][p], syy = P.sigma[YY][p], szz = P.sigma[ZZ][p];
    const Real sxy = P.sigma[XY][p], syz = P.sigma[YZ][p], sxz = P.sigma[XZ][p];
    if constexpr (D == 3 && !Apic && Rows)
    {
        // 3D without the APIC offsets: one loop over each row of W nodes
        // along x, contiguous in memory (Lattice: axes (0, 1, 2), stride[0]
        // = 1), as a vector loop over the row computed from the stencil's
        // x weights. Each node receives the same terms, by
        // the same expressions, in the same order as in forEach's loop.
        // Measured trade-off (benchmarks/mppicComparison/README.md): P2G
        // of the 32^3 block 2x faster with cubic B-splines, but 1.4x
        // slower on the coupled mppicComparison scene's small grid; hence
        // the choice by timing (step/p2gRowChoice.hpp).
        const Index s1 = L.stride[1], s2 = L.stride[2];
        // On the host, a row of 3 (QBS) as 4, the fourth node with zero
        // weights: one full 4-wide vector per array instead of a masked
        // one (P2G 1.4x faster on the 3D block). Adding +-0 leaves a node's
        // bits as they are, and the fourth node stays within CBS's reach,
        // which the padding and the binning's colours allow for. Not on
        // the device, where it would be one more atomic per row.
#ifdef MPM_HOST_LANES
        constexpr int Wx = K::width == 3 ? 4 : K::width;
#else
        constexpr int Wx = K::width;
#endif
        Real w0[Wx], dw0[Wx];
        for (int i = 0; i < Wx; ++i)
        {
            w0[i] = i < K::width ? s.w[0][i] : 0.0;
            dw0[i] = i < K::width ? s.dw[0][i] : 0.0;
        }
        for (int k = 0; k < K::width; ++k)
        for (int j = 0; j < K::width; ++j)
        {
            const Real wjk = s.w[1][j]*s.w[2][k];
            const Real djk = s.dw[1][j]*s.w[2][k];
            const Real wdk = s.w[1][j]*s.dw[2][k];
            const Index first = s.base[0] + (s.base[1] + j)*s1 + (s.base[2] + k)*s2;
            MPM_SIMD
            for (int i = 0; i < Wx; ++i)
            {
                const Index I = first + i;
                const Real N = w0[i]*wjk;
                if constexpr (MassMomentum)
                {
                    add(g.mass, I, N*m);
                    add(g.volume, I, N*solidVol);
                }
                if constexpr (Momentum)
                {
                    const Real Nm = N*m;
                    add(g.momentum[0], I, Nm*v0);
                    add(g.momentum[1], I, Nm*v1);
                    add(g.momentum[2], I, Nm*v2);
                }
                if constexpr (Force)
                {
                    const Real dN0 = dw0[i]*wjk, dN1 = w0[i]*djk, dN2 = w0[i]*wdk;
                    add(g.force[0], I, -vol*(sxx*dN0 + sxy*dN1 + sxz*dN2));
                    add(g.force[1], I, -vol*(sxy*dN0 + syy*dN1 + syz*dN2));
                    add(g.force[2], I, -vol*(sxz*dN0 + syz*dN1 + szz*dN2));
                }
            }
        }
        return;
    }
    s.forEach(L, [&](Index I, Real N, const Real* dN, const Real* dx)
    {
        if constexpr (MassMomentum)
        {
            add(g.mass, I, N*m);
            add(g.volume, I, N*solidVol);
        }
        if constexpr (Momentum)
        {
            Real u0 = v0, u1 = v1, u2 = v2;
            if constexpr (Apic)
            {
                u0 += Cp[0]*dx[0] + Cp[1]*dx[1] + Cp[2]*dx[2];
                u1 += Cp[3]*dx[0] + Cp[4]*dx[1] + Cp[5]*dx[2];
                u2 += Cp[6]*dx[0] + Cp[7]*dx[1] + Cp[8]*dx[2];
            }
            const Real Nm = N*m;
            add(g.momentum[0], I, Nm*u0);
            add(g.momentum[1], I, Nm*u1);
            add(g.momentum[2], I, Nm*u2);
        }
        if constexpr (Force)
        {
            add(g.force[0], I, -vol*(sxx*dN[0] + sxy*dN[1] + sxz*dN[2]));
            add(g.force[1], I, -vol*(sxy*dN[0] + syy*dN[1] + syz*dN[2]));
            add(g.force[2], I, -vol*(sxz*dN[0] + syz*dN[1] + szz*dN[2]));
        }
    });
}

// The CPU's add: a plain store (the colouring makes it race-free)
struct PlainAdd
{
    MPM_HOST_DEVICE void operator()(Real* a, Index I, Real x) const { a[I] += x; }
};

} // namespace mpm

// G2P bodies of one material point.
//
// g2pPoint: the new point velocity (PIC/FLIP blend, or APIC with its affine
// matrix C), the displacement over the step (dt times the PIC velocity,
// stored in P.dx) and the velocity gradient L from the updated grid
// velocity (stored in P.L). gradientPoint: L alone, from a given nodal
// velocity (USF before the stress update, MUSL after the re-map).
#pragma once
#include "../transfer/stencil.hpp"
#include "views.hpp"
#include <type_traits>

namespace mpm {

// One node's record of GridView::velocityPack: v, then v - vOld as FLIP's
// increment computes it (the fourth and eighth values stay zero)
MPM_HOST_DEVICE inline void packNodeVelocity(const GridView& g, Real* pack, Index I)
{
    Real* r = pack + 8*I;
    for (int i = 0; i < 3; ++i)
    {
        r[i] = g.velocity[i][I];
        r[4 + i] = g.velocity[i][I] - g.velocityOld[i][I];
    }
}

// PIC/FLIP's point update from the sums: the blended velocity, the
// displacement dt vPic and the velocity gradient
MPM_HOST_DEVICE inline void g2pWrite
(
    const PointView& P, Real flipRatio, Real dt, Index p, const Real vPic[3], const Real dv[3], const Real Lg[9]
)
{
    for (int i = 0; i < 3; ++i)
    {
        P.v[i][p] = flipRatio*(P.v[i][p] + dv[i]) + (1.0 - flipRatio)*vPic[i];
        P.dx[i][p] = dt*vPic[i];
    }
    for (int e = 0; e < 9; ++e) P.L[e][p] = Lg[e];
}

#ifdef MPM_HOST_LANES
// Host only: the 3D PIC/FLIP G2P of Np points at once from the velocity
// pack (GridView::velocityPack; the device has none and takes g2pPoint's
// node loop). A node's velocities are two 4-wide loads, and each point's
// sums are 4-wide lanes: vPic, dv and the columns of L (L[3i+j] is lane i
// of column j). The sums are factored by rows: along each row of W nodes
// in x, the sums of w_x v, w_x (v - vOld) and w_x' v, then each row's
// y-z weights once; 3 FMAs per node instead of 5 plus the node's weight
// products. That is the node loop's sum in another order, so it agrees
// with it to round-off, not to the bit (tests/unit/transferTest.cpp). The
// Np points' sums are independent chains, interleaved, so that they
// overlap in the FMA pipeline.
template<class K, int Np>
inline void g2pPackedPoints
(
    const Lattice& L, const PointView& P, const GridView& g, Real flipRatio, Real dt, const Index* p
)
{
    typedef Real R4 __attribute__((vector_size(4*sizeof(Real))));
    constexpr int W = K::width;
    Stencil<K, 3> s[Np];
    R4 a[Np], b[Np], c0[Np], c1[Np], c2[Np];
    for (int q = 0; q < Np; ++q)
    {
        s[q].compute(L, P.x[0][p[q]], P.x[1][p[q]], P.x[2][p[q]]);
        a[q] = b[q] = c0[q] = c1[q] = c2[q] = R4{0, 0, 0, 0};
    }
    const Index s1 = L.stride[1], s2 = L.stride[2];
    for (int k = 0; k < W; ++k)
    for (int j = 0; j < W; ++j)
    {
        R4 sv[Np], sd[Np], sg[Np];
        for (int q = 0; q < Np; ++q)
        {
            const Real* row = g.velocityPack + 8*(s[q].base[0] + (s[q].base[1] + j)*s1 + (s[q].base[2] + k)*s2);
            sv[q] = sd[q] = sg[q] = R4{0, 0, 0, 0};
            for (int i = 0; i < W; ++i)
            {
                R4 v = {0, 0, 0, 0}, dvel = v;
                __builtin_memcpy(&v, row + 8*i, sizeof(R4));
                __builtin_memcpy(&dvel, row + 8*i + 4, sizeof(R4));
                sv[q] += s[q].w[0][i]*v;
                sd[q] += s[q].w[0][i]*dvel;
                sg[q] += s[q].dw[0][i]*v;
            }
        }
        for (int q = 0; q < Np; ++q)
        {
            const Real wjk = s[q].w[1][j]*s[q].w[2][k];
            const Real djk = s[q].dw[1][j]*s[q].w[2][k];
            const Real wdk = s[q].w[1][j]*s[q].dw[2][k];
            a[q] += wjk*sv[q];
            b[q] += wjk*sd[q];
            c0[q] += wjk*sg[q];
            c1[q] += djk*sv[q];
            c2[q] += wdk*sv[q];
        }
    }
    for (int q = 0; q < Np; ++q)
    {
        const Real Lg[9] = {c0[q][0], c1[q][0], c2[q][0], c0[q][1], c1[q][1], c2[q][1], c0[q][2], c1[q][2], c2[q][2]};
        const Real vPic[3] = {a[q][0], a[q][1], a[q][2]}, dv[3] = {b[q][0], b[q][1], b[q][2]};
        g2pWrite(P, flipRatio, dt, p[q], vPic, dv, Lg);
    }
}
#endif

template<class K, int D, bool Apic>
MPM_HOST_DEVICE inline void g2pPoint
(
    const Lattice& L, const PointView& P, const GridView& g, Real flipRatio, Real dt, Index p
)
{
    constexpr bool lh = std::is_same<K, LinearHat>::value;
#ifdef MPM_HOST_LANES
    if constexpr (D == 3 && !Apic)
    {
        if (g.velocityPack) { g2pPackedPoints<K, 1>(L, P, g, flipRatio, dt, &p); return; }
    }
#endif
    Stencil<K, D> s;
    s.compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
    Real vPic[3] = {0, 0, 0}, dv[3] = {0, 0, 0};
    Real Lg[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    Real Bx[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    s.forEach(L, [&](Index I, Real N, const Real* dN, const Real* dx)
    {
        for (int i = 0; i < 3; ++i)
        {
            const Real vi = g.velocity[i][I];
            vPic[i] += N*vi;
            if constexpr (!Apic) dv[i] += N*(vi - g.velocityOld[i][I]);
            for (int j = 0; j < 3; ++j)
            {
                Lg[3*i + j] += vi*dN[j];
                if constexpr (Apic && !lh) Bx[3*i + j] += N*vi*dx[j];
            }
        }
    });
    if constexpr (!Apic)
    {
        g2pWrite(P, flipRatio, dt, p, vPic, dv, Lg);
    }
    else
    {
        for (int i = 0; i < 3; ++i)
        {
            P.v[i][p] = vPic[i];
            P.dx[i][p] = dt*vPic[i];
        }
        for (int e = 0; e < 9; ++e) P.L[e][p] = Lg[e];
        // LH: the affine matrix is the velocity gradient (Jiang et al.);
        // B-splines: C = B D^-1 with D constant per axis.
        Real Dinv[3];
        s.apicInertia(L, Dinv);
        for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
        {
            P.C[3*i + j][p] = lh ? Lg[3*i + j] : Bx[3*i + j]*Dinv[j];
        }
    }
}

template<class K, int D>
MPM_HOST_DEVICE inline void gradientPoint
(
    const Lattice& L, const PointView& P, const Real* const v[3], Index p
)
{
    Stencil<K, D> s;
    s.compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
    Real Lg[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    s.forEach(L, [&](Index I, Real, const Real* dN, const Real*)
    {
        for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Lg[3*i + j] += v[i][I]*dN[j];
    });
    for (int e = 0; e < 9; ++e) P.L[e][p] = Lg[e];
}

} // namespace mpm

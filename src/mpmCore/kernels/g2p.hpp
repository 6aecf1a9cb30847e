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

template<class K, int D, bool Apic>
MPM_HOST_DEVICE inline void g2pPoint
(
    const Lattice& L, const PointView& P, const GridView& g, Real flipRatio, Real dt, Index p
)
{
    constexpr bool lh = std::is_same<K, LinearHat>::value;
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
    for (int i = 0; i < 3; ++i)
    {
        P.v[i][p] = Apic ? vPic[i] : flipRatio*(P.v[i][p] + dv[i]) + (1.0 - flipRatio)*vPic[i];
        P.dx[i][p] = dt*vPic[i];
    }
    for (int e = 0; e < 9; ++e) P.L[e][p] = Lg[e];
    if constexpr (Apic)
    {
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

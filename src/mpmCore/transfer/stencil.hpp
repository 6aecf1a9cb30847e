// Tensor-product stencil of one material point on the padded lattice.
//
// Templated on the kernel K and the number of solved directions D so that
// the node loops have compile-time trip counts (unrolled, vectorisable):
// the same body serves P2G, G2P and the force scatter, and would serve a
// CUDA back-end unchanged (it touches only a Lattice and raw pointers).
#pragma once
#include "../grid/lattice.hpp"
#include "../shapeFunctions/shapeFunctions.hpp"

namespace mpm {

template<class K, int D>
struct Stencil
{
    static constexpr int W = K::width;
    Index base[D];
    Real w[D][W];
    Real dw[D][W];    // already divided by h
    Real xiLocal[D];  // point position minus base node, lattice units

    MPM_HOST_DEVICE inline void compute(const Lattice& L, Real x0, Real x1, Real x2)
    {
        const Real xs[3] = {x0, x1, x2};
        const Real invh = 1.0/L.h;
        for (int d = 0; d < D; ++d)
        {
            const int a = L.axes[d];
            // Node i (padded) sits at origin + (i - pad + 1/2) h.
            const Real xi = (xs[a] - L.origin[a])*invh - 0.5 + L.pad;
            K::eval(xi, base[d], w[d], dw[d]);
            xiLocal[d] = xi - Real(base[d]);
            for (int q = 0; q < W; ++q) dw[d][q] *= invh;
        }
    }

    // Calls f(node, N, gradN[3]) for every node of the stencil, gradN in
    // global axis order (zero in unsolved directions), plus the offset
    // (x_I - x_p) in global axis order, for APIC.
    template<class Fn>
    MPM_HOST_DEVICE inline void forEach(const Lattice& L, Fn&& f) const
    {
        const int a0 = L.axes[0];
        const Index s0 = L.stride[a0];
        if constexpr (D == 1)
        {
            for (int i = 0; i < W; ++i)
            {
                Real g[3] = {0, 0, 0}; Real dx[3] = {0, 0, 0};
                g[a0] = dw[0][i];
                dx[a0] = (Real(i) - xiLocal[0])*L.h;
                f((base[0] + i)*s0, w[0][i], g, dx);
            }
        }
        else if constexpr (D == 2)
        {
            const int a1 = L.axes[1];
            const Index s1 = L.stride[a1];
            for (int j = 0; j < W; ++j)
            for (int i = 0; i < W; ++i)
            {
                Real g[3] = {0, 0, 0}; Real dx[3] = {0, 0, 0};
                g[a0] = dw[0][i]*w[1][j];
                g[a1] = w[0][i]*dw[1][j];
                dx[a0] = (Real(i) - xiLocal[0])*L.h;
                dx[a1] = (Real(j) - xiLocal[1])*L.h;
                f((base[0] + i)*s0 + (base[1] + j)*s1, w[0][i]*w[1][j], g, dx);
            }
        }
        else
        {
            const int a1 = L.axes[1], a2 = L.axes[2];
            const Index s1 = L.stride[a1], s2 = L.stride[a2];
            for (int k = 0; k < W; ++k)
            for (int j = 0; j < W; ++j)
            {
                const Real wjk = w[1][j]*w[2][k];
                const Real djk = dw[1][j]*w[2][k];
                const Real wdk = w[1][j]*dw[2][k];
                const Index nodeJK = (base[1] + j)*s1 + (base[2] + k)*s2;
                for (int i = 0; i < W; ++i)
                {
                    Real g[3]; Real dx[3];
                    g[a0] = dw[0][i]*wjk;
                    g[a1] = w[0][i]*djk;
                    g[a2] = w[0][i]*wdk;
                    dx[a0] = (Real(i) - xiLocal[0])*L.h;
                    dx[a1] = (Real(j) - xiLocal[1])*L.h;
                    dx[a2] = (Real(k) - xiLocal[2])*L.h;
                    f((base[0] + i)*s0 + nodeJK, w[0][i]*wjk, g, dx);
                }
            }
        }
    }

    // Calls f(first, wjk) for every row of W nodes along the first solved
    // axis: its first node (the others follow at stride[axes[0]]) and the
    // product of the other axes' weights (1 in 1D); the row's node i has
    // weight w[0][i]*wjk, as in forEach
    template<class Fn>
    MPM_HOST_DEVICE inline void forEachRow(const Lattice& L, Fn&& f) const
    {
        const Index s0 = L.stride[L.axes[0]];
        if constexpr (D == 1)
        {
            f(base[0]*s0, Real(1));
        }
        else if constexpr (D == 2)
        {
            const Index s1 = L.stride[L.axes[1]];
            for (int j = 0; j < W; ++j) f(base[0]*s0 + (base[1] + j)*s1, w[1][j]);
        }
        else
        {
            const Index s1 = L.stride[L.axes[1]], s2 = L.stride[L.axes[2]];
            for (int k = 0; k < W; ++k)
            for (int j = 0; j < W; ++j)
            {
                f(base[0]*s0 + (base[1] + j)*s1 + (base[2] + k)*s2, w[1][j]*w[2][k]);
            }
        }
    }

    // Calls f(node, N) for every node of the stencil: the weights alone,
    // in forEach's order (no gradients)
    template<class Fn>
    MPM_HOST_DEVICE inline void forEachWeight(const Lattice& L, Fn&& f) const
    {
        const Index s0 = L.stride[L.axes[0]];
        forEachRow(L, [&](Index first, Real wjk)
        {
            for (int i = 0; i < W; ++i) f(first + i*s0, w[0][i]*wjk);
        });
    }

    // Diagonal of the APIC inertia D_p = sum N (x_I - x_p)^2 per solved axis.
    MPM_HOST_DEVICE inline void apicInertia(const Lattice& L, Real Dinv[3]) const
    {
        Dinv[0] = Dinv[1] = Dinv[2] = 0;
        for (int d = 0; d < D; ++d)
        {
            Real s = 0;
            for (int q = 0; q < W; ++q)
            {
                const Real r = (Real(q) - xiLocal[d])*L.h;
                s += w[d][q]*r*r;
            }
            Dinv[L.axes[d]] = s > 0 ? 1.0/s : 0.0;
        }
    }
};

} // namespace mpm

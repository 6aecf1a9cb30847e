// Small 3x3 tensor helpers shared by the constitutive laws.
//
// Full tensors are row-major (T_ij at [3i+j]); symmetric tensors use the
// six-component order of types.hpp (xx yy zz xy yz xz) holding the tensor
// components themselves (no doubled engineering shears).
#pragma once
#include "../types.hpp"
#include <array>
#include <cmath>

namespace mpm {
namespace tensor {

using Mat3 = std::array<Real, 9>;
using Sym6 = std::array<Real, 6>;

inline Mat3 identity() { return {1, 0, 0, 0, 1, 0, 0, 0, 1}; }

inline Mat3 load(const Real* a)
{
    return {a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8]};
}

inline Mat3 symToFull(const Real* s)
{
    return {s[XX], s[XY], s[XZ],
            s[XY], s[YY], s[YZ],
            s[XZ], s[YZ], s[ZZ]};
}

// Stores the symmetric part of a full tensor, so round-off asymmetry of
// products such as W*sigma - sigma*W never leaks into the stored stress.
inline void storeSym(const Mat3& A, Real* s)
{
    s[XX] = A[ij(0, 0)];
    s[YY] = A[ij(1, 1)];
    s[ZZ] = A[ij(2, 2)];
    s[XY] = 0.5*(A[ij(0, 1)] + A[ij(1, 0)]);
    s[YZ] = 0.5*(A[ij(1, 2)] + A[ij(2, 1)]);
    s[XZ] = 0.5*(A[ij(0, 2)] + A[ij(2, 0)]);
}

inline Sym6 symPart(const Real* A)
{
    Sym6 s;
    storeSym(load(A), s.data());
    return s;
}

inline Mat3 skewPart(const Real* A)
{
    Mat3 W;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            W[ij(i, j)] = 0.5*(A[ij(i, j)] - A[ij(j, i)]);
    return W;
}

inline Mat3 mul(const Mat3& A, const Mat3& B)
{
    Mat3 C{};
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 3; ++j)
                C[ij(i, j)] += A[ij(i, k)]*B[ij(k, j)];
    return C;
}

// A A^T (e.g. the left Cauchy-Green tensor B = F F^T), symmetric.
inline Sym6 selfOuterT(const Real* A)
{
    auto dotRows = [A](int i, int j)
    {
        return A[ij(i, 0)]*A[ij(j, 0)] + A[ij(i, 1)]*A[ij(j, 1)] + A[ij(i, 2)]*A[ij(j, 2)];
    };
    Sym6 s;
    s[XX] = dotRows(0, 0); s[YY] = dotRows(1, 1); s[ZZ] = dotRows(2, 2);
    s[XY] = dotRows(0, 1); s[YZ] = dotRows(1, 2); s[XZ] = dotRows(0, 2);
    return s;
}

inline Real det(const Real* A)
{
    return A[0]*(A[4]*A[8] - A[5]*A[7])
         - A[1]*(A[3]*A[8] - A[5]*A[6])
         + A[2]*(A[3]*A[7] - A[4]*A[6]);
}

inline Real trace(const Real* s) { return s[XX] + s[YY] + s[ZZ]; }

// Deviatoric part of a symmetric tensor, in place.
inline void makeDeviatoric(Real* s)
{
    const Real m = trace(s)/3.0;
    s[XX] -= m; s[YY] -= m; s[ZZ] -= m;
}

// Double contraction a:b of two symmetric tensors (shears count twice).
inline Real ddot(const Real* a, const Real* b)
{
    return a[XX]*b[XX] + a[YY]*b[YY] + a[ZZ]*b[ZZ]
         + 2.0*(a[XY]*b[XY] + a[YZ]*b[YZ] + a[XZ]*b[XZ]);
}

} // namespace tensor
} // namespace mpm

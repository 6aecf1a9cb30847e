// Small 3x3 tensor helpers shared by the constitutive laws, callable on the
// host and the device (plain arrays through pointers: no std::array
// temporaries, no constexpr library calls in device code).
//
// Full tensors are row-major (T_ij at [3i+j]); symmetric tensors use the
// six-component order of types.hpp (xx yy zz xy yz xz) holding the tensor
// components themselves (no doubled engineering shears).
#pragma once
#include "../common/hostDevice.hpp"
#include "../types.hpp"
#include <cmath>

namespace mpm {
namespace tensor {

// a*b + c rounded once where the hardware fuses it (the device; the host
// built with FMA, e.g. -march=native), twice elsewhere. Written out where
// an update must not depend on where it is inlined: the compiler fuses an
// a*b + c it sees at its own choice (-ffp-contract=fast), which differs
// between call sites, but never splits or re-fuses an explicit one.
MPM_HOST_DEVICE inline Real fmadd(Real a, Real b, Real c)
{
#if defined(__CUDA_ARCH__) || defined(__FMA__)
    return std::fma(a, b, c);
#else
    return a*b + c;
#endif
}

// Symmetric part of a full tensor A into s. Also used to store a product
// such as W*sigma - sigma*W, so round-off asymmetry never leaks into the
// stored stress.
MPM_HOST_DEVICE inline void symPart(const Real* A, Real* s)
{
    s[XX] = A[0];
    s[YY] = A[4];
    s[ZZ] = A[8];
    s[XY] = 0.5*(A[1] + A[3]);
    s[YZ] = 0.5*(A[5] + A[7]);
    s[XZ] = 0.5*(A[2] + A[6]);
}

// A A^T (e.g. the left Cauchy-Green tensor B = F F^T), symmetric.
MPM_HOST_DEVICE inline Real dotRows(const Real* A, int i, int j)
{
    return A[3*i]*A[3*j] + A[3*i + 1]*A[3*j + 1] + A[3*i + 2]*A[3*j + 2];
}

MPM_HOST_DEVICE inline void selfOuterT(const Real* A, Real* s)
{
    s[XX] = dotRows(A, 0, 0); s[YY] = dotRows(A, 1, 1); s[ZZ] = dotRows(A, 2, 2);
    s[XY] = dotRows(A, 0, 1); s[YZ] = dotRows(A, 1, 2); s[XZ] = dotRows(A, 0, 2);
}

MPM_HOST_DEVICE inline Real det(const Real* A)
{
    return A[0]*(A[4]*A[8] - A[5]*A[7])
         - A[1]*(A[3]*A[8] - A[5]*A[6])
         + A[2]*(A[3]*A[7] - A[4]*A[6]);
}

MPM_HOST_DEVICE inline Real trace(const Real* s) { return s[XX] + s[YY] + s[ZZ]; }

// Deviatoric part of a symmetric tensor, in place.
MPM_HOST_DEVICE inline void makeDeviatoric(Real* s)
{
    const Real m = trace(s)/3.0;
    s[XX] -= m; s[YY] -= m; s[ZZ] -= m;
}

// Double contraction a:b of two symmetric tensors (shears count twice).
MPM_HOST_DEVICE inline Real ddot(const Real* a, const Real* b)
{
    return a[XX]*b[XX] + a[YY]*b[YY] + a[ZZ]*b[ZZ]
         + 2.0*(a[XY]*b[XY] + a[YZ]*b[YZ] + a[XZ]*b[XZ]);
}

MPM_HOST_DEVICE inline void copy6(const Real* a, Real* b)
{
    for (int c = 0; c < 6; ++c) b[c] = a[c];
}

} // namespace tensor
} // namespace mpm

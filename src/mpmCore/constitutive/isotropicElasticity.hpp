// Isotropic linear elasticity and its objective (Jaumann-rate) update, the
// elastic part shared by LinearElastic and the elastic trial of the
// plasticity models. Host and device (see lawKernels.hpp).
#pragma once
#include "../common/hostDevice.hpp"
#include "tensorOps.hpp"

namespace mpm {

// Lame coefficients of an isotropic elastic solid.
struct IsotropicElasticity
{
    Real lambda;
    Real mu;        // shear modulus G

    MPM_HOST_DEVICE static IsotropicElasticity fromYoungPoisson(Real E, Real nu)
    {
        return {E*nu/((1.0 + nu)*(1.0 - 2.0*nu)), E/(2.0*(1.0 + nu))};
    }
    MPM_HOST_DEVICE Real bulkModulus() const { return lambda + 2.0*mu/3.0; }
    MPM_HOST_DEVICE Real pWaveModulus() const { return lambda + 2.0*mu; }

    // sigma : C^-1 : sigma / 2 per unit current volume.
    MPM_HOST_DEVICE Real complementaryEnergy(const Real* s) const
    {
        const Real tr = s[XX] + s[YY] + s[ZZ];
        const Real ss = s[XX]*s[XX] + s[YY]*s[YY] + s[ZZ]*s[ZZ]
                      + 2.0*(s[XY]*s[XY] + s[YZ]*s[YZ] + s[XZ]*s[XZ]);
        return (ss - lambda/(3.0*lambda + 2.0*mu)*tr*tr)/(4.0*mu);
    }
};

// Objective (Jaumann-rate) hypoelastic update of sigma (6 components, in
// place) over one step with velocity gradient L (row-major 3x3):
//
//   sigma_{n+1} = sigma_n + dt*(C:D + W sigma_n - sigma_n W),
//   C:D = lambda tr(D) I + 2 mu D,
//
// with D, W the symmetric and skew parts of L.
//
// The spin term is evaluated as R = W S + (W S)^T: for S symmetric and W
// skew, S W = -(W S)^T holds exactly in floating point too (every product
// S_ik W_kj is -W_jk S_ki, summed in the same order), so this is the
// symmetric part of W S - S W with half the products, and the zero
// diagonal of W is not multiplied. Every multiply-add is an explicit
// tensor::fmadd, so the result does not depend on where the function is
// inlined (the elastic trial a test computes is the one inside a law) and
// the device computes the same.
MPM_HOST_DEVICE inline void jaumannElasticUpdate
(
    const IsotropicElasticity& el, const Real* L, Real dt, Real* sigma
)
{
    using tensor::fmadd;
    // W = (L - L^T)/2 above the diagonal; below it is the negative
    const Real w01 = 0.5*(L[1] - L[3]);
    const Real w02 = 0.5*(L[2] - L[6]);
    const Real w12 = 0.5*(L[5] - L[7]);
    const Real sxx = sigma[XX], syy = sigma[YY], szz = sigma[ZZ];
    const Real sxy = sigma[XY], syz = sigma[YZ], sxz = sigma[XZ];

    // (W S)_ij = sum_k W_ik S_kj over k != i
    const Real ws00 = fmadd(w02, sxz, w01*sxy);
    const Real ws01 = fmadd(w02, syz, w01*syy);
    const Real ws02 = fmadd(w02, szz, w01*syz);
    const Real ws10 = fmadd(w12, sxz, -w01*sxx);
    const Real ws11 = fmadd(w12, syz, -w01*sxy);
    const Real ws12 = fmadd(w12, szz, -w01*sxz);
    const Real ws20 = fmadd(-w12, sxy, -w02*sxx);
    const Real ws21 = fmadd(-w12, syy, -w02*sxy);
    const Real ws22 = fmadd(-w12, syz, -w02*sxz);

    Real D[6];
    tensor::symPart(L, D);
    const Real rotation[6] =
    {
        ws00 + ws00, ws11 + ws11, ws22 + ws22,
        ws01 + ws10, ws12 + ws21, ws02 + ws20
    };
    const Real lambdaTrD = el.lambda*tensor::trace(D);
    const Real twoMu = 2.0*el.mu;
    for (int a = 0; a < 3; ++a)
        sigma[a] = fmadd(dt, fmadd(twoMu, D[a], lambdaTrD) + rotation[a], sigma[a]);
    for (int a = 3; a < 6; ++a)
        sigma[a] = fmadd(dt, fmadd(twoMu, D[a], rotation[a]), sigma[a]);
}

} // namespace mpm

// Kernel body of the stress phase, one material point: the deformation
// gradient update F_new = (I + dt L) F_old, its determinant and the point's
// solid fraction, the material's law (lawKernels.hpp, a switch on its
// type), the finiteness check and the write-back of F, sigma, the plastic
// strain and the volume. Written once for every back-end; the launcher
// reduces the returned status (first bad point, inverted points).
#pragma once
#include "../common/hostDevice.hpp"
#include "../constitutive/lawKernels.hpp"
#include "views.hpp"
#include <cmath>

namespace mpm {

enum class StressPointStatus : unsigned char
{
    ok,         // updated
    bad,        // non-finite stress, plastic strain or F: nothing written
    inverted    // updated, but J <= 0 or the volume is not positive
};

// P.L holds the step's velocity gradient; laws[m] is material m's law.
MPM_HOST_DEVICE inline StressPointStatus stressPoint
(
    const PointView& P, const LawParams* laws, Real dt, Index p
)
{
    const LawParams& law = laws[P.material[p]];
    Real Lp[9], Fo[9], Fn[9], sig[6];
    for (int e = 0; e < 9; ++e) Fo[e] = P.F[e][p];
    if (law.deforms)
    {
        Real dtL[9];
        for (int e = 0; e < 9; ++e) { Lp[e] = P.L[e][p]; dtL[e] = dt*Lp[e]; }
        // F_{n+1} = (I + dt L) F_n
        for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
        {
            Real s = Fo[3*i + j];
            for (int k = 0; k < 3; ++k) s += dtL[3*i + k]*Fo[3*k + j];
            Fn[3*i + j] = s;
        }
    }
    else
    {
        // A law without deformation (dilute grains) sees L = 0: F is kept
        // (at identity), and the product (I + 0) F is skipped.
        for (int e = 0; e < 9; ++e) { Lp[e] = 0; Fn[e] = Fo[e]; }
    }
    for (int c = 0; c < 6; ++c) sig[c] = P.sigma[c][p];
    // Work a law does not need is skipped: the plastic strain of elastic
    // laws (neither read nor written), the solid fraction's division.
    const bool plastic = changesPlasticStrain(law.type);
    Real ep = plastic ? P.eqPlasticStrain[p] : Real(0);
    const Real Jn = tensor::det(Fn);
    const Real solidFraction =
        readsSolidFraction(law.type) ? P.mass[p]/(law.rho0*P.volume0[p]*Jn) : Real(1);
    const PointKinematics k{Lp, Fo, Fn, dt, solidFraction};
    PointStress st{sig, plastic ? &ep : nullptr};
    updateStress(law, k, st);

    bool finite = std::isfinite(ep);
    for (int c = 0; c < 6; ++c) finite = finite && std::isfinite(sig[c]);
    for (int e = 0; e < 9; ++e) finite = finite && std::isfinite(Fn[e]);
    if (!finite) return StressPointStatus::bad;

    for (int e = 0; e < 9; ++e) P.F[e][p] = Fn[e];
    for (int c = 0; c < 6; ++c) P.sigma[c][p] = sig[c];
    if (plastic) P.eqPlasticStrain[p] = ep;
    P.volume[p] = P.volume0[p]*Jn;
    return Jn <= 0 || P.volume[p] <= 0 ? StressPointStatus::inverted : StressPointStatus::ok;
}

} // namespace mpm

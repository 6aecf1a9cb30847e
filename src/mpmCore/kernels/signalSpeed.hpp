// Kernel body of the Courant number's signal speed of one material point:
// its law's wave speed at its volume ratio J, for a parcel lighter than its
// law's reference density (grains in a fluid: mass = rho0 solidFraction V0)
// faster by sqrt(rho0 V0 / mass), plus its speed |v|. The host's
// maxSignalSpeed (phases/timeStepLimit.hpp) and the resident device step
// reduce it with max.
#pragma once
#include "../constitutive/lawKernels.hpp"
#include "views.hpp"
#include <cmath>

namespace mpm {

MPM_HOST_DEVICE inline Real signalSpeedPoint(const PointView& P, const LawParams* laws, Index p)
{
    const LawParams& law = laws[P.material[p]];
    const Real v2 = P.v[0][p]*P.v[0][p] + P.v[1][p]*P.v[1][p] + P.v[2][p]*P.v[2][p];
    const Real a = P.F[0][p], b = P.F[1][p], c = P.F[2][p];
    const Real d = P.F[3][p], e = P.F[4][p], f = P.F[5][p];
    const Real g = P.F[6][p], h = P.F[7][p], i = P.F[8][p];
    const Real J = a*(e*i - f*h) - b*(d*i - f*g) + c*(d*h - e*g);
    const Real lighter = std::sqrt(law.rho0*P.volume0[p]/P.mass[p]);
    return lawWaveSpeed(law, J)*lighter + std::sqrt(v2);
}

} // namespace mpm

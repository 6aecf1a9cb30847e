// Per-point stress update of NeoHookean (host and device):
//   sigma = (mu/J)(B - I) + (lambda ln J / J) I,   B = F F^T,  J = det F.
#pragma once
#include "isotropicElasticity.hpp"
#include "pointState.hpp"
#include <cmath>

namespace mpm {

struct NeoHookeanParams
{
    IsotropicElasticity el;
};

MPM_HOST_DEVICE inline void neoHookeanStress
(
    const NeoHookeanParams& c, const PointKinematics& k, PointStress& s
)
{
    const Real J = tensor::det(k.Fnew);
    Real B[6];
    tensor::selfOuterT(k.Fnew, B);
    const Real muOverJ = c.el.mu/J;
    const Real volumetric = c.el.lambda*std::log(J)/J;
    for (int a = 0; a < 6; ++a) s.sigma[a] = muOverJ*B[a];
    for (int a = 0; a < 3; ++a) s.sigma[a] += volumetric - muOverJ;
}

} // namespace mpm

// Per-point stress update of NewtonianFluid (host and device):
//   p = K (J^-gamma - 1),   sigma = -p I + 2 mu dev(D).
#pragma once
#include "../common/hostDevice.hpp"
#include "pointState.hpp"
#include "tensorOps.hpp"
#include <cmath>

namespace mpm {

struct NewtonianFluidParams
{
    Real K;       // Tait coefficient
    Real gamma;   // Tait exponent
    Real mu;      // dynamic viscosity
};

MPM_HOST_DEVICE inline Real newtonianFluidPressure(const NewtonianFluidParams& c, Real J)
{
    return c.K*(std::pow(J, -c.gamma) - 1.0);
}

MPM_HOST_DEVICE inline void newtonianFluidStress
(
    const NewtonianFluidParams& c, const PointKinematics& k, PointStress& s
)
{
    Real devD[6];
    tensor::symPart(k.L, devD);
    tensor::makeDeviatoric(devD);
    const Real p = newtonianFluidPressure(c, tensor::det(k.Fnew));
    for (int a = 0; a < 6; ++a) s.sigma[a] = 2.0*c.mu*devD[a];
    for (int a = 0; a < 3; ++a) s.sigma[a] -= p;
}

} // namespace mpm

// Per-point stress update of LinearElastic (host and device).
#pragma once
#include "isotropicElasticity.hpp"
#include "pointState.hpp"

namespace mpm {

struct LinearElasticParams
{
    IsotropicElasticity el;
};

MPM_HOST_DEVICE inline void linearElasticStress
(
    const LinearElasticParams& c, const PointKinematics& k, PointStress& s
)
{
    jaumannElasticUpdate(c.el, k.L, k.dt, s.sigma);
}

} // namespace mpm

// Per-point stress update of Dilute: stress-free grains (host and device).
#pragma once
#include "../common/hostDevice.hpp"
#include "pointState.hpp"

namespace mpm {

MPM_HOST_DEVICE inline void diluteStress(const PointKinematics&, PointStress& s)
{
    for (int a = 0; a < 6; ++a) s.sigma[a] = 0;
}

} // namespace mpm

#include "timeStepLimit.hpp"
#include "../kernels/signalSpeed.hpp"
#include <algorithm>
#include <limits>

namespace mpm {

Real maxSignalSpeed(const SystemState& s)
{
    // Resident points: reduced on the device, the host's copy being stale
    if (s.deviceAhead) return s.maxAll(s.resident->maxSignalSpeed());
    const std::vector<LawParams> laws = s.lawTable();
    const PointView P = const_cast<SystemState&>(s).points();   // read only
    const Index n = P.n;
    Real cmax = 0;
    #pragma omp parallel for reduction(max:cmax) if(s.worthThreads(n))
    for (Index p = 0; p < n; ++p) cmax = std::max(cmax, signalSpeedPoint(P, laws.data(), p));
    return s.maxAll(cmax);
}

Real stableDeltaT(const SystemState& s, Real courant)
{
    const Real c = maxSignalSpeed(s);
    Real dt = c > 0 ? courant*s.lattice.h/c : std::numeric_limits<Real>::infinity();
    for (const auto& m : s.materials) dt = std::min(dt, m->maxStableDt(s.lattice.h));
    return dt;
}

} // namespace mpm

#include "stress.hpp"
#include "../kernels/stressPoint.hpp"
#include <algorithm>

namespace mpm {

void updateStress(SystemState& s, Real dt)
{
    const Index n = s.particles.size();
    const std::vector<LawParams> laws = s.lawTable();
    const LawParams* table = laws.data();
    const PointView view = s.points();
    Index firstBad = n;
    Index nInverted = 0;
    #pragma omp parallel for schedule(static) reduction(min:firstBad) reduction(+:nInverted) if(s.worthThreads(n))
    for (Index p = 0; p < n; ++p)
    {
        const StressPointStatus status = stressPoint(view, table, dt, p);
        if (status == StressPointStatus::bad) firstBad = std::min(firstBad, p);
        else if (status == StressPointStatus::inverted) ++nInverted;
    }
    s.stopIfNonFinite(firstBad, "stress or deformation");
    s.inverted = InvertedPoints{};
    s.inverted.count = nInverted;
    if (nInverted > 0) s.findFirstInverted();
}

} // namespace mpm

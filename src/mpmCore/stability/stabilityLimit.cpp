#include "stabilityLimit.hpp"
#include "fourierSymbol.hpp"
#include <cmath>

namespace mpm {
namespace stability {

LimitOptions defaultLimitOptions(Model m)
{
    LimitOptions o;
    // Explicit limits are O(1): Fo up to ~2, CFL up to ~1.5 for these schemes.
    o.maxNumber = (m == Model::diffusion ? 8.0 : 4.0);
    return o;
}

bool isStable(const AnalysisSetup& s, Real number, const LimitOptions& o)
{
    return maxSpectralRadius(s, number, o.thetaIntervals) <= 1.0 + o.slack;
}

StabilityLimit stabilityLimit(const AnalysisSetup& s, const LimitOptions& o)
{
    return stabilityLimit([&](Real p) { return isStable(s, p, o); }, o);
}

StabilityLimit stabilityLimit(const std::function<bool(Real)>& stable, const LimitOptions& o)
{
    StabilityLimit result;
    Real lo = 0, hi = -1;
    for (int i = 1; i <= o.scanPoints; ++i)
    {
        const Real p = o.maxNumber*i/o.scanPoints;
        if (!stable(p)) { hi = p; break; }
        lo = p;
    }
    if (hi < 0) { result.limit = o.maxNumber; result.reachedMax = true; return result; }
    // Bisection keeps lo stable and hi unstable.
    while (hi - lo > o.relTolerance*hi && hi > 1e-14*o.maxNumber)
    {
        const Real mid = 0.5*(lo + hi);
        (stable(mid) ? lo : hi) = mid;
    }
    result.limit = lo;
    return result;
}

std::vector<std::pair<Real, StabilityLimit>>
limitVersusShift(const AnalysisSetup& s, const std::vector<Real>& shifts, const LimitOptions& o)
{
    std::vector<std::pair<Real, StabilityLimit>> out;
    for (Real shift : shifts)
    {
        AnalysisSetup t = s;
        for (Real& off : t.offsets) off = off + shift - std::floor(off + shift);
        out.emplace_back(shift, stabilityLimit(t, o));
    }
    return out;
}

} // namespace stability
} // namespace mpm

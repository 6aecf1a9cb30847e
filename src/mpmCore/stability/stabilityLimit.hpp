// Stability limit: the largest Fo (diffusion) or CFL (wave) such that every
// mode has spectral radius <= 1 + slack, searched as the right end of the
// stable interval that starts at 0.
//
// The stable set need not be an interval, so "the limit" is defined as
//   sup { p : maxSpectralRadius(p') <= 1 + slack for every p' in (0, p] }
// and found by scanning p = maxNumber i/scanPoints upwards until the first
// unstable value, then bisecting between it and the last stable one. A
// stable island narrower than the scan step beyond the first instability is
// ignored by design (it is not usable as a time-step rule anyway).
#pragma once
#include "stabilitySetup.hpp"
#include <functional>
#include <utility>

namespace mpm {
namespace stability {

struct LimitOptions
{
    Real maxNumber = 8.0;      // search range (0, maxNumber]
    int scanPoints = 400;      // coarse scan resolution
    int thetaIntervals = 360;  // kh samples in [0, pi]
    Real slack = 1e-12;        // |G| <= 1 + slack counts as stable
    Real relTolerance = 1e-10; // bisection stops at this relative bracket width
};

LimitOptions defaultLimitOptions(Model);

struct StabilityLimit
{
    Real limit = 0;            // 0: unstable for every tested p > 0
    bool reachedMax = false;   // stable on the whole range: limit >= maxNumber
};

bool isStable(const AnalysisSetup&, Real number, const LimitOptions&);
// The scan-and-bisect search above for any predicate stable(p) on
// (0, o.maxNumber] (o.thetaIntervals and o.slack are the predicate's business).
StabilityLimit stabilityLimit(const std::function<bool(Real)>& stable, const LimitOptions&);
StabilityLimit stabilityLimit(const AnalysisSetup&, const LimitOptions&);

// Limit versus position: the setup's offset pattern shifted by each `shift`
// (wrapped into [0,1)); with a single offset 0 this is the limit vs offset.
std::vector<std::pair<Real, StabilityLimit>>
limitVersusShift(const AnalysisSetup&, const std::vector<Real>& shifts, const LimitOptions&);

} // namespace stability
} // namespace mpm

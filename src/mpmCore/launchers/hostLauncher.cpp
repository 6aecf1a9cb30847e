// The serial and openmp back-ends' step: the plan's phases, each one of
// the host phases of phases/*.hpp.
#include "launchers.hpp"
#include "../phases/gather.hpp"
#include "../phases/migrate.hpp"
#include "../phases/movePoints.hpp"
#include "../phases/nodalUpdate.hpp"
#include "../phases/scatter.hpp"
#include "../phases/stress.hpp"

namespace mpm {

void stepOnHost(SystemState& s, Real dt)
{
    s.sizePointScratch();
    updateMassTolerance(s);
    const bool withForce = s.plan.forceWithScatter;
    runPlan(s.plan, s.timers, [&](Phase phase)
    {
        switch (phase)
        {
            case Phase::scatter: binPoints(s); scatterMassMomentum(s, withForce); break;
            case Phase::nodalAfterScatter: nodalAfterScatter(s, dt, withForce); break;
            case Phase::gradientFromOld: gradientFromGrid(s, s.grid.velocityOld); break;
            case Phase::stress: updateStress(s, dt); break;
            case Phase::scatterForce: scatterForce(s); break;
            case Phase::foldForce: foldScatteredForce(s); break;
            case Phase::nodalUpdate: nodalUpdate(s, dt); break;
            case Phase::gather: gather(s, dt); break;
            case Phase::remapMomentum: remapMomentum(s); break;
            case Phase::nodalAfterRemap: nodalAfterRemap(s); break;
            case Phase::gradientFromNew: gradientFromGrid(s, s.grid.velocity); break;
            case Phase::move: movePoints(s, dt); break;
            case Phase::migrate: migrate(s); break;
        }
    }, s.recordPhases);
}

} // namespace mpm

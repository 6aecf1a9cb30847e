// The serial and openmp back-ends' step: the plan's phases, each one of
// the host phases of phases/*.hpp.
#include "launchers.hpp"
#include "../phases/gather.hpp"
#include "../phases/halo.hpp"
#include "../phases/migrate.hpp"
#include "../phases/movePoints.hpp"
#include "../phases/nodalUpdate.hpp"
#include "../phases/scatter.hpp"
#include "../phases/stress.hpp"
#include "../phases/walls.hpp"

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
            case Phase::scatter: binPoints(s); scatter(s, {true, withForce, false}); break;
            case Phase::nodalAfterScatter: nodalAfterScatter(s, dt, withForce); break;
            case Phase::gradientFromOld: gradientFromGrid(s, s.grid.velocityOld); break;
            case Phase::stress: updateStress(s, dt); break;
            // The internal force, added to the gravity already there
            case Phase::scatterForce: scatter(s, {false, true, false}); break;
            case Phase::foldForce: sumHalo(s, foldForce); foldGhosts(s, foldForce); break;
            case Phase::nodalUpdate: nodalUpdate(s, dt); break;
            case Phase::gather: gather(s, dt); break;
            case Phase::remapMomentum: scatter(s, {false, false, true}); break;
            case Phase::nodalAfterRemap: nodalAfterRemap(s); break;
            case Phase::gradientFromNew: gradientFromGrid(s, s.grid.velocity); break;
            case Phase::move: movePoints(s, dt); break;
            case Phase::migrate: migrate(s); break;
        }
    }, s.recordPhases);
}

} // namespace mpm

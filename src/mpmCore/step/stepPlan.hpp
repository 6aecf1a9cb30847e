// The phase order of one MPM step, as data: built once from the step's
// options, logged at start-up, and run by every back-end's launcher
// (launchers/launchers.hpp: the host phases, the host-assisted cuda
// phases, the resident device step of backend/residentStep.hpp). No
// back-end writes the order itself, so a change to it (a USF, USL or MUSL
// detail) is made once here.
//
//   USF   scatter  nodalAfterScatter  gradientFromOld  stress  scatterForce
//         foldForce  nodalUpdate  gather  move  migrate
//   USL   scatter+f  nodalAfterScatter  nodalUpdate  gather  stress  move
//         migrate
//   MUSL  scatter+f  nodalAfterScatter  nodalUpdate  gather  remapMomentum
//         nodalAfterRemap  gradientFromNew  stress  move  migrate
//
// (+f: the fresh P2G scatters the internal force with the mass and
// momentum.) The halo of decomposed and periodic runs is summed inside the
// nodal phases that follow a scatter (the seam "halo sum") and copied
// inside those that set a velocity (the seam "halo copy"); migration is the
// step's last phase.
#pragma once
#include "stepOptions.hpp"
#include "stepTimers.hpp"
#include <string>
#include <vector>

namespace mpm {

enum class Phase
{
    scatter,            // bin the points; P2G of mass, volume, momentum (+ force)
    nodalAfterScatter,  // gravity, halo sum, ghost folds, contact, v^n
    gradientFromOld,    // USF: the velocity gradient from v^n
    stress,             // the constitutive update of every point
    scatterForce,       // USF: P2G of the internal force
    foldForce,          // USF: halo sum and ghost fold of that force
    nodalUpdate,        // (M + D) v = p + dt f, walls, friction, ghosts
    gather,             // G2P: point velocity, displacement, gradient
    remapMomentum,      // MUSL: P2G of the new point momentum
    nodalAfterRemap,    // MUSL: its velocity, walls, ghosts
    gradientFromNew,    // MUSL: the velocity gradient from that velocity
    move,               // advance the points; walls, open faces, NaN stop
    migrate             // decomposed runs: points to their owners
};

const char* phaseName(Phase p);

// The timer a phase's time adds to (StepTimers' categories), and the one
// its halo time adds to (StepTimers::haloIn)
double& phaseTimer(StepTimers& t, Phase p);
double& haloTimer(StepTimers& t, Phase p);

struct StepPlan
{
    std::vector<Phase> phases;
    // The fresh P2G scatters the internal force too (USL, MUSL)
    bool forceWithScatter = true;

    // "scatter+force nodalAfterScatter ..." for the start-up log
    std::string describe() const;
};

StepPlan makeStepPlan(const StepOptions& options);

// Runs the plan: launcher(phase) for each phase in order, its time added to
// the phase's timer; record (tests): each phase appended as it starts
template<class Launcher>
void runPlan(const StepPlan& plan, StepTimers& timers, Launcher&& launcher, std::vector<Phase>* record = nullptr)
{
    for (const Phase p : plan.phases)
    {
        if (record) record->push_back(p);
        const double halo0 = timers.halo;
        {
            ScopedTimer t(phaseTimer(timers, p));
            launcher(p);
        }
        if (timers.halo != halo0) haloTimer(timers, p) += timers.halo - halo0;
    }
}

} // namespace mpm

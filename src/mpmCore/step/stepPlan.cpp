#include "stepPlan.hpp"

namespace mpm {

const char* phaseName(Phase p)
{
    switch (p)
    {
        case Phase::scatter: return "scatter";
        case Phase::nodalAfterScatter: return "nodalAfterScatter";
        case Phase::gradientFromOld: return "gradientFromOld";
        case Phase::stress: return "stress";
        case Phase::scatterForce: return "scatterForce";
        case Phase::foldForce: return "foldForce";
        case Phase::nodalUpdate: return "nodalUpdate";
        case Phase::gather: return "gather";
        case Phase::remapMomentum: return "remapMomentum";
        case Phase::nodalAfterRemap: return "nodalAfterRemap";
        case Phase::gradientFromNew: return "gradientFromNew";
        case Phase::move: return "move";
        case Phase::migrate: return "migrate";
    }
    return "?";
}

double& phaseTimer(StepTimers& t, Phase p)
{
    switch (p)
    {
        case Phase::scatter:
        case Phase::scatterForce:
        case Phase::remapMomentum: return t.p2g;
        case Phase::nodalAfterScatter:
        case Phase::foldForce:
        case Phase::nodalUpdate:
        case Phase::nodalAfterRemap: return t.nodal;
        case Phase::stress: return t.constitutive;
        case Phase::migrate: return t.migration;
        case Phase::gradientFromOld:
        case Phase::gather:
        case Phase::gradientFromNew:
        case Phase::move: break;
    }
    return t.g2p;
}

double& haloTimer(StepTimers& t, Phase p)
{
    const double* phase = &phaseTimer(t, p);
    if (phase == &t.p2g) return t.haloIn.p2g;
    if (phase == &t.nodal) return t.haloIn.nodal;
    if (phase == &t.constitutive) return t.haloIn.constitutive;
    return t.haloIn.g2p;   // g2p, and migration (no halo)
}

StepPlan makeStepPlan(const StepOptions& options)
{
    StepPlan plan;
    using P = Phase;
    switch (options.stressUpdate)
    {
        case StressUpdate::USF:
            plan.forceWithScatter = false;
            plan.phases = {P::scatter, P::nodalAfterScatter, P::gradientFromOld, P::stress,
                           P::scatterForce, P::foldForce, P::nodalUpdate, P::gather};
            break;
        case StressUpdate::USL:
            plan.phases = {P::scatter, P::nodalAfterScatter, P::nodalUpdate, P::gather, P::stress};
            break;
        case StressUpdate::MUSL:
            plan.phases = {P::scatter, P::nodalAfterScatter, P::nodalUpdate, P::gather,
                           P::remapMomentum, P::nodalAfterRemap, P::gradientFromNew, P::stress};
            break;
    }
    plan.phases.push_back(P::move);
    plan.phases.push_back(P::migrate);
    return plan;
}

std::string StepPlan::describe() const
{
    std::string s;
    for (const Phase p : phases)
    {
        if (!s.empty()) s += ' ';
        s += phaseName(p);
        if (p == Phase::scatter && forceWithScatter) s += "+force";
    }
    return s;
}

} // namespace mpm

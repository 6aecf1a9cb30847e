// The timed loop every step benchmark runs: warm-up steps, then `steps`
// steps of dt timed by the wall clock and by the step's own phase timers.
#pragma once
#include "step/mpmSystem.hpp"
#include <chrono>
#include <ctime>

namespace mpm::bench {

struct TimedSteps
{
    double seconds = 0;       // wall time of the timed steps
    // CPU time of the process over the timed steps (all threads): on a
    // shared machine the wall clock also counts other processes' slices
    double cpuSeconds = 0;
    StepTimers phases;        // the phase timers over the timed steps only
};

inline double processCpuSeconds()
{
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9*double(t.tv_nsec);
}

inline TimedSteps timeSteps(MpmSystem& s, Real dt, int warmup, int steps)
{
    for (int i = 0; i < warmup; ++i) s.step(dt);
    const StepTimers t0 = s.timers();
    const auto start = std::chrono::steady_clock::now();
    const double cpu0 = processCpuSeconds();
    for (int i = 0; i < steps; ++i) s.step(dt);
    TimedSteps r;
    r.cpuSeconds = processCpuSeconds() - cpu0;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const StepTimers& t = s.timers();
    r.phases.p2g = t.p2g - t0.p2g;
    r.phases.nodal = t.nodal - t0.nodal;
    r.phases.g2p = t.g2p - t0.g2p;
    r.phases.constitutive = t.constitutive - t0.constitutive;
    r.phases.migration = t.migration - t0.migration;
    r.phases.halo = t.halo - t0.halo;
    return r;
}

} // namespace mpm::bench

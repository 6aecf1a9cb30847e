// Particle throughput of the MPM step: a 3D elastic block, 32^3 cells,
// 8 points per cell (262144 points), linear-elastic, gravity, USL, FLIP 0.99.
// Prints particle-steps/s for LH, QBS and CBS at 1 and 2 OpenMP threads, all
// in one run so the ratios share the machine's state, the stress phase's
// time per step, and the achieved fraction of the machine's ceilings
// (ceilings.hpp, measured at the start of the run): bytes and flops per
// point-step counted as stepCost.hpp says, times the point-step rate, over
// the triad bandwidth and the FMA peak at the same thread count. Where the
// build has the cuda back-end and a GPU is present, it then prints a cuda
// row per shape function with its ratio to 1 CPU thread (measured again
// next to it); otherwise it says why there is none.
//
//   build/benchmarks/particleThroughput [cells=32] [steps=20] [shuffle=0] [reorder=1]
#include "constitutive/constitutiveLaw.hpp"
#include "step/mpmSystem.hpp"
#include "ceilings.hpp"
#include "machine.hpp"
#include "stepCost.hpp"
#include "timedSteps.hpp"
#include "elasticBlock.hpp"
#include <algorithm>
#include <random>
#include <cstdio>
#include <cstdlib>
#include <omp.h>
#include <string>

using namespace mpm;

int main(int argc, char** argv)
{
    const int n = argc > 1 ? std::atoi(argv[1]) : 32;
    const int steps = argc > 2 ? std::atoi(argv[2]) : 20;
    // Optional: 1 to shuffle the points' storage order first (points after
    // long mixing), and 0 to switch off StepOptions::reorderPoints
    const bool shuffle = argc > 3 && std::atoi(argv[3]) != 0;
    const bool reorder = argc > 4 ? std::atoi(argv[4]) != 0 : true;
    std::printf("# particleThroughput: 3D elastic block of %d^3 cells in a %d^3 lattice, 8 points/cell%s%s\n",
                n, n + 8, shuffle ? ", points stored in random order" : "",
                reorder ? "" : ", reorderPoints off");
    double load[3] = {0, 0, 0};
    if (getloadavg(load, 3) < 0) load[0] = -1;
    std::printf("# machine: %s, load average %.2f (other work skews 2-thread runs most)\n",
                bench::machine().c_str(), load[0]);
    // cpu: point-steps per CPU second of one thread (1 thread: the CPU time,
    // the figure that survives a shared machine; 2: the CPU time / 2)
    const int maxThreads = omp_get_num_procs() < 2 ? 1 : 2;
    double bandwidth[3] = {0, 0, 0}, peak[3] = {0, 0, 0};
    for (int t = 1; t <= maxThreads; ++t)
    {
        bandwidth[t] = bench::triadBandwidth(t);
        peak[t] = bench::fmaPeak(t);
        std::printf("# ceilings at %d thread(s): triad %.2f GB/s, FMA peak %.2f GFLOP/s (ceilings.hpp)\n",
                    t, bandwidth[t], peak[t]);
    }
    std::printf("%-18s %8s %10s %12s %14s %11s %10s %10s %10s %10s %10s %9s %9s %7s %7s %7s %9s\n", "shape", "threads",
                "points", "ms/step", "Mpoint-step/s", "cpu Mpt-s/s", "P2G%", "nodal%", "G2P%", "stress%", "stress-ms",
                "B/pt-step", "fl/pt-step", "GB/s", "%triad", "%peak", "P2G loop");
    for (auto shape : {ShapeKind::linearHat, ShapeKind::quadraticBSpline, ShapeKind::cubicBSpline})
    for (int threads = 1; threads <= maxThreads; ++threads)
    {
        omp_set_num_threads(threads);
        MpmSystem s = bench::makeBlock(shape, n, reorder, shuffle);
        // warm-up: first-touch allocation and the P2G loop's timing trials
        const bench::TimedSteps r = bench::timeSteps(s, s.stableDeltaT(0.5), P2gRowChoice::tuningSteps, steps);
        const double sec = r.seconds;
        const StepTimers& t = r.phases;
        const double tot = t.total();
        const double rate = s.particles().size()*double(steps)/sec;     // point-steps/s
        const bench::StepCost cost = bench::stepCost(shape, s.particles().size(), s.activeNodeCount());
        // P2G loop: the one the first steps' timing chose (step/p2gRowChoice.hpp)
        std::printf("%-18s %8d %10lld %12.2f %14.3f %11.3f %10.1f %10.1f %10.1f %10.1f %10.2f %9.0f %9.0f %7.2f %7.1f %7.1f %9s\n",
                    shapeName(shape), threads, (long long)s.particles().size(), 1e3*sec/steps, rate/1e6,
                    s.particles().size()*double(steps)/(r.cpuSeconds/threads)/1e6,
                    100*t.p2g/tot, 100*t.nodal/tot, 100*t.g2p/tot, 100*t.constitutive/tot,
                    1e3*t.constitutive/steps, cost.bytes, cost.flops, cost.bytes*rate/1e9,
                    100*cost.bytes*rate/1e9/bandwidth[threads], 100*cost.flops*rate/1e9/peak[threads],
                    s.p2gRowChoice().chosenRows() ? "rows" : "nodes");
    }
    // The cuda back-end (docs/gpu.md): the point work on the GPU, the node
    // work and the transfers' packing on 1 CPU thread
    const std::string noGpu = backendUnavailableReason(Backend::cuda);
    if (!noGpu.empty())
    {
        std::printf("# no cuda rows: %s\n", noGpu.c_str());
        return 0;
    }
    std::printf("%-18s %8s %10s %12s %14s %10s %10s %10s %10s %9s\n", "shape", "backend", "points",
                "ms/step", "Mpoint-step/s", "P2G%", "nodal%", "G2P%", "stress%", "x1thread");
    omp_set_num_threads(1);
    for (auto shape : {ShapeKind::linearHat, ShapeKind::quadraticBSpline, ShapeKind::cubicBSpline})
    {
        double cpuRate = 0;
        for (Backend b : {Backend::serial, Backend::cuda})
        {
            MpmSystem s = bench::makeBlock(shape, n, reorder, shuffle, b);
            const bench::TimedSteps r = bench::timeSteps(s, s.stableDeltaT(0.5), P2gRowChoice::tuningSteps, steps);
            const StepTimers& t = r.phases;
            const double tot = t.total();
            const double rate = s.particles().size()*double(steps)/r.seconds/1e6;
            if (b == Backend::serial) cpuRate = rate;
            std::printf("%-18s %8s %10lld %12.2f %14.3f %10.1f %10.1f %10.1f %10.1f %9.2f\n", shapeName(shape),
                        backendName(b), (long long)s.particles().size(), 1e3*r.seconds/steps, rate,
                        100*t.p2g/tot, 100*t.nodal/tot, 100*t.g2p/tot, 100*t.constitutive/tot, rate/cpuRate);
        }
    }
    return 0;
}

// GPU throughput of the MPM step against the host, in one run: the 3D elastic
// block of particleThroughput (elasticBlock.hpp; 64^3 cells: 2.1 M points),
// per shape function, stepped by
//   serial     one host thread
//   openmp     every host core
//   cuda-host  the host-assisted cuda step (backend/deviceStep.hpp: points
//              up and down every step, node work on the host)
//   cuda-atom  the resident cuda step (backend/residentStep.hpp), P2G with
//              one atomic per point and node
//   cuda       the resident cuda step, P2G atomics pre-reduced over the
//              warp's points of one stencil (the default)
// with the ratios to one thread and to every core, and for the cuda rows
// the achieved memory traffic (stepCost.hpp's model of bytes per
// point-step, the grid counted once per node) as a fraction of the card's
// triad bandwidth measured at the start. Prints why there are no cuda rows
// where the build or the machine has no GPU.
//
//   build/benchmarks/gpuThroughput [cells=64] [steps=10]
#include "elasticBlock.hpp"
#include "machine.hpp"
#include "stepCost.hpp"
#include "timedSteps.hpp"
#include <cstdio>
#include <cstdlib>
#include <omp.h>
#include <string>

using namespace mpm;

int main(int argc, char** argv)
{
    const int n = argc > 1 ? std::atoi(argv[1]) : 64;
    const int steps = argc > 2 ? std::atoi(argv[2]) : 10;
    const int cores = omp_get_num_procs();
    std::printf("# gpuThroughput: 3D elastic block of %d^3 cells, 8 points/cell, USL FLIP 0.99, lumped mass,"
                " double precision, %d timed steps\n", n, steps);
    std::printf("# host: %s, %d cores\n", bench::machine().c_str(), cores);
    const std::string noGpu = backendUnavailableReason(Backend::cuda);
    double triad = 0;
#ifdef MPM_HAVE_CUDA
    if (noGpu.empty())
    {
        triad = cudaTriadBandwidth();
        std::printf("# device: %s, triad bandwidth %.0f GB/s\n", cudaDeviceDescription().c_str(), triad);
    }
#endif
    if (!noGpu.empty()) std::printf("# no cuda rows: %s\n", noGpu.c_str());
    std::printf("%-18s %10s %8s %10s %10s %14s %9s %9s %9s %8s %7s\n", "shape", "step", "threads", "points",
                "ms/step", "Mpoint-step/s", "x1thread", "xcores", "B/pt-step", "GB/s", "%triad");
    for (auto shape : {ShapeKind::linearHat, ShapeKind::quadraticBSpline, ShapeKind::cubicBSpline})
    {
        double one = 0, all = 0;
        for (int row = 0; row < 5; ++row)
        {
            if (row >= 2 && !noGpu.empty()) break;
            const Backend b = row == 0 ? Backend::serial : row == 1 ? Backend::openmp : Backend::cuda;
            omp_set_num_threads(row == 1 ? cores : 1);
            MpmSystem s = bench::makeBlock(shape, n, true, false, b, row >= 3, row == 4);
            const bench::TimedSteps r = bench::timeSteps(s, s.stableDeltaT(0.5), P2gRowChoice::tuningSteps, steps);
            const Index points = s.particles().size();
            const double rate = points*double(steps)/r.seconds;
            if (row == 0) one = rate;
            if (row == 1) all = rate;
            const char* const names[] = {"serial", "openmp", "cuda-host", "cuda-atom", "cuda"};
            const char* name = names[row];
            if (row >= 3 && !s.lastStepResident())
            {
                std::printf("# the resident step did not run: %s\n", s.residentUnsupported().c_str());
            }
            std::printf("%-18s %10s %8d %10lld %10.2f %14.1f %9.2f", shapeName(shape), name,
                        row == 1 ? cores : 1, (long long)points, 1e3*r.seconds/steps, rate/1e6, rate/one);
            if (all > 0) std::printf(" %9.2f", rate/all);
            else std::printf(" %9s", "-");
            if (row >= 3)
            {
                // Resident: the dense grid's every node is touched each step
                const bench::StepCost cost = bench::stepCost(shape, points, s.lattice().nNodes);
                const double gbs = cost.bytes*rate/1e9;
                std::printf(" %9.0f %8.0f %7.1f", cost.bytes, gbs, triad > 0 ? 100*gbs/triad : 0.0);
            }
            std::printf("\n");
        }
    }
    return 0;
}

// The machine's ceilings for the step benchmarks (ceilings.hpp): memory
// bandwidth by a STREAM triad and the double-precision FMA peak, at 1 and 2
// threads, with how each was measured.
//
//   build/benchmarks/machineCeilings
#include "ceilings.hpp"
#include "machine.hpp"
#include <cstdio>

using namespace mpm;

int main()
{
    double load[3] = {0, 0, 0};
    if (getloadavg(load, 3) < 0) load[0] = -1;
    std::printf("# machineCeilings\n# machine: %s, load average %.2f (other work lowers both)\n",
                bench::machine().c_str(), load[0]);
    const std::size_t n = bench::triadElements();
    std::printf("# bandwidth: STREAM triad a = b + s c, 3 arrays of %zu doubles (%.0f MiB each), "
                "best of 6 passes, 24 bytes per element (write-allocate not counted)\n",
                n, n*8.0/(1 << 20));
    std::printf("# arithmetic: 16 independent chains x = x a + b of 8-wide double vectors in "
                "registers (fused multiply-add, -march=native), best of 3, 2 flops per FMA and lane\n");
    std::printf("# last-level cache %ld KiB (sysconf)\n", sysconf(_SC_LEVEL3_CACHE_SIZE)/1024);
    std::printf("%-10s %8s %12s %12s\n", "ceiling", "threads", "value", "unit");
    const int maxThreads = omp_get_num_procs() < 2 ? 1 : 2;
    for (int t = 1; t <= maxThreads; ++t)
        std::printf("%-10s %8d %12.2f %12s\n", "triad", t, bench::triadBandwidth(t), "GB/s");
    for (int t = 1; t <= maxThreads; ++t)
        std::printf("%-10s %8d %12.2f %12s\n", "fma", t, bench::fmaPeak(t), "GFLOP/s");
    // For comparison: the same triad on 3 x 32 MiB, about the working set
    // of particleThroughput's default block, which may be cache-resident
    // on a machine with a large last-level cache (the step's fraction of
    // the memory triad can then exceed 100 %).
    const std::size_t small = std::size_t(4) << 20;
    for (int t = 1; t <= maxThreads; ++t)
        std::printf("%-10s %8d %12.2f %12s\n", "triad96MiB", t, bench::triadBandwidth(t, 20, small), "GB/s");
    return 0;
}

// The machine's two ceilings for the step benchmarks: memory bandwidth and
// double-precision arithmetic peak, measured (not taken from data sheets),
// so the step's throughput can be put as a fraction of each.
//
//  - Bandwidth: a STREAM triad a[i] = b[i] + s c[i] over three arrays whose
//    total size is at least 4 times the last-level cache (so they come
//    from memory), best of several passes, counted as STREAM does: 24 bytes
//    per element (read b and c, write a; the write-allocate read of a is
//    not counted, as the step's traffic is not either).
//  - Arithmetic: 16 independent chains x = x*a + b on 8-wide vectors of
//    doubles, kept in registers, compiled with the core's -march=native so
//    they become fused multiply-adds on the widest vector unit; 2 flops per
//    fused multiply-add and lane. 16 chains cover the FMA latency (4..5
//    cycles) times 2 FMA ports.
#pragma once
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <omp.h>
#include <unistd.h>
#include <vector>

namespace mpm::bench {

struct Ceiling
{
    double value = 0;        // GB/s or GFLOP/s
    int threads = 1;
};

inline double secondsSince(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Elements per triad array: 4x the last-level cache over 3 arrays, at
// least 32 Mi doubles (256 MiB), at most 128 Mi doubles (1 GiB) each.
inline std::size_t triadElements()
{
    long llc = sysconf(_SC_LEVEL3_CACHE_SIZE);
    if (llc <= 0) llc = sysconf(_SC_LEVEL2_CACHE_SIZE);
    const std::size_t fromCache = llc > 0 ? std::size_t(4)*std::size_t(llc)/3/sizeof(double) : 0;
    return std::min<std::size_t>(std::max<std::size_t>(fromCache, std::size_t(32) << 20),
                                 std::size_t(128) << 20);
}

// STREAM triad bandwidth in GB/s (1e9 bytes/s) with `threads` threads, the
// best of `passes` passes; the arrays are first touched by the same threads.
// elements: per array (default triadElements(), from memory).
inline double triadBandwidth(int threads, int passes = 6, std::size_t n = triadElements())
{
    std::vector<double> a, b, c;
    a.reserve(n); b.reserve(n); c.reserve(n);
    double* pa = a.data(); double* pb = b.data(); double* pc = c.data();
    #pragma omp parallel for schedule(static) num_threads(threads)
    for (std::size_t i = 0; i < n; ++i) { pa[i] = 0; pb[i] = 1; pc[i] = 2; }
    double best = 1e300;
    const double s = 3.0;
    for (int pass = 0; pass < passes; ++pass)
    {
        const auto t0 = std::chrono::steady_clock::now();
        #pragma omp parallel for schedule(static) num_threads(threads)
        for (std::size_t i = 0; i < n; ++i) pa[i] = pb[i] + s*pc[i];
        best = std::min(best, secondsSince(t0));
    }
    if (pa[n/2] != 7.0) std::printf("# triad check failed\n");
    return 24.0*double(n)/best/1e9;
}

// Peak double-precision rate in GFLOP/s with `threads` threads, each
// running the same independent FMA chains.
inline double fmaPeak(int threads, long iterations = 200000000L/16)
{
    typedef double v8 __attribute__((vector_size(64)));
    constexpr int chains = 16;
    double sink = 0, best = 1e300;
    for (int pass = 0; pass < 3; ++pass)
    {
        const auto t0 = std::chrono::steady_clock::now();
        #pragma omp parallel num_threads(threads) reduction(+:sink)
        {
            v8 x[chains];
            const double seed = 1.0 + 1e-3*omp_get_thread_num();
            for (int c = 0; c < chains; ++c) for (int l = 0; l < 8; ++l) x[c][l] = seed + 1e-6*(8*c + l);
            // a < 1 and b = 1 - a: every chain tends to 1, no overflow,
            // no subnormals; the compiler cannot fold the recurrence.
            const v8 a = x[0]*0 + (1.0 - 1e-9), b = x[0]*0 + 1e-9;
            for (long it = 0; it < iterations; ++it)
                for (int c = 0; c < chains; ++c) x[c] = x[c]*a + b;
            for (int c = 0; c < chains; ++c) for (int l = 0; l < 8; ++l) sink += x[c][l];
        }
        best = std::min(best, secondsSince(t0));
    }
    if (sink == 0) std::printf("# fma check failed\n");
    return 2.0*8*chains*double(iterations)*threads/best/1e9;
}

} // namespace mpm::bench

// StaggeredAllocator (common/staggeredArray.hpp): arrays of one size start
// on different cache lines of a page, so that a phase streaming many of
// them at one index does not map them all to one L1 set; and the arrays
// behave as vectors (the whole length usable, copies equal, freed safely).
#include "common/staggeredArray.hpp"
#include "particles/particles.hpp"
#include <gtest/gtest.h>
#include <set>

using namespace mpm;

TEST(StaggeredArray, ArraysOfOneSizeStartOnDifferentCacheLines)
{
    // 25 arrays of 110 592 values: the stress phase's streams at the size
    // where glibc's mmap'd arrays all began at one page offset
    const std::size_t n = 110592;
    std::vector<StaggeredArray<double>> arrays(25);
    std::set<std::uintptr_t> lines;
    for (auto& a : arrays)
    {
        a.assign(n, 1.0);
        const auto address = reinterpret_cast<std::uintptr_t>(a.data());
        EXPECT_EQ(address % 64, 0u);
        lines.insert(address % 4096/64);
    }
    EXPECT_EQ(lines.size(), arrays.size());
    // Every value usable, copies equal
    for (std::size_t k = 0; k < arrays.size(); ++k)
    {
        for (std::size_t i = 0; i < n; ++i) arrays[k][i] = double(k) + 1e-6*double(i);
    }
    const StaggeredArray<double> copy = arrays[7];
    EXPECT_EQ(copy, arrays[7]);
    EXPECT_EQ(copy[n - 1], 7 + 1e-6*double(n - 1));
}

TEST(StaggeredArray, ParticleArraysAreStaggered)
{
    Particles P;
    P.resize(110592);
    std::set<std::uintptr_t> lines;
    for (const auto& a : P.F) lines.insert(reinterpret_cast<std::uintptr_t>(a.data()) % 4096/64);
    for (const auto& a : P.sigma) lines.insert(reinterpret_cast<std::uintptr_t>(a.data()) % 4096/64);
    EXPECT_EQ(lines.size(), 15u);
}

// The long per-point and per-node arrays (Particles, GridState, the step's
// point scratch) as std::vector with an allocator that starts each array at
// a different cache-line offset within a 4 KiB page.
//
// Why: glibc serves large blocks with mmap, page-aligned plus a 16-byte
// header, so every array of one size starts at the same page offset, and a
// phase that streams 20-30 such arrays at the same index (the stress update
// reads L, F, sigma, V0 and writes F, sigma, V) maps all of them to one set
// of the 12-way L1. Measured on the solver's QBS block: the stress phase
// took 64 ns per point at 102 400 points and more against 30 ns at 98 304
// and fewer, and 29 ns at 110 592 with glibc's mmap threshold raised, so
// that the arrays came from the heap (benchmarks/README.md; the set
// conflict is inferred, there are no hardware counters here). With the
// arrays staggered, 30 ns at every size, whichever way malloc serves them.
#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <vector>

namespace mpm {

template<class T>
struct StaggeredAllocator
{
    using value_type = T;
    static constexpr std::size_t line = 64, page = 4096;

    StaggeredAllocator() noexcept = default;
    template<class U> StaggeredAllocator(const StaggeredAllocator<U>&) noexcept {}

    T* allocate(std::size_t n)
    {
        // The offsets cycle through the page's 64 lines, one per allocation
        static std::atomic<unsigned> next{0};
        const std::size_t offset = line*(next.fetch_add(1, std::memory_order_relaxed) % (page/line));
        void* raw = std::malloc(n*sizeof(T) + 2*page);
        if (!raw) throw std::bad_alloc();
        // Page-aligned past room for the raw pointer, then the offset
        std::uintptr_t a = reinterpret_cast<std::uintptr_t>(raw) + sizeof(void*);
        a = (a + page - 1)/page*page + offset;
        reinterpret_cast<void**>(a)[-1] = raw;
        return reinterpret_cast<T*>(a);
    }

    void deallocate(T* p, std::size_t) noexcept
    {
        if (p) std::free(reinterpret_cast<void**>(p)[-1]);
    }
};

template<class T, class U>
bool operator==(const StaggeredAllocator<T>&, const StaggeredAllocator<U>&) noexcept { return true; }
template<class T, class U>
bool operator!=(const StaggeredAllocator<T>&, const StaggeredAllocator<U>&) noexcept { return false; }

template<class T>
using StaggeredArray = std::vector<T, StaggeredAllocator<T>>;

} // namespace mpm

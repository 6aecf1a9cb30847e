// The resident step on a GPU (residentStepImpl.hpp over CUDA): device
// buffers, one thread per item, atomicAdd where threads share a node.
// P2G adds with global atomics on points kept in binning-block order
// (MpmSystem sorts them on the host when they are uploaded), pre-reduced
// over the warp (WarpReducedAdd) or not (StepOptions::p2gWarpReduction).
#include "residentStepImpl.hpp"
#include "deviceBuffer.cuh"
#include "deviceStep.hpp"
#include "forEachOnDevice.cuh"
#include <type_traits>

namespace mpm {

namespace {

// P2G's add with the sums of a warp's points that share a stencil added
// together first. Points stored in block order come in runs of a cell's
// points, and every point of a run adds to the same nodes in the same
// order (p2gPoint's loops have no data-dependent branch), so at each add
// the run's values are summed by a segmented shuffle reduction and only
// the run's first lane issues the atomic: a cell of 8 points costs one
// atomic per node and array instead of 8. The runs are found at the first
// add, whose node is the stencil's first (equal for equal stencils).
// Lanes of a warp with all points in different stencils skip the shuffles.
struct WarpReducedAdd
{
    unsigned active = 0;
    unsigned ok = 0;       // bit s: lane + 2^s is active and in my run
    int steps = -1;        // shuffle steps (-1: runs not found yet)
    bool head = true;

    __device__ void find(Index I)
    {
        active = __activemask();
        const int lane = int(threadIdx.x & 31u);
        const Index left = __shfl_up_sync(active, I, 1);
        head = lane == 0 || !((active >> (lane - 1)) & 1u) || left != I;
        const unsigned heads = __ballot_sync(active, head);
        const unsigned upTo = lane == 31 ? 0xffffffffu : (2u << lane) - 1u;
        const int run = __popc(heads & upTo);
        steps = 0;
        for (int s = 0; s < 5; ++s)
        {
            const int off = 1 << s;
            const int other = __shfl_down_sync(active, run, off);
            const bool same = lane + off < 32 && ((active >> (lane + off)) & 1u) && other == run;
            if (same) ok |= 1u << s;
            if (__ballot_sync(active, same)) steps = s + 1;
        }
    }

    __device__ void operator()(Real* a, Index I, Real x)
    {
        if (steps < 0) find(I);
        for (int s = 0; s < steps; ++s)
        {
            const Real y = __shfl_down_sync(active, x, 1 << s);
            if (ok & (1u << s)) x += y;
        }
        if (head) atomicAdd(a + I, x);
    }
};

// The atomics (add, min, max, count) are cuda::Atomics'
struct CudaExec : cuda::Atomics
{
    template<bool Warp> using P2gAdd = std::conditional_t<Warp, WarpReducedAdd, cuda::AtomicAdd>;

    template<class T> using Buffer = cuda::DeviceBuffer<T>;

    template<class T> static void copyToDevice(T* d, const T* h, std::size_t n)
    {
        if (n) cuda::cudaCheck(cudaMemcpy(d, h, n*sizeof(T), cudaMemcpyHostToDevice), "cudaMemcpy of the resident points to the device");
    }
    template<class T> static void copyToHost(T* h, const T* d, std::size_t n)
    {
        if (n) cuda::cudaCheck(cudaMemcpy(h, d, n*sizeof(T), cudaMemcpyDeviceToHost), "cudaMemcpy of the resident points to the host");
    }
    static void zero(Real* d, std::size_t n)
    {
        if (n) cuda::cudaCheck(cudaMemsetAsync(d, 0, n*sizeof(Real)), "cudaMemsetAsync of a resident grid array");
    }
    template<class Body>
    static void forEach(Index n, const Body& body, const char* name) { cuda::forEachOnDevice(n, body, name); }

};

} // namespace

std::unique_ptr<ResidentStep> makeResidentCuda()
{
    const std::string why = cudaUnavailableReason();
    if (!why.empty()) throw std::runtime_error(why);
    return std::make_unique<resident::Step<CudaExec>>();
}

} // namespace mpm

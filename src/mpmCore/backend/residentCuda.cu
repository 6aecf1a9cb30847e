// The resident step on a GPU (residentStepImpl.hpp over CUDA): device
// buffers, one thread per item, atomicAdd where threads share a node.
// P2G adds with plain global atomics on points kept in binning-block order
// (MpmSystem sorts them on the host when they are uploaded).
#include "residentStepImpl.hpp"
#include "deviceBuffer.cuh"
#include "deviceStep.hpp"
#include "forEachOnDevice.cuh"

namespace mpm {

namespace {

struct CudaExec
{
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

    // Called from MPM_HOST_DEVICE bodies; only the device side ever runs
    MPM_HOST_DEVICE static void add(Real* a, Real x)
    {
#ifdef __CUDA_ARCH__
        atomicAdd(a, x);
#else
        *a += x;
#endif
    }
    MPM_HOST_DEVICE static void min(unsigned long long* a, unsigned long long x)
    {
#ifdef __CUDA_ARCH__
        atomicMin(a, x);
#else
        if (x < *a) *a = x;
#endif
    }
    MPM_HOST_DEVICE static void count(unsigned long long* a)
    {
#ifdef __CUDA_ARCH__
        atomicAdd(a, 1ull);
#else
        ++*a;
#endif
    }
};

} // namespace

std::unique_ptr<ResidentStep> makeResidentCuda()
{
    const std::string why = cudaUnavailableReason();
    if (!why.empty()) throw std::runtime_error(why);
    return std::make_unique<resident::Step<CudaExec>>();
}

} // namespace mpm

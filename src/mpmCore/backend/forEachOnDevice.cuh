// The CUDA launcher of the kernel bodies (CUDA translation units only).
//
// forEachOnDevice(n, body, "name") runs body(i) for i in [0, n), one thread
// per item: the bodies of kernels/*.hpp are MPM_HOST_DEVICE functions of one
// point or one node, and the CPU back-ends run the same bodies in a loop
// (backend/backend.hpp). body is a device lambda (nvcc --extended-lambda)
// capturing views and lattices by value: they hold raw device pointers.
#pragma once
#include "cudaCheck.cuh"
#include "../common/hostDevice.hpp"
#include "../types.hpp"

namespace mpm::cuda {

// 256 threads: a multiple of the warp, enough resident blocks per SM for the
// register-heavy stencil bodies (CBS: 64 nodes) to hide memory latency.
constexpr int threadsPerBlock = 256;

template<class Body>
__global__ void forEachKernel(Index n, Body body)
{
    const Index i = Index(blockIdx.x)*blockDim.x + threadIdx.x;
    if (i < n) body(i);
}

template<class Body>
void forEachOnDevice(Index n, Body body, const char* name)
{
    if (n <= 0) return;
    const Index blocks = (n + threadsPerBlock - 1)/threadsPerBlock;
    forEachKernel<<<unsigned(blocks), threadsPerBlock>>>(n, body);
    cudaCheckLaunch(name);
}

// The atomic reductions of the kernel bodies (backend/pointBodies.hpp,
// residentStepImpl.hpp), callable from MPM_HOST_DEVICE bodies; only the
// device side ever runs
struct Atomics
{
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
    // x >= 0: a double's bits order as the integers do
    MPM_HOST_DEVICE static void max(unsigned long long* a, Real x)
    {
#ifdef __CUDA_ARCH__
        atomicMax(a, (unsigned long long)__double_as_longlong(x));
#else
        (void)a; (void)x;
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

// P2G's add on the device: concurrent points share nodes. Points stored in
// block or stencil order keep a warp's atomics on a few cache lines.
struct AtomicAdd
{
    __device__ void operator()(Real* a, Index I, Real x) const { atomicAdd(a + I, x); }
};

} // namespace mpm::cuda

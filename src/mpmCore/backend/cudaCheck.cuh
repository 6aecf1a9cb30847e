// Error checks of the CUDA runtime calls (CUDA translation units only).
//
// Every runtime call of the back-end goes through cudaCheck, which throws a
// std::runtime_error naming the call and CUDA's reason; a kernel launch is
// checked with cudaCheckLaunch (launch errors are reported by
// cudaGetLastError, not by the launch itself). The step's callers (MpmSystem,
// the OpenFOAM layer) turn the exception into their fatal error.
#pragma once
#include <cuda_runtime.h>
#include <stdexcept>
#include <string>

namespace mpm::cuda {

inline void cudaCheck(cudaError_t e, const char* call)
{
    if (e == cudaSuccess) return;
    throw std::runtime_error
    (
        std::string("CUDA back-end: ") + call + " failed: " + cudaGetErrorName(e) + " ("
        + cudaGetErrorString(e) + ")"
    );
}

// After a launch: the configuration error now; with MPM_CUDA_SYNC_CHECK
// (debugging) also the kernel's own failure, at the cost of a sync.
inline void cudaCheckLaunch(const char* kernel)
{
    cudaCheck(cudaGetLastError(), kernel);
#ifdef MPM_CUDA_SYNC_CHECK
    cudaCheck(cudaDeviceSynchronize(), kernel);
#endif
}

} // namespace mpm::cuda

// Is there a usable GPU? (the CUDA build's cudaUnavailableReason)
#include "deviceStep.hpp"
#include <cuda_runtime.h>
#include <string>

namespace mpm {

namespace {

__global__ void probeKernel(int* out) { *out = 1; }

std::string reason(const char* what, cudaError_t e)
{
    return std::string("the cuda back-end needs a usable GPU: ") + what + " returned "
        + cudaGetErrorName(e) + " (" + cudaGetErrorString(e) + ")";
}

} // namespace

std::string cudaUnavailableReason()
{
    // Once per process: the answer does not change, and the probe costs a
    // context creation the first time.
    static const std::string answer = []() -> std::string
    {
        int n = 0;
        const cudaError_t e = cudaGetDeviceCount(&n);
        if (e == cudaErrorInsufficientDriver || e == cudaErrorNoDevice)
        {
            return reason("cudaGetDeviceCount", e)
                + ": this machine has no NVIDIA GPU with a driver for this CUDA version";
        }
        if (e != cudaSuccess) return reason("cudaGetDeviceCount", e);
        if (n == 0) return "the cuda back-end needs a usable GPU: no CUDA device was found";
        // The build's architectures (MPM_CUDA_ARCHITECTURES) must include
        // the device's, or a lower one whose PTX it can compile.
        cudaFuncAttributes attr;
        const cudaError_t k = cudaFuncGetAttributes(&attr, probeKernel);
        if (k != cudaSuccess)
        {
            cudaDeviceProp prop;
            cudaGetDeviceProperties(&prop, 0);
            return reason("cudaFuncGetAttributes", k) + ": the device " + prop.name
                + " (compute capability " + std::to_string(prop.major) + "." + std::to_string(prop.minor)
                + ") cannot run this build's code; rebuild with -DMPM_CUDA_ARCHITECTURES including "
                + std::to_string(10*prop.major + prop.minor);
        }
        return "";
    }();
    return answer;
}

} // namespace mpm

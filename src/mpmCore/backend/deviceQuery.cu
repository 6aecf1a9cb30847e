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

namespace {

__global__ void triadKernel(double* a, const double* b, const double* c, double s, long n)
{
    const long i = long(blockIdx.x)*blockDim.x + threadIdx.x;
    if (i < n) a[i] = b[i] + s*c[i];
}

} // namespace

std::string cudaDeviceDescription()
{
    cudaDeviceProp prop;
    if (cudaGetDeviceProperties(&prop, 0) != cudaSuccess) return "unknown device";
    return std::string(prop.name) + " (compute capability " + std::to_string(prop.major) + "."
        + std::to_string(prop.minor) + ", " + std::to_string(prop.multiProcessorCount) + " SMs, "
        + std::to_string(prop.totalGlobalMem >> 30) + " GiB)";
}

// STREAM's triad counting: 3 arrays of 8-byte values per element (no
// write-allocate), the best of 10 launches over 2^26 elements
double cudaTriadBandwidth()
{
    const long n = 1l << 26;
    double* d = nullptr;
    if (cudaMalloc(&d, 3*n*sizeof(double)) != cudaSuccess) return 0;
    cudaMemset(d, 0, 3*n*sizeof(double));
    cudaEvent_t t0, t1;
    cudaEventCreate(&t0);
    cudaEventCreate(&t1);
    float best = 1e30f;
    for (int r = 0; r < 10; ++r)
    {
        cudaEventRecord(t0);
        triadKernel<<<unsigned((n + 255)/256), 256>>>(d, d + n, d + 2*n, 1.5, n);
        cudaEventRecord(t1);
        cudaEventSynchronize(t1);
        float ms = 0;
        cudaEventElapsedTime(&ms, t0, t1);
        best = ms < best ? ms : best;
    }
    cudaEventDestroy(t0);
    cudaEventDestroy(t1);
    cudaFree(d);
    return 3.0*n*sizeof(double)/(1e-3*best)/1e9;
}

} // namespace mpm

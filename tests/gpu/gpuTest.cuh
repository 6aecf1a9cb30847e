// Shared start of the GPU tests: names the device, or prints why there is
// none; the test then exits 77, which ctest reports as skipped (not passed).
#pragma once
#include <cstdio>
#include <cuda_runtime.h>

inline bool gpuPresent()
{
    int devices = 0;
    if (cudaGetDeviceCount(&devices) != cudaSuccess || devices == 0)
    {
        std::printf("SKIP: no usable CUDA device (%s)\n", cudaGetErrorString(cudaGetLastError()));
        return false;
    }
    cudaDeviceProp prop;
    cudaGetDeviceProperties(&prop, 0);
    std::printf("device: %s, compute capability %d.%d\n", prop.name, prop.major, prop.minor);
    return true;
}

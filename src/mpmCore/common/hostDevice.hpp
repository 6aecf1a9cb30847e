// Functions compiled for the CPU and, under nvcc, for the GPU too: the
// kernel bodies (shape functions, stencils, lattice indexing) are written
// once and called by every back-end.
#pragma once

#if defined(__CUDACC__)
#define MPM_HOST_DEVICE __host__ __device__
#else
#define MPM_HOST_DEVICE
#endif

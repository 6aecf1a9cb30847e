// Functions compiled for the CPU and, under nvcc, for the GPU too: the
// kernel bodies (shape functions, stencils, lattice indexing) are written
// once and called by every back-end.
#pragma once

#if defined(__CUDACC__)
#define MPM_HOST_DEVICE __host__ __device__
#else
#define MPM_HOST_DEVICE
#endif

// Before a loop over the nodes of a stencil row whose iterations are
// independent: vectorise it on the CPU (OpenMP's simd, no reassociation, so
// the same bits); nothing on the GPU, where a thread is one point.
#if defined(__CUDA_ARCH__) || !defined(_OPENMP)
#define MPM_SIMD
#else
#define MPM_SIMD _Pragma("omp simd")
#endif

// Four Reals as one vector register on the CPU (GCC's and Clang's vector
// extension: element-wise arithmetic, each lane rounded as the scalar
// expression is, so the same bits). Host code only: a GPU thread is one
// point, and kernels use it under MPM_HOST_LANES only.
#if !defined(__CUDA_ARCH__) && (defined(__GNUC__) || defined(__clang__))
#define MPM_HOST_LANES 1
#endif

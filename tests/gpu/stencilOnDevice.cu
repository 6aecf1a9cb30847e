// GPU test: the kernel bodies are written once (common/hostDevice.hpp) and
// must give the same stencils on the device as on the host. For random
// points in a 3D lattice and every shape function, a kernel evaluates each
// point's stencil (weights, gradients, node indices) and reduces it to
// checksums: the partition of unity sum N, the first moment sum N x_I, the
// gradient sum (zero) and sum node*N. They must equal the host's to 1e-12
// relative (fused multiply-add differs between the compilers).
//
// Exit codes: 0 pass, 1 fail, 77 no usable GPU (ctest reports it skipped).
#include "gpuTest.cuh"
#include "transfer/stencil.hpp"
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>
#include <cuda_runtime.h>

using namespace mpm;

namespace {

constexpr int nSums = 6;

template<class K>
MPM_HOST_DEVICE void pointSums(const Lattice& L, Real x, Real y, Real z, Real* out)
{
    Stencil<K, 3> s;
    s.compute(L, x, y, z);
    for (int c = 0; c < nSums; ++c) out[c] = 0;
    s.forEach(L, [&](Index I, Real N, const Real* dN, const Real* dx)
    {
        out[0] += N;
        out[1] += N*dx[0];             // sum N (x_I - x_p): zero for B-splines
        out[2] += dN[0] + dN[1] + dN[2];
        out[3] += N*Real(I);
        out[4] += N*dx[1]*dx[2];
        out[5] += dN[0]*Real(I % 7);
    });
}

template<class K>
__global__ void stencilKernel(Lattice L, const Real* x, int n, Real* out)
{
    const int p = blockIdx.x*blockDim.x + threadIdx.x;
    if (p < n) pointSums<K>(L, x[3*p], x[3*p + 1], x[3*p + 2], out + nSums*p);
}

bool check(cudaError_t e, const char* what)
{
    if (e == cudaSuccess) return true;
    std::printf("CUDA error in %s: %s\n", what, cudaGetErrorString(e));
    return false;
}

template<class K>
int run(const char* name, const Lattice& L, const std::vector<Real>& x)
{
    const int n = int(x.size()/3);
    Real *dx = nullptr, *dout = nullptr;
    if (!check(cudaMalloc(&dx, x.size()*sizeof(Real)), "cudaMalloc")) return 1;
    if (!check(cudaMalloc(&dout, std::size_t(n)*nSums*sizeof(Real)), "cudaMalloc")) return 1;
    cudaMemcpy(dx, x.data(), x.size()*sizeof(Real), cudaMemcpyHostToDevice);
    stencilKernel<K><<<(n + 127)/128, 128>>>(L, dx, n, dout);
    if (!check(cudaGetLastError(), "kernel launch") || !check(cudaDeviceSynchronize(), "kernel")) return 1;
    std::vector<Real> device(std::size_t(n)*nSums);
    cudaMemcpy(device.data(), dout, device.size()*sizeof(Real), cudaMemcpyDeviceToHost);
    cudaFree(dx);
    cudaFree(dout);

    Real worst = 0;
    for (int p = 0; p < n; ++p)
    {
        Real host[nSums];
        pointSums<K>(L, x[3*p], x[3*p + 1], x[3*p + 2], host);
        for (int c = 0; c < nSums; ++c)
        {
            const Real scale = std::max(std::abs(host[c]), Real(1));
            worst = std::max(worst, std::abs(host[c] - device[std::size_t(p)*nSums + c])/scale);
        }
    }
    const bool ok = worst <= 1e-12;
    std::printf("%s %s: %d points, largest relative difference host/device %.3e\n",
                ok ? "PASS" : "FAIL", name, n, worst);
    return ok ? 0 : 1;
}

} // namespace

int main()
{
    if (!gpuPresent()) return 77;

    Lattice L;
    L.h = 0.05;
    L.nCells = {24, 20, 16};
    L.finalise();
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> u(0.05, 0.95);
    std::vector<Real> x;
    for (int p = 0; p < 100000; ++p)
        for (int a = 0; a < 3; ++a) x.push_back(u(rng)*L.length(a));
    int failures = 0;
    failures += run<LinearHat>("linearHat", L, x);
    failures += run<QuadraticBSpline>("quadraticBSpline", L, x);
    failures += run<CubicBSpline>("cubicBSpline", L, x);
    return failures ? 1 : 0;
}

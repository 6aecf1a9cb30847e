// The CUDA back-end of the step (interface and data flow: deviceStep.hpp).
//
// Every kernel is forEachOnDevice over a functor that calls one body of
// kernels/*.hpp, the bodies the CPU launchers run: the device and the CPU
// differ only in the order of P2G's sums (atomicAdd) and in the compilers'
// use of fused multiply-add.
#include "deviceStep.hpp"
#include "deviceBuffer.cuh"
#include "forEachOnDevice.cuh"
#include "pointArrays.hpp"
#include "pointBodies.hpp"
#include "../constitutive/lawKernels.hpp"
#include "../kernels/g2p.hpp"
#include "../kernels/movePoint.hpp"
#include "../kernels/p2g.hpp"
#include "../kernels/stressPoint.hpp"
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace mpm {

namespace {

using cuda::DeviceBuffer;
using cuda::forEachOnDevice;

using bodies::dispatchKD;
using bodies::pick;
using cuda::AtomicAdd;

// The advance: per point its MoveFlags, and the number flagged
struct MoveBody
{
    Lattice L; PointView P; bool periodic[3]; bool frozen;
    int* flags; unsigned long long* flagged;
    __device__ void operator()(Index p) const
    {
        Real x[3];
        const int f = advancePoint(L, periodic, frozen, P, p, x);
        flags[p] = f;
        if (f) atomicAdd(flagged, 1ull);
        if (f & moveBad || frozen) return;
        if (f & moveOutside)
        {
            // Unclamped: the host decides (open face: removed; wall: held)
            for (int a = 0; a < 3; ++a) P.x[a][p] = x[a];
            return;
        }
        storePosition(L, periodic, P, p, x);
    }
};

// Active-node transfers: arrays packed side by side, nActive values each
struct ZeroNodes
{
    const Index* nodes; Real* a[14]; int count;
    __device__ void operator()(Index k) const
    {
        const Index I = nodes[k];
        for (int j = 0; j < count; ++j) a[j][I] = 0;
    }
};

struct PackNodes
{
    const Index* nodes; Index n; Real* a[14]; int count; Real* buf;
    __device__ void operator()(Index k) const
    {
        const Index I = nodes[k];
        for (int j = 0; j < count; ++j) buf[j*n + k] = a[j][I];
    }
};

struct UnpackNodes
{
    const Index* nodes; Index n; Real* a[14]; int count; const Real* buf;
    __device__ void operator()(Index k) const
    {
        const Index I = nodes[k];
        for (int j = 0; j < count; ++j) a[j][I] = buf[j*n + k];
    }
};

// Pinned host memory for the packed node transfers (a pageable copy is
// staged by the driver through its own pinned buffer: one more copy)
class PinnedBuffer
{
public:
    ~PinnedBuffer() { if (data_) cudaFreeHost(data_); }
    Real* get(std::size_t n)
    {
        if (n > capacity_)
        {
            if (data_) cuda::cudaCheck(cudaFreeHost(data_), "cudaFreeHost of the node staging buffer");
            data_ = nullptr;
            cuda::cudaCheck(cudaMallocHost(reinterpret_cast<void**>(&data_), n*sizeof(Real)),
                            "cudaMallocHost of the node staging buffer");
            capacity_ = n;
        }
        return data_;
    }
private:
    Real* data_ = nullptr;
    std::size_t capacity_ = 0;
};

// Grid arrays in the order of DeviceStep::GridArrays' bits, 14 in all
int gridArrays(const GridView& g, unsigned what, Real* out[14])
{
    int c = 0;
    if (what & DeviceStep::gridMass) out[c++] = g.mass;
    if (what & DeviceStep::gridVolume) out[c++] = g.volume;
    for (int d = 0; d < 3; ++d) if (what & DeviceStep::gridMomentum) out[c++] = g.momentum[d];
    for (int d = 0; d < 3; ++d) if (what & DeviceStep::gridForce) out[c++] = g.force[d];
    for (int d = 0; d < 3; ++d) if (what & DeviceStep::gridVelocityOld) out[c++] = g.velocityOld[d];
    for (int d = 0; d < 3; ++d) if (what & DeviceStep::gridVelocity) out[c++] = g.velocity[d];
    return c;
}

} // namespace

struct DeviceStep::Impl
{
    DeviceBuffer<Real> points{"the device points"};
    DeviceBuffer<int> material{"the device points' materials"};
    DeviceBuffer<int> moveFlags{"the move flags"};
    PointView P;                                // device pointers
    DeviceBuffer<Real> grid{"the device grid"};
    GridView g;                                 // device pointers
    DeviceBuffer<Index> active{"the active node list"};
    std::vector<Index> activeHost;              // what `active` holds
    DeviceBuffer<Real> packed{"the packed node values"};
    PinnedBuffer staging;
    DeviceBuffer<LawParams> laws{"the material laws"};
    std::vector<LawParams> lawsHost;            // what `laws` holds
    DeviceBuffer<Real> invRho0{"1/rho0 per material"};
    std::vector<Real> invRho0Host;
    DeviceBuffer<unsigned long long> counters{"the step's counters"};

    void setPoints(Index n)
    {
        points.resize(std::size_t(n)*realsPerPoint);
        material.resize(std::size_t(n));
        P = layPoints(points.data(), material.data(), n);
    }

    // Zeroes the two counters (stress: first bad, inverted; move: flagged)
    void resetCounters(unsigned long long first)
    {
        counters.resize(2);
        const unsigned long long init[2] = {first, 0};
        counters.upload(init, 2);
    }
};

DeviceStep::DeviceStep()
{
    const std::string why = cudaUnavailableReason();
    if (!why.empty()) throw std::runtime_error(why);
    impl_ = std::make_unique<Impl>();
}

DeviceStep::~DeviceStep() = default;

void DeviceStep::setMaterials(const std::vector<LawParams>& laws)
{
    Impl& m = *impl_;
    const bool same = laws.size() == m.lawsHost.size()
        && std::memcmp(laws.data(), m.lawsHost.data(), laws.size()*sizeof(LawParams)) == 0;
    if (same) return;
    m.laws.upload(laws.data(), laws.size());
    m.lawsHost = laws;
}

void DeviceStep::uploadPoints(const PointView& host, bool apic)
{
    Impl& m = *impl_;
    m.setPoints(host.n);
    const std::size_t n = std::size_t(host.n);
    forEachPointArray(m.P, host, PointDirection::up, apic, [&](Real* d, const Real* h, const char* name)
    {
        if (n) cuda::cudaCheck(cudaMemcpy(d, h, n*sizeof(Real), cudaMemcpyHostToDevice),
                               (std::string("cudaMemcpy of the points' ") + name + " to the device").c_str());
    });
    m.material.upload(host.material, n);
}

void DeviceStep::downloadPoints(const PointView& host, bool apic)
{
    Impl& m = *impl_;
    if (host.n != m.P.n) throw std::runtime_error("DeviceStep::downloadPoints: the host holds another number of points");
    const std::size_t n = std::size_t(host.n);
    forEachPointArray(m.P, host, PointDirection::down, apic, [&](const Real* d, Real* h, const char* name)
    {
        if (n) cuda::cudaCheck(cudaMemcpy(h, d, n*sizeof(Real), cudaMemcpyDeviceToHost),
                               (std::string("cudaMemcpy of the points' ") + name + " to the host").c_str());
    });
}

void DeviceStep::setActiveNodes(Index nNodes, const std::vector<Index>& active)
{
    Impl& m = *impl_;
    if (m.g.n != nNodes)
    {
        // A new lattice: the mirror starts at zero everywhere, and from
        // then on only active nodes are zeroed and written
        m.grid.resize(std::size_t(nNodes)*realsPerNode);
        m.grid.zero();
        m.g = layGrid(m.grid.data(), nNodes);
    }
    m.active.upload(active.data(), active.size());
    m.activeHost = active;
}

void DeviceStep::zeroGrid(unsigned arrays)
{
    Impl& m = *impl_;
    ZeroNodes z{m.active.data(), {}, 0};
    z.count = gridArrays(m.g, arrays, z.a);
    forEachOnDevice(Index(m.active.size()), z, "the grid zeroing kernel");
}

void DeviceStep::gridToHost(const GridView& host, unsigned arrays, bool add)
{
    Impl& m = *impl_;
    const Index n = Index(m.active.size());
    PackNodes pack{m.active.data(), n, {}, 0, nullptr};
    pack.count = gridArrays(m.g, arrays, pack.a);
    const std::size_t total = std::size_t(n)*pack.count;
    m.packed.resize(total);
    pack.buf = m.packed.data();
    forEachOnDevice(n, pack, "the grid packing kernel");
    Real* staged = m.staging.get(total);
    m.packed.download(staged, total);
    Real* h[14];
    gridArrays(host, arrays, h);
    const std::vector<Index>& nodes = m.activeHost;
    for (int j = 0; j < pack.count; ++j)
    {
        const Real* b = staged + std::size_t(j)*n;
        if (add) for (Index k = 0; k < n; ++k) h[j][nodes[k]] += b[k];
        else for (Index k = 0; k < n; ++k) h[j][nodes[k]] = b[k];
    }
}

void DeviceStep::gridFromHost(const GridView& host, unsigned arrays)
{
    Impl& m = *impl_;
    const Index n = Index(m.active.size());
    UnpackNodes unpack{m.active.data(), n, {}, 0, nullptr};
    unpack.count = gridArrays(m.g, arrays, unpack.a);
    const std::size_t total = std::size_t(n)*unpack.count;
    Real* staged = m.staging.get(total);
    Real* h[14];
    gridArrays(host, arrays, h);
    const std::vector<Index>& nodes = m.activeHost;
    for (int j = 0; j < unpack.count; ++j)
    {
        Real* b = staged + std::size_t(j)*n;
        for (Index k = 0; k < n; ++k) b[k] = h[j][nodes[k]];
    }
    m.packed.upload(staged, total);
    unpack.buf = m.packed.data();
    forEachOnDevice(n, unpack, "the grid unpacking kernel");
}

void DeviceStep::p2g
(
    const Lattice& L, ShapeKind shape, bool massMomentum, bool force, bool apic,
    const std::vector<Real>& invRho0, bool grainVolume
)
{
    Impl& m = *impl_;
    if (invRho0 != m.invRho0Host)
    {
        m.invRho0.upload(invRho0.data(), invRho0.size());
        m.invRho0Host = invRho0;
    }
    dispatchKD(shape, L.dim, [&](auto k, auto d)
    {
        using K = decltype(k);
        constexpr int D = decltype(d)::value;
        pick(massMomentum, [&](auto mm)
        {
            pick(force, [&](auto f)
            {
                pick(apic, [&](auto a)
                {
                    bodies::P2g<K, D, decltype(mm)::value, decltype(f)::value, decltype(a)::value, AtomicAdd> body
                    {L, m.P, m.g, m.invRho0.data(), grainVolume};
                    forEachOnDevice(m.P.n, body, "the P2G kernel");
                });
            });
        });
    });
}

void DeviceStep::g2p(const Lattice& L, ShapeKind shape, bool apic, Real flipRatio, Real dt)
{
    Impl& m = *impl_;
    dispatchKD(shape, L.dim, [&](auto k, auto d)
    {
        using K = decltype(k);
        constexpr int D = decltype(d)::value;
        pick(apic, [&](auto a)
        {
            bodies::G2p<K, D, decltype(a)::value> body{L, m.P, m.g, flipRatio, dt};
            forEachOnDevice(m.P.n, body, "the G2P kernel");
        });
    });
}

void DeviceStep::gradient(const Lattice& L, ShapeKind shape, bool fromVelocityOld)
{
    Impl& m = *impl_;
    Real* const* v = fromVelocityOld ? m.g.velocityOld : m.g.velocity;
    dispatchKD(shape, L.dim, [&](auto k, auto d)
    {
        bodies::Gradient<decltype(k), decltype(d)::value> body{L, m.P, {v[0], v[1], v[2]}};
        forEachOnDevice(m.P.n, body, "the velocity gradient kernel");
    });
}

DeviceStep::StressResult DeviceStep::stress(Real dt)
{
    Impl& m = *impl_;
    const Index n = m.P.n;
    m.resetCounters((unsigned long long)n);
    bodies::Stress<cuda::Atomics> body{m.P, m.laws.data(), dt, m.counters.data(), m.counters.data() + 1};
    forEachOnDevice(n, body, "the stress update kernel");
    unsigned long long c[2];
    m.counters.download(c, 2);
    return {Index(c[0]), Index(c[1])};
}

Index DeviceStep::move(const Lattice& domain, const bool periodic[3], bool frozen, std::vector<int>& flags)
{
    Impl& m = *impl_;
    const Index n = m.P.n;
    m.moveFlags.resize(std::size_t(n));
    m.resetCounters(0);
    MoveBody body{domain, m.P, {periodic[0], periodic[1], periodic[2]}, frozen, m.moveFlags.data(), m.counters.data()};
    forEachOnDevice(n, body, "the point advance kernel");
    unsigned long long c[2];
    m.counters.download(c, 2);
    if (c[0] > 0)
    {
        flags.resize(std::size_t(n));
        m.moveFlags.download(flags.data(), flags.size());
    }
    return Index(c[0]);
}

void DeviceStep::synchronise()
{
    cuda::cudaCheck(cudaDeviceSynchronize(), "cudaDeviceSynchronize");
}

} // namespace mpm

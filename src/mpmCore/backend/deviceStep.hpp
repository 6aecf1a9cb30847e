// The CUDA back-end of the MPM step, behind a plain C++ interface: no CUDA
// type appears here, so the core (MpmSystem) and the tests include it
// whether or not the build found nvcc. The implementation is
// backend/deviceStep.cu and deviceQuery.cu (libmpmCoreCuda); only a build
// with MPM_HAVE_CUDA defines it and constructs a DeviceStep. Everyone else
// asks backendUnavailableReason(Backend::cuda) (backend/backend.hpp),
// which is cudaUnavailableReason() in a CUDA build.
//
// What runs where, per step (docs/gpu.md):
//
//   host    bin the points, build the active region (Binning, ActiveRegion)
//   H->D    every point array the step reads (x, v, mass, volume0, volume,
//           F, sigma, eqPlasticStrain, material; C with APIC) and the list
//           of the active region's nodes
//   device  zero the grid on the active nodes; P2G with atomicAdd
//   D->H    mass, volume, momentum (and force) of the active nodes, packed
//   host    gravity, halo sums, ghost folds, wall contact, friction, the
//           coupling terms and the (lumped or consistent) mass solve: node
//           lists of the boundary, decomposition and fluid
//   H->D    the nodal velocities (new, and old for FLIP) of the active nodes
//   device  G2P and the velocity gradient; MUSL: the re-map P2G (momentum
//           D->H, velocity H->D, gradient); the stress update (material
//           laws by type, no virtual call); the point advance
//   D->H    every point array the step wrote (x, v, volume, F, sigma,
//           eqPlasticStrain; C with APIC) and, if any, the flags of the
//           points that went non-finite or beyond a face
//   host    remove the points that left through an open face, clamp those
//           at walls, migrate (decomposed runs)
//
// Cost: per point and step about 35 doubles up and 30 down (~0.5 kB; the
// consistent-mass sweeps read the host's copy of the points, unchanged
// until the step's end), per active node 5 to 7 doubles down and 3 to 6 up.
// On a PCIe 4 link (~20 GB/s) that is ~25 us per thousand points per step,
// more than the device's P2G and G2P take: the device step pays off when
// the point work is large (cubic B-splines, costly laws), and the next gain
// is to keep the points resident on the device between steps.
#pragma once
#include "../grid/lattice.hpp"
#include "../kernels/views.hpp"
#include "../shapeFunctions/shapeFunctions.hpp"
#include "../types.hpp"
#include <memory>
#include <string>
#include <vector>

namespace mpm {

struct LawParams;

// CUDA builds: "" when a usable GPU is present, otherwise why not (no
// device; driver missing or too old; an architecture the build lacks).
std::string cudaUnavailableReason();
// CUDA builds with a GPU: its name and size, and its measured memory
// bandwidth in GB/s (a triad, as STREAM counts it; benchmarks)
std::string cudaDeviceDescription();
double cudaTriadBandwidth();

class DeviceStep
{
public:
    // The grid arrays a transfer moves (bit set)
    enum GridArrays : unsigned
    {
        gridMass = 1, gridVolume = 2, gridMomentum = 4, gridForce = 8,
        gridVelocityOld = 16, gridVelocity = 32
    };

    // Throws std::runtime_error with cudaUnavailableReason() when there is
    // no usable GPU.
    DeviceStep();
    ~DeviceStep();
    DeviceStep(const DeviceStep&) = delete;
    DeviceStep& operator=(const DeviceStep&) = delete;

    // Materials: the laws' parameters, indexed by material (uploaded when
    // they change: call it at every step, it compares with the last upload)
    void setMaterials(const std::vector<LawParams>& laws);

    // Points: host -> device every array the step reads, device -> host
    // every array it writes (plus C with APIC). The device mirror is sized
    // by the upload. `host` holds host pointers (kernels/views.hpp).
    void uploadPoints(const PointView& host, bool apic);
    void downloadPoints(const PointView& host, bool apic);

    // The grid mirror holds nNodes values per array; `active` lists the
    // nodes of this step's region, the only ones zeroed and transferred.
    void setActiveNodes(Index nNodes, const std::vector<Index>& active);
    // Zero the chosen arrays on the active nodes
    void zeroGrid(unsigned arrays);
    // Device -> host on the active nodes: host = device, or host += device
    void gridToHost(const GridView& host, unsigned arrays, bool add = false);
    // Host -> device on the active nodes
    void gridFromHost(const GridView& host, unsigned arrays);

    // The kernel bodies of kernels/*.hpp, one thread per point
    // P2G (atomicAdd) of mass and volume, momentum, force as chosen; invRho0
    // per material (grain volume)
    void p2g
    (
        const Lattice& L, ShapeKind shape, bool massMomentum, bool force, bool apic,
        const std::vector<Real>& invRho0, bool grainVolume
    );
    void g2p(const Lattice& L, ShapeKind shape, bool apic, Real flipRatio, Real dt);
    // The velocity gradient from the velocity (false) or the old velocity
    void gradient(const Lattice& L, ShapeKind shape, bool fromVelocityOld);

    // The stress update of every point. firstBad: the lowest index of a
    // point that went non-finite (n if none; that point is left unchanged,
    // as on the CPU); inverted: points with J <= 0 or volume <= 0.
    struct StressResult { Index firstBad; Index inverted; };
    StressResult stress(Real dt);

    // The point advance (kernels/movePoint.hpp) over the domain's lattice.
    // Points inside are stored (storePosition); a point beyond a
    // non-periodic face keeps its unclamped new position for the host to
    // classify. flags (host, resized to n, filled only when some point is
    // flagged): MoveFlags per point. Returns the number of flagged points.
    Index move(const Lattice& domain, const bool periodic[3], bool frozen, std::vector<int>& flags);

    // Waits for the device (the timers of the phases)
    void synchronise();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace mpm

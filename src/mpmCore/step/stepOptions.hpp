// Algorithmic choices of one MPM step, as selected in constant/mpmProperties.
#pragma once
#include "../backend/backend.hpp"
#include "p2gRowChoice.hpp"
#include "../shapeFunctions/shapeFunctions.hpp"
#include <array>
#include <string>

namespace mpm {

// When the stress is updated relative to the momentum update:
//  USF  - update stress first, from the P2G grid velocity (v^n);
//  USL  - update stress last, from the updated grid velocity (v^{n+1});
//  MUSL - after G2P, map the new particle momentum back to the grid and
//         update stress from that (Sulsky et al. 1994).
enum class StressUpdate { USF = 0, USL = 1, MUSL = 2 };

// How velocity goes from grid to points: PIC/FLIP blend, or APIC (affine
// PIC, Jiang et al. 2015), which ignores flipRatio.
enum class Transfer { picFlip = 0, apic = 1 };

// Nodal mass matrix: lumped (row sums, the MPM standard) or consistent
// M_IJ = sum_p m_p N_I N_J, inverted approximately by a few Jacobi sweeps
// preconditioned with the lumped mass. Consistent mass removes most of the
// O((kh)^2) dispersion of B-spline MPM; each sweep costs one G2P + P2G.
enum class MassMatrix { lumped = 0, consistent = 1 };

const char* massMatrixName(MassMatrix m);
bool parseMassMatrix(const std::string& name, MassMatrix& m);
const char* validMassMatrixNames();

const char* stressUpdateName(StressUpdate s);
bool parseStressUpdate(const std::string& name, StressUpdate& s);
const char* validStressUpdateNames();

const char* transferName(Transfer t);
bool parseTransfer(const std::string& name, Transfer& t);
const char* validTransferNames();

struct StepOptions
{
    ShapeKind shape = ShapeKind::cubicBSpline;
    Real flipRatio = 0.99;            // alpha: 0 = PIC, 1 = FLIP
    Transfer transfer = Transfer::picFlip;
    StressUpdate stressUpdate = StressUpdate::USL;
    MassMatrix massMatrix = MassMatrix::lumped;
    int consistentMassIterations = 2;  // Jacobi sweeps for consistent mass
    std::array<Real, 3> gravity{0, 0, 0};
    bool freezePositions = false;     // analysis runs: points do not move
    // Volume a point adds to the lattice's solid volume (alpha.solid): its
    // current volume J V0 for a continuum solid; its grain volume mass /
    // rho0 for grains in a fluid (a point is then a parcel of mixture whose
    // incompressible grains fill part of it: J changes the packing, not the
    // grains).
    bool constantGrainVolume = false;
    // Grid work only where the material is (grid/activeRegion.hpp); false:
    // over the whole lattice, the reference the sparse step must equal.
    bool sparseGrid = true;
    // Store the points in binning-block order when their storage order has
    // drifted from it (runs of consecutive points shorter than 8 on
    // average), so that P2G and G2P stream through points and nodes
    // together (benchmarks/particleThroughput 32 10 1: points in random
    // order, 2.0 -> 4.6 M point-steps/s with linear hats). The decision
    // depends on the points alone, so results stay independent of the
    // thread count; against a run without it they differ by round-off (a
    // point entering a block is summed in its storage place).
    bool reorderPoints = true;
    // Who launches the kernel bodies (backend/backend.hpp)
    Backend backend = Backend::openmp;
    // cuda: keep the points and the grid on the device between steps where
    // the case allows it (backend/residentStep.hpp); false: the
    // host-assisted step always (comparisons)
    bool deviceResident = true;
    // The resident cuda step's P2G: the sums of a warp's points that share
    // a stencil added together (shuffles) before one atomic per node, or
    // one atomic per point and node (backend/residentCuda.cu; the choice
    // measured by benchmarks/gpuThroughput)
    bool p2gWarpReduction = true;
    // Tests: run the resident device step (backend/residentStep.hpp) on the
    // host, with the stand-in for the CUDA runtime, where it covers the case
    // (the host step otherwise). Not a back-end for runs.
    bool residentStandIn = false;
    // 3D P2G without APIC: node rows as vector loops or node by node, by
    // timing unless forced (step/p2gRowChoice.hpp; no effect on results)
    P2gRowLoop p2gRowLoop = P2gRowLoop::automatic;
};

} // namespace mpm

// The resident device step: the points and the whole grid stay in device
// memory between steps, and every phase of the step plan (step/stepPlan.hpp)
// runs there, node work included, as kernel bodies launched one thread per
// point, node or wall ghost. Per step the host receives five counters (the
// non-finite stops, the inverted and contained points, the points beyond a
// wall); points cross the bus only when the host reads or changes them
// (MpmSystem::particles()), or when some point went beyond a box wall.
//
// The plain C++ interface of this header hides the runtime: the one
// implementation (backend/residentStepImpl.hpp, a template over an
// execution policy) is compiled for CUDA (residentCuda.cu: device memory,
// kernels, atomicAdd) and for the host (residentHost.cpp: vectors, loops,
// plain adds; the stand-in that lets a machine without a GPU run and test
// the resident code path, StepOptions::residentStandIn).
//
// What it covers (MpmSystem::residentUnsupported says why not otherwise):
// one rank; any shape function, dimension, transfer and stress update;
// lumped mass; gravity; box walls noSlip, slip and friction (the ghost
// folds with the contact decision of unilateral walls, Coulomb friction);
// periodic axes; level-set walls and obstacles that are not outlets,
// moving ones included. Not yet: open faces and inlets, consistent mass,
// the fluid coupling and decomposed runs: those keep the host-assisted
// step (backend/deviceStep.hpp).
#pragma once
#include "../constitutive/lawKernels.hpp"
#include "../grid/boundary.hpp"
#include "../grid/lattice.hpp"
#include "../grid/levelSet.hpp"
#include "../kernels/views.hpp"
#include "../shapeFunctions/shapeFunctions.hpp"
#include "../step/stepPlan.hpp"
#include <array>
#include <memory>
#include <string>
#include <limits>
#include <vector>

namespace mpm {

// What the resident step needs besides the points, set at setup and when
// a part of it changes (the materials, a moving wall's level set)
struct ResidentConfig
{
    Lattice lattice;                     // the domain: one rank
    ShapeKind shape = ShapeKind::cubicBSpline;
    StepPlan plan;
    bool apic = false;
    Real flipRatio = 0.99;
    bool grainVolume = false;
    bool frozen = false;
    bool p2gWarpReduction = true;        // StepOptions::p2gWarpReduction
    std::array<Real, 3> gravity{0, 0, 0};
    std::vector<Boundary::Ghost> ghosts;
    std::vector<Boundary::FrictionNode> frictionNodes;
    std::array<bool, 3> periodic{false, false, false};
    std::vector<std::pair<Index, Index>> periodicCopies;   // Boundary's
    std::vector<LawParams> laws;
    std::vector<Real> invRho0;
    // The largest friction coefficient of level-set friction walls
    // (MpmSystem::computeFrictionCap; the box walls' are capped in ghosts)
    Real frictionCap = std::numeric_limits<Real>::infinity();
};

// The scalars a step hands back
struct ResidentResult
{
    Index firstBadStress;   // lowest index of a point with a non-finite stress (n: none)
    Index firstBadMove;     // ... with a non-finite velocity or displacement
    Index inverted;         // points with J <= 0 or volume <= 0
    Index beyondWall;       // points beyond a box face (flags: moveOutside)
    Index contained;        // points put back on a level-set wall
};

class ResidentStep
{
public:
    virtual ~ResidentStep() = default;
    virtual void configure(const ResidentConfig& c) = 0;
    // The level-set walls' node arrays (empty view: none), on nNodes nodes
    // and nWalls walls; again after the walls moved
    virtual void setLevelSet(const LevelSetView& host, Index nNodes, Index nWalls) = 0;
    // Every point array the step reads, and the materials
    virtual void uploadPoints(const PointView& host) = 0;
    // Every point array the step writes
    virtual void downloadPoints(const PointView& host) = 0;
    // After a step with beyondWall > 0: the MoveFlags per point
    virtual void downloadMoveFlags(std::vector<int>& flags) = 0;
    // One step of the configured plan (its migrate phase does nothing:
    // one rank). timers: per phase, the time to queue it; record: runPlan's.
    virtual ResidentResult step(Real dt, Real massTolerance, StepTimers& timers, std::vector<Phase>* record) = 0;
    // max over the points of signalSpeedPoint (kernels/signalSpeed.hpp)
    virtual Real maxSignalSpeed() = 0;
};

// The host stand-in (always available)
std::unique_ptr<ResidentStep> makeResidentStandIn();
#ifdef MPM_HAVE_CUDA
// The CUDA one (throws std::runtime_error without a usable GPU)
std::unique_ptr<ResidentStep> makeResidentCuda();
#endif

} // namespace mpm

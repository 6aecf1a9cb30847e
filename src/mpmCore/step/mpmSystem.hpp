// One MPM model: lattice, boundary, materials, points and the explicit step.
//
// The public face of the model. Its state is a SystemState (systemState.hpp),
// the step's phases are free functions on that state (phases/*.hpp), and
// step(dt) is one launcher per back-end (launchers/launchers.hpp) running
// the phases of the StepPlan (stepPlan.hpp) built once by setup. What this
// class adds is the life cycle (setup, a new subdomain, the device copies
// of the points kept in step) and the accessors; the rest forwards.
//
// Every phase is a loop over points or nodes on flat arrays; P2G runs blocks
// of one colour in parallel (see transfer/binning.hpp), G2P and the stress
// update are independent per point, so results do not depend on the number
// of OpenMP threads.
#pragma once
#include "../phases/gridMaps.hpp"
#include "nonFiniteError.hpp"
#include "systemState.hpp"
#include <memory>
#include <string>
#include <vector>

namespace mpm {

class MpmSystem
{
public:
    // Loops over fewer items than this run on one thread (tests lower it).
    static Index& parallelThreshold;
    using InvertedPoints = mpm::InvertedPoints;
    using GridSample = mpm::GridSample;
    static constexpr double fullCoverage = mpm::fullCoverage;

    // lattice: the whole domain. subdomain (decomposed runs): this rank's
    // box and halo; the points are then the ones in its cells, and every
    // global quantity (time step, sums, the NaN stop) is reduced over ranks.
    void setup
    (
        const Lattice& lattice, const BoundarySpec& boundary, const StepOptions& options,
        std::shared_ptr<const Subdomain> subdomain = nullptr
    );
    // Decomposed runs: this rank's new share of the lattice (a rebalance),
    // the points kept (migrate them to their new owners next). The node
    // arrays are made again on the new box lattice, the walls' nodes too;
    // the coupling's arrays are resized, to be filled again by their owner
    // (fluidCoupling), with the coverage (setCoverage). The counts of the
    // run (removed, migrated, clamped, steps) carry on.
    void changeSubdomain(std::shared_ptr<const Subdomain> subdomain);

    // Advances by dt. Throws NonFiniteError on NaN/inf.
    void step(Real dt);

    // The lattice the arrays live on: the domain, or this rank's box; the
    // whole domain (walls, periodicity, the seeding check)
    Lattice& lattice() { return s_.lattice; }
    const Lattice& lattice() const { return s_.lattice; }
    const Lattice& domain() const { return s_.domain; }
    const Subdomain* subdomain() const { return s_.subdomain.get(); }
    const Boundary& boundary() const { return s_.boundary; }
    const StepOptions& options() const { return s_.options; }
    // The step's phases in order, built by setup
    const StepPlan& plan() const { return s_.plan; }
    static int stencilReach(ShapeKind kind) { return mpm::stencilReach(kind); }

    // The points. With the resident device step the host holds a copy,
    // brought up to date here when the device is ahead; the non-const
    // access counts as a change, uploaded before the next step.
    Particles& particles() { s_.pullPoints(); s_.hostAhead = true; return s_.particles; }
    const Particles& particles() const { s_.pullPoints(); return s_.particles; }
    // The number of points on this rank (no transfer: the host and the
    // device always hold the same points)
    Index pointCount() const { return s_.particles.size(); }
    std::vector<std::unique_ptr<ConstitutiveLaw>>& materials() { return s_.materials; }
    const ConstitutiveLaw& material(int m) const { return *s_.materials[m]; }
    const GridState& grid() const { return s_.grid; }
    // Fluid coupling arrays (fluidCoupling.hpp), sized by the caller
    FluidCoupling& coupling() { return s_.coupling; }
    const FluidCoupling& coupling() const { return s_.coupling; }
    void setGravity(const std::array<Real, 3>& g) { s_.options.gravity = g; }
    void setConstantGrainVolume(bool on) { s_.options.constantGrainVolume = on; }

    // Decomposed runs: sends every point whose cell another rank owns to
    // that rank (phases/migrate.hpp); returns the number sent. Called by
    // step(); call it after reading or seeding points too.
    Index migrate();
    Real sumAll(Real x) const { return s_.sumAll(x); }
    Real maxAll(Real x) const { return s_.maxAll(x); }

    // Level-set walls (phases/walls.hpp), after setup. unsolved: the
    // coordinate of a 2D case's mid-plane along its unsolved axis. Moving
    // walls: each wall's displacement at the step's start and its velocity
    // over the step, before a step. Throws std::invalid_argument for a bad wall.
    void setLevelSetWalls(std::vector<LevelSetWall> walls, const std::array<Real, 3>& unsolved);
    void moveLevelSetWalls
    (
        const std::vector<std::array<Real, 3>>& displacement,
        const std::vector<std::array<Real, 3>>& velocity
    );
    const LevelSetWalls& levelSetWalls() const { return s_.levelSet; }
    Real computeFrictionCap() const;
    Real largestWallFriction() const;

    // The time step (phases/timeStepLimit.hpp)
    Real maxSignalSpeed() const;
    Real stableDeltaT(Real courant) const;

    // The grid maps for output and coupling (phases/gridMaps.hpp)
    void mapToGrid(std::vector<Real>* grainVolume = nullptr);
    GridSample sampleGrid();
    void materialGrainVolume(std::vector<std::vector<Real>>& out);
    void setCoverage(const std::vector<double>& coverage);
    void spreadGrainVolume(std::vector<Real>& spread) const;
    // Any node arrays: every copy of the exchange halo summed into its
    // owner, or the owners' values sent to their copies (decomposed;
    // serial: the periodic copies), for a mesh whose cells touch another
    // rank's nodes (fluidCoupling on a lattice of its own)
    void sumToOwners(const std::vector<Real*>& arrays);
    void copyToHalo(const std::vector<Real*>& arrays) const;

    // Counts of the run on this rank: points outside the domain (seeding
    // checks); removed through each open boundary condition (index into
    // the BoundarySpec's conditions), count and mass; held inside a box
    // wall (a step far too large: counted, so that clamping can never hide
    // a loss); put back on a level-set wall; sent to other ranks; steps
    Index countOutside() const;
    const std::vector<Index>& removedCount() const { return s_.removedCount; }
    const std::vector<Real>& removedMass() const { return s_.removedMass; }
    Index clampedCount() const { return s_.clamped; }
    Index levelSetContainedCount() const { return s_.contained; }
    Index migratedCount() const { return s_.migrated; }
    Index stepCount() const { return s_.stepCount; }
    // The last stress update's inverted points (systemState.hpp)
    const InvertedPoints& inverted() const { return s_.inverted; }
    // Nodes of the last step's active region (all nodes: sparseGrid off)
    Index activeNodeCount() const { return Index(s_.region.nodes().size()); }

    // Instrumentation: phase times, the 3D non-APIC P2G's loop choice
    // (p2gRowChoice.hpp), the phases a step runs appended to *out (tests;
    // null: none), why the resident device step does not run this case
    // ("" when it does, or when the back-end has none), whether it ran
    // the last step
    const StepTimers& timers() const { return s_.timers; }
    const P2gRowChoice& p2gRowChoice() const { return s_.p2gRows; }
    void recordPhases(std::vector<Phase>* out) { s_.recordPhases = out; }
    std::string residentUnsupported() const;
    bool lastStepResident() const { return s_.lastResident; }

private:
    SystemState s_;
};

} // namespace mpm

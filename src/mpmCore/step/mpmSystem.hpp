// One MPM model: lattice, boundary, materials, points and the explicit step.
//
//   step(dt): the phases of its StepPlan (step/stepPlan.hpp), built once
//             from the options and run by the back-end's launcher
//
// Every phase is a loop over points or nodes on flat arrays; P2G runs blocks
// of one colour in parallel (see transfer/binning.hpp), G2P and the stress
// update are independent per point, so results do not depend on the number
// of OpenMP threads. The kernels are instantiated per shape function and
// number of solved directions.
#pragma once
#include "../constitutive/constitutiveLaw.hpp"
#include "../backend/deviceStep.hpp"
#include "../backend/residentStep.hpp"
#include "../grid/activeRegion.hpp"
#include "../grid/boundary.hpp"
#include "../grid/gridState.hpp"
#include "../grid/lattice.hpp"
#include "../grid/levelSet.hpp"
#include "../kernels/views.hpp"
#include "../parallel/subdomain.hpp"
#include "../particles/particles.hpp"
#include "../transfer/binning.hpp"
#include "stepOptions.hpp"
#include "stepPlan.hpp"
#include "stepTimers.hpp"
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mpm {

// Thrown when a point's velocity or stress stops being finite: nothing is
// written after it, and the message names the step and point id, and for
// a stress its material (index), which the error carries so that a caller
// can name it (the OpenFOAM layer: by its dictionary name).
class NonFiniteError : public std::runtime_error
{
public:
    NonFiniteError(const std::string& base, Index step, std::int64_t id, int material = -1)
    : std::runtime_error(material >= 0 ? base + " (material " + std::to_string(material) + ")" : base),
      step(step), pointId(id), material(material), base(base) {}
    Index step;
    std::int64_t pointId;
    int material;        // -1: not a material's (a velocity)
    std::string base;    // the message without the material
};

// Momentum exchange with a fluid, per node (each real node is a fluid
// cell). The nodal update is implicit in the solid velocity v:
//   (m + dt K) v_new = p + dt (f + V_s F + K U)
// with V_s the node's solid volume (sum N V_p), so F is a force per unit
// solid volume (buoyancy: -rho_f grad p) that follows the material.
// so stiff drag (relaxation time << dt) stays stable and relaxes v to the
// fluid velocity plus the correct equilibrium slip. Empty K: no coupling,
// nothing is computed. The step also integrates v_new over time, for the
// fluid's drag source (the solid velocity averaged over the sub-cycles).
struct FluidCoupling
{
    std::vector<Real> K;                      // beta V_cell [kg/s], padded nodes
    std::array<std::vector<Real>, 3> U;       // fluid velocity at the nodes
    std::array<std::vector<Real>, 3> F;       // force per solid volume [N/m^3]
    std::array<std::vector<Real>, 3> velocityIntegral;  // sum dt v_new
    Real time = 0;                            // sum dt
    // Virtual mass (optional; 0: none, nothing is computed): the grains
    // carry added mass Cvm rho_f V_s and receive Cvm rho_f V_s a_f, with
    // a_f the fluid acceleration DU/Dt at the nodes, so the update becomes
    // (m + M_a + dt K) v = p + M_a v_old + dt (f + V_s F + K U + M_a a_f).
    Real addedMassDensity = 0;                // Cvm rho_f [kg/m^3]
    std::array<std::vector<Real>, 3> fluidAcceleration;

    // MPM_NO_FLUID_COUPLING compiles the step without the coupling terms
    // (benchmarks/effectsCost: what the hooks cost a pure-MPM run)
#ifdef MPM_NO_FLUID_COUPLING
    static constexpr bool active() { return false; }
#else
    bool active() const { return !K.empty(); }
#endif
    void resetIntegral();
    // Sizes the arrays to nNodes padded nodes, all zero (no drag, force or
    // fluid velocity yet); the added mass stays off, its array empty
    void resize(Index nNodes);
};

class MpmSystem
{
public:
    // Loops over fewer items than this run on one thread (tests lower it).
    static Index parallelThreshold;

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

    // The lattice the arrays live on: the domain, or this rank's box.
    Lattice& lattice() { return lattice_; }
    const Lattice& lattice() const { return lattice_; }
    // The whole domain (walls, periodicity, the seeding check).
    const Lattice& domain() const { return domain_; }
    const Subdomain* subdomain() const { return subdomain_.get(); }

    // Nodes a stencil reaches beyond its point's cell: 1 (LH, QBS), 2 (CBS).
    static int stencilReach(ShapeKind kind);

    // Decomposed runs: sends every point whose cell another rank owns to
    // that rank (all its fields); returns the number sent. Called by step()
    // after the points move; call it after reading or seeding points too.
    // Throws std::runtime_error (not NonFiniteError) if a point moved beyond
    // this rank's halo in one step.
    Index migrate();
    // Points this rank has sent to others so far.
    Index migratedCount() const { return migrated_; }

    // Global reductions (identity in serial runs).
    Real sumAll(Real x) const { return subdomain_ ? subdomain_->comm().sum(x) : x; }
    Real maxAll(Real x) const { return subdomain_ ? subdomain_->comm().max(x) : x; }
    const Boundary& boundary() const { return boundary_; }

    // Walls of any shape (grid/levelSet.hpp), after setup: their node
    // planes on this rank's lattice. unsolved: the coordinate of a 2D
    // case's mid-plane along its unsolved axis. Empty: none, nothing is
    // computed. Throws std::invalid_argument for a bad wall.
    void setLevelSetWalls(std::vector<LevelSetWall> walls, const std::array<Real, 3>& unsolved);
    const LevelSetWalls& levelSetWalls() const { return levelSet_; }
    // Moving level-set walls (translations), before a step: each wall's
    // displacement at the step's start and its velocity over the step
    // (LevelSetWalls::move). The node condition then holds the material to
    // the wall's velocity, and containment uses the wall at the step's end.
    void moveLevelSetWalls
    (
        const std::vector<std::array<Real, 3>>& displacement,
        const std::vector<std::array<Real, 3>>& velocity
    );
    // Points put back on a level-set wall's surface after a step, on this
    // rank since setup (the node condition keeps most outside; the rest
    // are within a fraction of a cell)
    Index levelSetContainedCount() const { return contained_; }
    const StepOptions& options() const { return options_; }
    // The step's phases in order (step/stepPlan.hpp), built by setup
    const StepPlan& plan() const { return plan_; }
    // Tests: every phase a step runs appended to *out (null: none)
    void recordPhases(std::vector<Phase>* out) { recordPhases_ = out; }
    // The points. With the resident device step the host holds a copy,
    // brought up to date here when the device is ahead; the non-const
    // access counts as a change, uploaded before the next step.
    Particles& particles() { pullPoints(); hostAhead_ = true; return particles_; }
    const Particles& particles() const { pullPoints(); return particles_; }
    // The number of points on this rank (no transfer: the host and the
    // device always hold the same points)
    Index pointCount() const { return particles_.size(); }
    // Why the resident device step does not run this case ("" when it
    // does, or when the back-end has none: cuda or the stand-in only)
    std::string residentUnsupported() const;
    // Whether the last step ran resident on the device (or its stand-in)
    bool lastStepResident() const { return lastResident_; }
    const GridState& grid() const { return grid_; }
    const StepTimers& timers() const { return timers_; }
    // The 3D non-APIC P2G's loop choice and its trial times (p2gRowChoice.hpp)
    const P2gRowChoice& p2gRowChoice() const { return p2gRows_; }
    Index stepCount() const { return stepCount_; }
    // Points the last stress update compressed to J <= 0 or volume <= 0,
    // on this rank (a NaN is the non-finite stop's): how many, and the one
    // of lowest id with its material, J and volume. Found in the update's
    // own loop, so checking costs no pass over the points.
    struct InvertedPoints
    {
        Index count = 0;
        std::int64_t id = 0;
        int material = -1;
        Real J = 0;
        Real volume = 0;
    };
    const InvertedPoints& inverted() const { return inverted_; }

    // Nodes of the last step's active region (all nodes: sparseGrid off)
    Index activeNodeCount() const { return Index(region_.nodes().size()); }
    void setGravity(const std::array<Real, 3>& g) { options_.gravity = g; }
    void setConstantGrainVolume(bool on) { options_.constantGrainVolume = on; }

    // Fluid coupling arrays, sized by the caller (padded nodes); see above.
    FluidCoupling& coupling() { return coupling_; }
    const FluidCoupling& coupling() const { return coupling_; }

    std::vector<std::unique_ptr<ConstitutiveLaw>>& materials() { return materials_; }
    // The largest friction coefficient a friction wall applies: the largest
    // shear strength ratio of the materials that have points (walls.cpp)
    Real computeFrictionCap() const;
    // The largest coefficient of the friction walls, box and level-set
    // walls alike; 0 without friction walls
    Real largestWallFriction() const;
    const ConstitutiveLaw& material(int m) const { return *materials_[m]; }

    // Advances by dt. Throws NonFiniteError on NaN/inf.
    void step(Real dt);

    // Largest signal speed max_p (c_p + |v_p|) for the Courant number.
    Real maxSignalSpeed() const;

    // Explicit stable step for Courant number `courant`, also honouring
    // each law's own bound (e.g. viscous diffusion).
    Real stableDeltaT(Real courant) const;

    // Maps mass, volume and momentum to the grid at the current positions
    // and sets grid().velocity; for output at any time. With
    // `grainVolume`, also a copy of the grid volume right after the P2G:
    // this rank's points only, before any halo sum or ghost fold (for
    // spreadGrainVolume).
    void mapToGrid(std::vector<Real>* grainVolume = nullptr);

    // The grid's mass, volume and velocity where a mesh samples them, after
    // mapToGrid() or a step: serial, the grid itself; decomposed, a copy
    // whose every node of the exchange halo holds its owner's values (a
    // mesh cell overlapping a lattice cell another rank owns: meshLattice's
    // own lattice; Subdomain::HaloKind). A copy, not the grid: the grid's
    // nodes outside the active region must stay zero.
    struct GridSample
    {
        const Real* mass;
        const Real* volume;
        std::array<const Real*, 3> velocity;
    };
    GridSample sampleGrid();
    // The same for any node arrays: every copy of the exchange halo summed
    // into its owner, or the owners' values sent to their copies
    // (decomposed; serial: the periodic copies). For an exchange with a
    // mesh whose cells touch another rank's nodes (fluidCoupling on a
    // lattice of its own).
    void sumToOwners(const std::vector<Real*>& arrays) { sumHalo(arrays, Subdomain::HaloKind::exchange); }
    void copyToHalo(const std::vector<Real*>& arrays) const { copyHalo(arrays, Subdomain::HaloKind::exchange); }

    // Grain volume (mass/rho0) of each material's points, spread to the
    // nodes with the shape functions and folded from the ghosts like the
    // grid volume: out[material][node]. The sum over materials is
    // grid().volume after mapToGrid() with constant grain volume. For
    // coupling models that differ per material (drag); one extra P2G.
    // Decomposed: the owners' values on every copy of the exchange halo.
    void materialGrainVolume(std::vector<std::vector<Real>>& out);

    // The grain volume (mass/rho0) of the points spread to the nodes with
    // the shape functions, each point's weights renormalised over its
    // stencil's coverage (per padded node, the share of its lattice cell
    // inside the mesh, 0..1): sum_I spread[I] coverage[I] is the points'
    // grain volume exactly, so a mesh that covers only part of the lattice
    // receives all of it (meshLattice's own lattice, fluidCoupling). No
    // ghost fold: ghosts lie outside the mesh (coverage 0). The coverage
    // does not change: set once. At every exchange, mapToGrid(&spread) and
    // then spreadGrainVolume(spread), with the points unmoved between: a
    // point whose stencil lies on fully covered nodes (|coverage - 1| <=
    // fullCoverage) keeps its P2G grain volume; only the others pay for a
    // second stencil.
    void setCoverage(const std::vector<double>& coverage);
    void spreadGrainVolume(std::vector<Real>& spread) const;
    static constexpr double fullCoverage = 1e-12;

    // Number of points outside the domain (seeding checks), on this rank.
    Index countOutside() const;

    // Open boundaries (grid/boundary.hpp): a point that crosses an open
    // face (outlet or inlet) is removed right after it moves. Per boundary
    // condition (index into the BoundarySpec's conditions): the count and
    // mass removed on this rank since setup. A point that would cross a
    // wall face is put back just inside it instead (a step far too large):
    // counted too, so that clamping can never hide a loss.
    const std::vector<Index>& removedCount() const { return removedCount_; }
    const std::vector<Real>& removedMass() const { return removedMass_; }
    Index clampedCount() const { return clamped_; }

private:
    template<class K, int D> void stepImpl(Real dt);
    // The cuda back-end (backend/deviceStep.hpp): the step with the point
    // work on the device and the node work here, as in stepImpl
    template<class K, int D> void stepOnDevice(Real dt);
    // The resident device step (backend/residentStep.hpp) and its host copy
    void stepResident(Real dt);
    ResidentConfig residentConfig() const;
    // Brings the host's points up to date when the device is ahead
    void pullPoints() const;
    void sortByStencil();
    void stressOnDevice(Real dt);
    void movePointsOnDevice(bool apic, Real dt);
    // The open condition through which a point beyond a face at x leaves,
    // or -1 when walls hold it (beyondWall: it lies past one)
    int exitCondition(const Real x[3], bool& beyondWall) const;
    // Marks a point beyond a face as leaving (true) or counts it clamped
    bool leavesThroughFace(Index p, const Real x[3], Index& leaving, Index& clamped);
    // Removes the `leaving` points marked in leaving_, counted per condition
    void removeLeaving(Index leaving);
    // inverted_ for its count: the inverted point of lowest id
    void findFirstInverted();
    // Per material: the law's kernel parameters, 1/rho0
    std::vector<LawParams> lawTable() const;
    std::vector<Real> inverseDensities() const;
    // P2G; massMomentum (a fresh P2G) must come right after binPoints()
    template<class K, int D> void scatter(bool massMomentum, bool force, bool velocityOnly);
    template<class K, int D, bool MassMomentum, bool Force, bool Apic, bool Rows> void scatterKernel();
    template<class K, int D> void gather(Real dt);
    template<class K, int D, bool Apic> void gatherKernel(Real dt);
    template<class K, int D> void gradientFromGrid(const std::array<std::vector<Real>, 3>& v);
    // x = (M + diag)^-1 rhs, M lumped or consistent (Jacobi sweeps)
    template<class K, int D> void solveMass(const std::array<std::vector<Real>, 3>& rhs, std::array<std::vector<Real>, 3>& x,
                                            const std::vector<Real>* diag = nullptr);
    template<class Fn> void dispatch(Fn&& f) const;
    // Whether a CPU loop over n items runs on several threads (openmp and
    // n >= parallelThreshold)
    bool worthThreads(Index n) const;
    template<class Fn> void forEachPointColoured(Fn&& fn) const;
    // fn(p, nodes): each point with its stencil (the grain-volume maps)
    template<class Fn> void forEachPointStencil(Fn&& fn);
    // Bins the points and builds this step's active region
    void binPoints();
    // fn(node) for every node of the active region (threaded when long)
    template<class Fn> void forEachActiveNode(Fn&& fn) const;

    enum FoldWhat : unsigned { foldMass = 1, foldMomentum = 2, foldForce = 4 };
    // Adds every halo copy of the chosen arrays into its owner (after P2G,
    // before the wall fold and contact decision), or sends the owners'
    // values back to the copies (after the fill, before G2P). Decomposed:
    // the Subdomain's halo across ranks; serial: the periodic copies.
    void sumHalo(unsigned what);
    // The arrays' lattice (the domain, or subdomain_'s box) with its
    // boundary, and the node arrays and active region sized on it (setup,
    // changeSubdomain)
    void buildNodes(const BoundarySpec& spec);
    void sumHalo(const std::vector<Real*>& arrays, Subdomain::HaloKind kind = Subdomain::HaloKind::step);
    void copyHalo(const std::vector<Real*>& arrays, Subdomain::HaloKind kind = Subdomain::HaloKind::step) const;
    // Stops every rank with the same message when any point went non-finite
    // (firstBad: the local index of this rank's first bad point, or n).
    void stopIfNonFinite(Index firstBad, const char* what);
    void foldGhosts(unsigned what);
    // Adds each ghost's scalar into its image, then copies images to ghosts
    void foldScalar(std::vector<Real>& a) const;
    void foldVector(std::array<std::vector<Real>, 3>& a) const;
    void decideWallContact(Real dt, bool withForce);
    void fillGhosts(std::array<std::vector<Real>, 3>& v) const;
    void nodalVelocity(std::array<std::vector<Real>, 3>& v);
    void updateMassTolerance();
    // m g on every node, from the P2G masses (before the halo sum and fold)
    void addGravity();
    template<class K, int D> void nodalUpdate(Real dt);
    // The node work after the fresh P2G, and after the MUSL re-map (shared
    // by the host and device steps)
    template<class K, int D> void nodalAfterScatter(Real dt, bool withForce);
    template<class K, int D> void nodalAfterRemap();
    template<class K, int D> void massToVelocity(std::array<std::vector<Real>, 3>& v);
    // Coulomb friction of friction walls on the updated velocity, bounded
    // by the normal impulse of the wall's fold (momentum + dt force of its
    // contact ghosts) and contact at each node
    void applyFriction(std::array<std::vector<Real>, 3>& v, Real dt);
    void decideFrictionStick(Real dt, bool withForce);
    // The level-set walls' node condition on an updated velocity
    void applyLevelSetWalls(std::array<std::vector<Real>, 3>& v);
    // Puts points inside a level-set wall back on its surface (moving walls
    // where they are at the end of the step dt); marks those beyond a
    // level-set outlet in leaving_ (sized by the caller) and returns their
    // number
    Index containPoints(Real dt);
    void updateStress(Real dt);
    void movePoints(Real dt);

    Lattice domain_;
    Lattice lattice_;
    std::shared_ptr<const Subdomain> subdomain_;
    std::array<std::vector<Real>, 5> sample_;   // sampleGrid's copies
    Boundary boundary_;
    LevelSetWalls levelSet_;
    Index contained_ = 0;
    StepOptions options_;
    StepPlan plan_;
    std::vector<Phase>* recordPhases_ = nullptr;
    Particles particles_;
    std::vector<std::unique_ptr<ConstitutiveLaw>> materials_;
    GridState grid_;
    // setCoverage: per node, the coverage, and whether every node of the
    // stencil whose first node it is is fully covered
    std::vector<double> coverage_;
    std::vector<unsigned char> coveredStencil_;
    template<class K, int D> void spreadOverCoverage(std::vector<Real>& spread) const;
    Binning binning_;
    ActiveRegion region_;
    mutable StepTimers timers_;
    P2gRowChoice p2gRows_;
    FluidCoupling coupling_;
    Index stepCount_ = 0;
    Index migrated_ = 0;
    InvertedPoints inverted_;
    Real massTolerance_ = 0;
    std::vector<Index> removedCount_;
    std::vector<Real> removedMass_;
    Index clamped_ = 0;
    // Per point during movePoints: the open condition it left through, or -1
    std::vector<int> leaving_;
    // The cuda back-end's device mirror and step (null for the CPU ones);
    // shared_ptr: its deleter is bound where it is made, so this header
    // compiles the same with and without CUDA
    std::shared_ptr<DeviceStep> device_;
    std::vector<int> moveFlags_;
    std::shared_ptr<ResidentStep> resident_;
    ResidentConfig residentKey_;            // what resident_ was configured with
    bool residentConfigured_ = false;
    bool levelSetChanged_ = true;           // the level set to upload again
    bool hostAhead_ = true;                 // host points changed since the upload
    mutable bool deviceAhead_ = false;      // device points newer than the host's
    bool lastResident_ = false;

    // Scratch per point: velocity gradient and displacement over the step.
    std::array<std::vector<Real>, 9> L_;
    std::array<std::vector<Real>, 3> dx_;

    // Reflection signs of each ghost for this step: the boundary's, with
    // the normal sign of unilateral walls released where material leaves.
    std::vector<std::array<Real, 3>> ghostSign_;
    // Per node and wall axis: the normal impulse of friction walls in this
    // step (applyFriction; zero between its calls)
    std::array<std::vector<Real>, 3> wallImpulse_;
    // Per node and wall axis: 1 where a friction wall's image sticks this
    // step (decideFrictionStick)
    std::array<std::vector<Real>, 3> wallStuck_;
    // this step's computeFrictionCap (decideWallContact), for box and
    // level-set friction walls
    Real frictionCap_ = std::numeric_limits<Real>::infinity();

    // Scratch for the consistent-mass sweeps: per point and per node.
    std::array<std::vector<Real>, 3> pointScratch_;
    std::array<std::vector<Real>, 3> nodeScratch_, nodeRhs_;
    std::vector<Real> nodeDiag_;             // coupling: dt K + M_a
};

} // namespace mpm

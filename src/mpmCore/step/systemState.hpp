// The state of one MPM model, in one place: the lattice and its boundary,
// the options and step plan, the points, the node arrays, the counters of
// the run, the back-ends' device mirrors and the step's scratch arrays.
//
// MpmSystem (step/mpmSystem.hpp) owns one and is its public face; the
// phases of the step (phases/*.hpp) are free functions that take it, and
// the launchers (launchers/launchers.hpp) run the plan's phases on it, one
// launcher per back-end. A plain struct: every phase reads and writes what
// it needs, and this header says what there is.
#pragma once
#include "../backend/deviceStep.hpp"
#include "../backend/residentStep.hpp"
#include "../constitutive/constitutiveLaw.hpp"
#include "../grid/activeRegion.hpp"
#include "../grid/boundary.hpp"
#include "../grid/gridState.hpp"
#include "../grid/lattice.hpp"
#include "../grid/levelSet.hpp"
#include "../kernels/views.hpp"
#include "../parallel/subdomain.hpp"
#include "../particles/particles.hpp"
#include "../transfer/binning.hpp"
#include "fluidCoupling.hpp"
#include "p2gRowChoice.hpp"
#include "stepOptions.hpp"
#include "stepPlan.hpp"
#include "stepTimers.hpp"
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

namespace mpm {

// Points the last stress update compressed to J <= 0 or volume <= 0, on
// this rank (a NaN is the non-finite stop's): how many, and the one of
// lowest id with its material, J and volume. Found in the update's own
// loop, so checking costs no pass over the points.
struct InvertedPoints
{
    Index count = 0;
    std::int64_t id = 0;
    int material = -1;
    Real J = 0;
    Real volume = 0;
};

struct SystemState
{
    // Loops over fewer items than this run on one thread (tests lower it).
    static Index parallelThreshold;

    // The model
    Lattice domain;                          // the whole domain
    Lattice lattice;                         // the arrays' (domain or this rank's box)
    std::shared_ptr<const Subdomain> subdomain;   // null: serial
    Boundary boundary;
    LevelSetWalls levelSet;
    StepOptions options;
    StepPlan plan;
    Particles particles;
    std::vector<std::unique_ptr<ConstitutiveLaw>> materials;
    GridState grid;
    FluidCoupling coupling;

    // This step's bins of points and the nodes they reach
    Binning binning;
    ActiveRegion region;
    // Nodes lighter than this get zero velocity (updateMassTolerance)
    Real massTolerance = 0;

    // Instrumentation: phase times, the P2G loop choice, and (tests) the
    // phases a step runs appended to *recordPhases
    mutable StepTimers timers;
    P2gRowChoice p2gRows;
    std::vector<Phase>* recordPhases = nullptr;

    // Counts of the run, on this rank
    Index stepCount = 0;
    Index migrated = 0;                      // points sent to other ranks
    Index contained = 0;                     // points put back on a level-set wall
    Index clamped = 0;                       // points held just inside a box wall
    std::vector<Index> removedCount;         // per boundary condition
    std::vector<Real> removedMass;
    InvertedPoints inverted;                 // the last stress update's

    // The grid maps' state (phases/gridMaps.hpp): the mesh's coverage per
    // node, whether every node of the stencil whose first node it is is
    // fully covered, and sampleGrid's copies
    std::vector<double> coverage;
    std::vector<unsigned char> coveredStencil;
    std::array<StaggeredArray<Real>, 5> sample;

    // The cuda back-end's device mirror (null for the CPU ones) and the
    // resident step; shared_ptr: the deleter is bound where each is made,
    // so this header compiles the same with and without CUDA
    std::shared_ptr<DeviceStep> device;
    std::shared_ptr<ResidentStep> resident;
    ResidentConfig residentKey;              // what resident was configured with
    bool residentConfigured = false;
    bool levelSetChanged = true;             // the level set to upload again
    bool hostAhead = true;                   // host points changed since the upload
    mutable bool deviceAhead = false;        // device points newer than the host's
    bool lastResident = false;

    // Scratch per point: velocity gradient and displacement over the step;
    // per point during the move: the open condition it leaves through, or
    // -1; the device move's flags (kernels/movePoint.hpp)
    std::array<StaggeredArray<Real>, 9> velocityGradient;
    std::array<StaggeredArray<Real>, 3> displacement;
    std::vector<int> leavingThrough;
    std::vector<int> moveFlags;

    // Walls, this step (phases/walls.hpp): each ghost's reflection signs
    // (the boundary's, the normal sign of unilateral walls released where
    // material leaves); per node and wall axis the friction walls' normal
    // impulse (zero between applyFriction's calls) and where their image
    // sticks; the friction cap (computeFrictionCap)
    std::vector<std::array<Real, 3>> ghostSign;
    std::array<StaggeredArray<Real>, 3> wallImpulse;
    std::array<StaggeredArray<Real>, 3> wallStuck;
    Real frictionCap = std::numeric_limits<Real>::infinity();

    // Scratch for the consistent-mass sweeps and the nodal solve: per
    // point and per node; the coupling's diagonal dt K + M_a
    std::array<StaggeredArray<Real>, 3> pointScratch;
    std::array<StaggeredArray<Real>, 3> nodeScratch, nodeRhs;
    std::vector<Real> nodeDiag;

    // The arrays' lattice (the domain, or the subdomain's box) with its
    // boundary, and the node arrays and active region sized on it
    void buildNodes(const BoundarySpec& spec);
    // The per-point scratch sized to the points
    void sizePointScratch();
    // The points' arrays as the kernels see them (kernels/views.hpp)
    PointView points() { return pointView(particles, velocityGradient, displacement); }
    // Brings the host's points up to date when the resident step's are ahead
    void pullPoints() const;

    // Global reductions (identity in serial runs)
    Real sumAll(Real x) const { return subdomain ? subdomain->comm().sum(x) : x; }
    Real maxAll(Real x) const { return subdomain ? subdomain->comm().max(x) : x; }
    // Stops every rank with the same message when any point went non-finite
    // (firstBad: the local index of this rank's first bad point, or n);
    // throws NonFiniteError
    void stopIfNonFinite(Index firstBad, const char* what);
    // inverted for its count: the inverted point of lowest id
    void findFirstInverted();
    // Per material: the law's kernel parameters (once per step, no virtual
    // call per point), 1/rho0 (a point's grain volume is its mass times it)
    std::vector<LawParams> lawTable() const;
    std::vector<Real> inverseDensities() const;

    // Whether a CPU loop over n items runs on several threads (openmp and
    // n >= parallelThreshold)
    bool worthThreads(Index n) const;
    // f(K{}, integral_constant<int, D>{}): the kernels are instantiated per
    // shape function K and number of solved directions D
    template<class Fn> void dispatch(Fn&& f) const;
    // fn(p) for every point, blocks of one colour in parallel, so that fn
    // may scatter to its stencil's nodes with plain stores (transfer/binning.hpp)
    template<class Fn> void forEachPointColoured(Fn&& fn) const;
    // fn(node) for every node of the active region (threaded when long)
    template<class Fn> void forEachActiveNode(Fn&& fn) const;
};

// Nodes a stencil reaches beyond its point's cell: 1 (LH, QBS), 2 (CBS).
int stencilReach(ShapeKind kind);

template<class Fn>
void SystemState::dispatch(Fn&& f) const
{
    dispatchShape(options.shape, [&](auto k)
    {
        switch (lattice.dim)
        {
            case 1: f(k, std::integral_constant<int, 1>{}); break;
            case 2: f(k, std::integral_constant<int, 2>{}); break;
            default: f(k, std::integral_constant<int, 3>{}); break;
        }
    });
}

template<class Fn>
void SystemState::forEachPointColoured(Fn&& fn) const
{
    const std::vector<Index>& order = binning.order();
    for (int c = 0; c < binning.nColours(); ++c)
    {
        const Index k0 = binning.colourBegin(c), k1 = binning.colourBegin(c + 1);
        #pragma omp parallel for schedule(dynamic, 1) if(worthThreads(Index(order.size())))
        for (Index key = k0; key < k1; ++key)
        {
            for (Index q = binning.start(key); q < binning.start(key + 1); ++q)
            {
                fn(order[q]);
            }
        }
    }
}

template<class Fn>
void SystemState::forEachActiveNode(Fn&& fn) const
{
    const std::vector<Index>& list = region.nodes();
    const Index n = Index(list.size());
    #pragma omp parallel for if(worthThreads(n))
    for (Index k = 0; k < n; ++k) fn(list[k]);
}

} // namespace mpm

#include "mpmSystemLoops.hpp"
#include "../constitutive/tensorOps.hpp"
#include "../kernels/frictionWall.hpp"
#include "../kernels/g2p.hpp"
#include "../kernels/levelSetWall.hpp"
#include "../kernels/movePoint.hpp"
#include "../kernels/nodal.hpp"
#include "../kernels/p2g.hpp"
#include "../kernels/signalSpeed.hpp"
#include "../kernels/stressPoint.hpp"
#include "../kernels/views.hpp"
#include "../transfer/stencil.hpp"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace mpm {

void MpmSystem::setup
(
    const Lattice& lattice, const BoundarySpec& spec, const StepOptions& options,
    std::shared_ptr<const Subdomain> subdomain
)
{
    const std::string unavailable = backendUnavailableReason(options.backend);
    if (!unavailable.empty())
    {
        throw std::invalid_argument
        (
            std::string("backend ") + backendName(options.backend) + ": " + unavailable
        );
    }
    domain_ = lattice;
    domain_.finalise();
    options_ = options;
    subdomain_ = std::move(subdomain);
    buildNodes(spec);
    plan_ = makeStepPlan(options_);
    p2gRows_ = P2gRowChoice(options_.p2gRowLoop);
    removedCount_.assign(spec.conditions.size(), 0);
    removedMass_.assign(spec.conditions.size(), 0.0);
    clamped_ = 0;
    contained_ = 0;
    levelSet_ = LevelSetWalls();
    // Gravity along unsolved directions has nothing to act on.
    for (int a = 0; a < 3; ++a) if (!lattice_.solved[a]) options_.gravity[a] = 0;
    // Available (checked above): the device mirror, sized by the first step
    if (options_.backend != Backend::cuda) device_.reset();
#ifdef MPM_HAVE_CUDA
    else if (!device_) device_ = std::make_shared<DeviceStep>();
#endif
    // The resident step, where the case allows it (residentUnsupported)
    pullPoints();
    resident_.reset();
    if (options_.residentStandIn) resident_ = makeResidentStandIn();
#ifdef MPM_HAVE_CUDA
    else if (options_.backend == Backend::cuda && options_.deviceResident) resident_ = makeResidentCuda();
#endif
    residentConfigured_ = false;
    levelSetChanged_ = true;
    hostAhead_ = true;
    lastResident_ = false;
}

void MpmSystem::buildNodes(const BoundarySpec& spec)
{
    if (subdomain_)
    {
        const Subdomain& sd = *subdomain_;
        lattice_ = sd.local();
        boundary_.build(domain_, spec, lattice_, sd.offset(), [&sd](Index c) { return sd.ownsCell(c); });
    }
    else
    {
        lattice_ = domain_;
        boundary_.build(lattice_, spec);
    }
    grid_.resize(lattice_.nNodes);
    region_ = ActiveRegion();
    region_.setDense(!options_.sparseGrid);
}

void MpmSystem::changeSubdomain(std::shared_ptr<const Subdomain> subdomain)
{
    pullPoints();
    const BoundarySpec spec = boundary_.spec();
    subdomain_ = std::move(subdomain);
    buildNodes(spec);
    levelSet_.relocate(lattice_);
    levelSetChanged_ = true;
    if (!coupling_.K.empty()) coupling_.resize(lattice_.nNodes);
    coverage_.clear();
    coveredStencil_.clear();
    for (auto& a : sample_) a.clear();
    // The device mirrors are sized by the next step
#ifdef MPM_HAVE_CUDA
    if (device_) device_ = std::make_shared<DeviceStep>();
#endif
    residentConfigured_ = false;
    hostAhead_ = true;
}

int MpmSystem::stencilReach(ShapeKind kind)
{
    return dispatchShape(kind, [](auto k) { return decltype(k)::width/2; });
}

Index MpmSystem::parallelThreshold = 50000;

// Below MpmSystem::parallelThreshold work items a loop runs serially: a
// parallel region costs microseconds on an idle machine but a scheduler time
// slice (milliseconds) when another process holds a core, and small loops
// gain nothing from two threads.
// With the serial back-end every loop runs on one thread.
bool MpmSystem::worthThreads(Index n) const
{
    return options_.backend == Backend::openmp && n >= parallelThreshold;
}

void MpmSystem::binPoints()
{
    binning_.build(lattice_, particles_);
    if (options_.reorderPoints && binning_.fragmented())
    {
        particles_.permute(binning_.order());
        binning_.setIdentityOrder();
        hostAhead_ = true;
    }
    static const std::vector<Index> none;
    auto& g = grid_;
    region_.build
    (
        lattice_, binning_, stencilReach(options_.shape), boundary_,
        subdomain_ ? subdomain_->haloNodeList() : none,
        {
            g.mass.data(), g.volume.data(),
            g.momentum[0].data(), g.momentum[1].data(), g.momentum[2].data(),
            g.force[0].data(), g.force[1].data(), g.force[2].data(),
            g.velocityOld[0].data(), g.velocityOld[1].data(), g.velocityOld[2].data(),
            g.velocity[0].data(), g.velocity[1].data(), g.velocity[2].data()
        }
    );
}

void MpmSystem::step(Real dt)
{
    lastResident_ = resident_ && residentUnsupported().empty();
    if (lastResident_) stepResident(dt);
    else
    {
        pullPoints();
        dispatch([&](auto k, auto d) { stepImpl<decltype(k), decltype(d)::value>(dt); });
    }
    ++stepCount_;
}

void MpmSystem::mapToGrid(std::vector<Real>* grainVolume)
{
    pullPoints();
    updateMassTolerance();
    dispatch([&](auto k, auto d)
    {
        binPoints();
        scatter<decltype(k), decltype(d)::value>(true, false, false);
        if (grainVolume) grainVolume->assign(grid_.volume.begin(), grid_.volume.end());
        sumHalo(foldMass | foldMomentum);
        foldGhosts(foldMass);
        decideWallContact(0, false);
        foldGhosts(foldMomentum);
        massToVelocity<decltype(k), decltype(d)::value>(grid_.velocity);
        fillGhosts(grid_.velocity);
    });
}

// fn(p, nodes) for every point, blocks of one colour in parallel (plain
// stores into node arrays are safe), where nodes(visit) calls visit(I, N)
// for each node of p's stencil: the P2G loop of the grain-volume maps
template<class Fn>
void MpmSystem::forEachPointStencil(Fn&& fn)
{
    const auto& P = particles_;
    dispatch([&](auto k, auto d)
    {
        using K = decltype(k);
        constexpr int D = decltype(d)::value;
        binning_.build(lattice_, particles_);
        forEachPointColoured([&](Index p)
        {
            Stencil<K, D> s;
            s.compute(lattice_, P.x[0][p], P.x[1][p], P.x[2][p]);
            fn(p, [&](auto&& visit)
            {
                s.forEachWeight(lattice_, [&](Index I, Real N) { visit(I, N); });
            });
        });
    });
}

void MpmSystem::materialGrainVolume(std::vector<std::vector<Real>>& out)
{
    pullPoints();
    out.assign(materials_.size(), std::vector<Real>(lattice_.nNodes, 0.0));
    const std::vector<Real> invRho0 = inverseDensities();
    const auto& P = particles_;
    forEachPointStencil([&](Index p, auto&& nodes)
    {
        const int m = P.material[p];
        const Real v = P.mass[p]*invRho0[m];
        Real* o = out[m].data();
        nodes([&](Index I, Real N) { o[I] += N*v; });
    });
    for (auto& o : out)
    {
        sumHalo({o.data()});
        foldScalar(o);
        if (subdomain_) copyHalo({o.data()}, Subdomain::HaloKind::exchange);
    }
}

MpmSystem::GridSample MpmSystem::sampleGrid()
{
    auto& g = grid_;
    if (!subdomain_) return {g.mass.data(), g.volume.data(), {g.velocity[0].data(), g.velocity[1].data(), g.velocity[2].data()}};
    sample_[0] = g.mass;
    sample_[1] = g.volume;
    for (int d = 0; d < 3; ++d) sample_[2 + d] = g.velocity[d];
    std::vector<Real*> all;
    for (auto& a : sample_) all.push_back(a.data());
    copyHalo(all, Subdomain::HaloKind::exchange);
    return {sample_[0].data(), sample_[1].data(), {sample_[2].data(), sample_[3].data(), sample_[4].data()}};
}

void MpmSystem::setCoverage(const std::vector<double>& coverage)
{
    const Lattice& L = lattice_;
    if (coverage.size() != std::size_t(L.nNodes))
    {
        throw std::invalid_argument("setCoverage: one value per node of the lattice");
    }
    coverage_ = coverage;
    int width = 0;
    dispatch([&](auto k, auto) { width = decltype(k)::width; });
    auto& full = coveredStencil_;
    full.resize(coverage.size());
    for (std::size_t I = 0; I < full.size(); ++I)
    {
        full[I] = std::abs(coverage[I] - 1) <= fullCoverage;
    }
    // Whether the W nodes from I on are all full, along each solved axis
    // in turn: then the stencil whose first node is I is (a stencil past
    // the padded lattice counts as uncovered)
    std::vector<unsigned char> in;
    for (int a = 0; a < 3; ++a)
    {
        if (!L.solved[a]) continue;
        in = full;
        const Index n = L.nodes[a], stride = L.stride[a];
        for (Index I = 0; I < L.nNodes; ++I)
        {
            const Index i = (I/stride) % n;
            unsigned char f = i + width <= n;
            for (int o = 0; f && o < width; ++o) f = in[std::size_t(I + o*stride)];
            full[std::size_t(I)] = f;
        }
    }
}

void MpmSystem::spreadGrainVolume(std::vector<Real>& spread) const
{
    if (coverage_.size() != std::size_t(lattice_.nNodes) || spread.size() != coverage_.size())
    {
        throw std::logic_error("spreadGrainVolume: needs setCoverage and mapToGrid(&spread) on this lattice");
    }
    if (!options_.constantGrainVolume)
    {
        throw std::logic_error("spreadGrainVolume: the grid volume is not the grain volume (setConstantGrainVolume)");
    }
    // The P2G's grain volume is the spread for every point whose stencil
    // is fully covered: the others are corrected
    dispatch([&](auto k, auto d)
    {
        spreadOverCoverage<decltype(k), decltype(d)::value>(spread);
    });
}

template<class K, int D>
void MpmSystem::spreadOverCoverage(std::vector<Real>& spread) const
{
    const Lattice& L = lattice_;
    const auto& P = particles_;
    const std::vector<Real> invRho0 = inverseDensities();
    Real* o = spread.data();
    const double* cov = coverage_.data();
    const Real invh = 1.0/L.h;
    for (Index p = 0; p < P.size(); ++p)
    {
        // The first node of the point's stencil (Stencil::compute's base)
        Index first = 0;
        for (int a = 0; a < 3; ++a)
        {
            if (!L.solved[a]) continue;
            // The same expression as Stencil::compute's, so the same bits
            const Index b = K::baseOf((P.x[a][p] - L.origin[a])*invh - 0.5 + L.pad);
            first += std::min(std::max(b, Index(0)), Index(L.nodes[a] - 1))*L.stride[a];
        }
        if (coveredStencil_[std::size_t(first)]) continue;
        Stencil<K, D> s;
        s.compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
        const Real v = P.mass[p]*invRho0[P.material[p]];
        // By rows of W nodes, as the P2G's rows: short sums rather than
        // one chain of W^D dependent additions
        const Index s0 = L.stride[L.axes[0]];
        Real covered = 0;
        s.forEachRow(L, [&](Index first, Real wjk)
        {
            Real row = 0;
            for (int i = 0; i < K::width; ++i) row += s.w[0][i]*cov[first + i*s0];
            covered += wjk*row;
        });
        // The P2G gave N v; the spread is N v/covered. A point with no
        // covered node (outside the mesh) gives nothing.
        const Real extra = covered > 0 ? v/covered - v : -v;
        s.forEachRow(L, [&](Index first, Real wjk)
        {
            const Real e = wjk*extra;
            for (int i = 0; i < K::width; ++i) o[first + i*s0] += s.w[0][i]*e;
        });
    }
}

template<class K, int D>
void MpmSystem::stepImpl(Real dt)
{
#ifdef MPM_HAVE_CUDA
    if (device_) { stepOnDevice<K, D>(dt); return; }
#endif
    const Index n = particles_.size();
    for (auto& a : L_) a.resize(n);
    for (auto& a : dx_) a.resize(n);
    updateMassTolerance();
    const bool withForce = plan_.forceWithScatter;
    // The host's phases, in the plan's order (step/stepPlan.hpp)
    runPlan(plan_, timers_, [&](Phase phase)
    {
        switch (phase)
        {
            case Phase::scatter: binPoints(); scatter<K, D>(true, withForce, false); break;
            case Phase::nodalAfterScatter: nodalAfterScatter<K, D>(dt, withForce); break;
            case Phase::gradientFromOld: gradientFromGrid<K, D>(grid_.velocityOld); break;
            case Phase::stress: updateStress(dt); break;
            // The internal force, added to the gravity already there
            case Phase::scatterForce: scatter<K, D>(false, true, false); break;
            case Phase::foldForce: sumHalo(foldForce); foldGhosts(foldForce); break;
            case Phase::nodalUpdate: nodalUpdate<K, D>(dt); break;
            case Phase::gather: gather<K, D>(dt); break;
            case Phase::remapMomentum: scatter<K, D>(false, false, true); break;
            case Phase::nodalAfterRemap: nodalAfterRemap<K, D>(); break;
            case Phase::gradientFromNew: gradientFromGrid<K, D>(grid_.velocity); break;
            case Phase::move: movePoints(dt); break;
            case Phase::migrate: migrate(); break;
        }
    }, recordPhases_);
}

// The node work after the step's fresh P2G (host and device steps alike):
// gravity, the halo sums, the ghost folds with the wall-contact decision,
// and the old velocity v^n with its ghosts. withForce: the P2G scattered
// the internal force too (USL, MUSL), so it is summed and folded here.
template<class K, int D>
void MpmSystem::nodalAfterScatter(Real dt, bool withForce)
{
    addGravity();
    sumHalo(foldMass | foldMomentum | (withForce ? foldForce : 0u));
    foldGhosts(foldMass);
    decideWallContact(dt, withForce);
    foldGhosts(foldMomentum | (withForce ? foldForce : 0u));
    massToVelocity<K, D>(grid_.velocityOld);
    fillGhosts(grid_.velocityOld);
}

// The node work of the MUSL re-map: the re-scattered momentum summed and
// folded, the velocity it gives (walls and friction, no force: dt = 0).
template<class K, int D>
void MpmSystem::nodalAfterRemap()
{
    sumHalo(foldMomentum);
    foldGhosts(foldMomentum);
    massToVelocity<K, D>(grid_.velocity);
    applyFriction(grid_.velocity, 0);
    applyLevelSetWalls(grid_.velocity);
    fillGhosts(grid_.velocity);
}

// P2G. massMomentum: mass, volume and momentum; force: internal force;
// velocityOnly: momentum only, from the (new) point velocities (MUSL).
// The choices become template arguments so the node loop has no branches.
template<class K, int D>
void MpmSystem::scatter(bool massMomentum, bool force, bool velocityOnly)
{
    // A fresh P2G (massMomentum) always follows binPoints, which left every
    // grid array zero; the force scatter alone (USF) adds the internal
    // force to the gravity there; the MUSL re-map starts its momentum anew.
    auto& g = grid_;
    if (velocityOnly) region_.zero({g.momentum[0].data(), g.momentum[1].data(), g.momentum[2].data()});
    auto pick = [](bool x, auto&& k) { if (x) k(std::true_type{}); else k(std::false_type{}); };
    const bool apic = options_.transfer == Transfer::apic;
    // Only the 3D P2G without APIC has the two loops to choose from
    const bool choice = D == 3 && !apic;
    const bool rows = choice ? p2gRows_.rows(stepCount_) : true;
    const auto t0 = std::chrono::steady_clock::now();
    pick(massMomentum, [&](auto mm)
    {
        pick(force, [&](auto f)
        {
            pick(apic, [&](auto a)
            {
                constexpr bool MM = decltype(mm)::value, F = decltype(f)::value, A = decltype(a)::value;
                if constexpr (D == 3 && !A)
                {
                    pick(rows, [&](auto r) { scatterKernel<K, D, MM, F, A, decltype(r)::value>(); });
                }
                else
                {
                    scatterKernel<K, D, MM, F, A, true>();
                }
            });
        });
    });
    if (choice)
    {
        p2gRows_.record(stepCount_, rows,
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
}

template<class K, int D, bool MassMomentum, bool Force, bool Apic, bool Rows>
void MpmSystem::scatterKernel()
{
    const std::vector<Real> invRho0 = inverseDensities();
    const PointView P = pointView(particles_, L_, dx_);
    const GridView g = gridView(grid_);
    const Lattice& L = lattice_;
    const bool grainVolume = options_.constantGrainVolume;
    forEachPointColoured([&](Index p)
    {
        p2gPoint<K, D, MassMomentum, Force, Apic, Rows>(L, P, g, invRho0.data(), grainVolume, p, PlainAdd{});
    });
}

void MpmSystem::updateMassTolerance()
{
    // Nodes lighter than this (a point at the far edge of a stencil) get
    // zero velocity rather than a ratio of round-off.
    const Index n = particles_.size();
    Real total = 0;
    for (Index p = 0; p < n; ++p) total += particles_.mass[p];
    const Real count = sumAll(Real(n));
    total = sumAll(total);
    massTolerance_ = count > 0 ? 1e-10*total/count : 0;
}

void MpmSystem::addGravity()
{
    const Real gravity[3] = {options_.gravity[0], options_.gravity[1], options_.gravity[2]};
    const GridView g = gridView(grid_);
    forEachActiveNode([&](Index I) { gravityNode(g, gravity, I); });
}

void MpmSystem::sumHalo(unsigned what)
{
    auto& g = grid_;
    std::vector<Real*> a;
    if (what & foldMass) { a.push_back(g.mass.data()); a.push_back(g.volume.data()); }
    for (int d = 0; d < 3; ++d)
    {
        if (what & foldMomentum) a.push_back(g.momentum[d].data());
        if (what & foldForce) a.push_back(g.force[d].data());
    }
    sumHalo(a);
}

void MpmSystem::sumHalo(const std::vector<Real*>& arrays, Subdomain::HaloKind kind)
{
    if (subdomain_)
    {
        ScopedTimer t(timers_.halo);
        subdomain_->sum(arrays, kind);
        return;
    }
    // Serial: the periodic copies are the halo.
    const auto& pc = boundary_.periodicCopies();
    for (Real* a : arrays) for (const Index c : region_.periodicCopies()) a[pc[c].second] += a[pc[c].first];
}

void MpmSystem::copyHalo(const std::vector<Real*>& arrays, Subdomain::HaloKind kind) const
{
    if (subdomain_)
    {
        ScopedTimer t(timers_.halo);
        subdomain_->copy(arrays, kind);
        return;
    }
    const auto& pc = boundary_.periodicCopies();
    for (Real* a : arrays) for (const Index c : region_.periodicCopies()) a[pc[c].first] = a[pc[c].second];
}

void MpmSystem::nodalVelocity(std::array<std::vector<Real>, 3>& v)
{
    const GridView g = gridView(grid_);
    Real* const vp[3] = {v[0].data(), v[1].data(), v[2].data()};
    const Real tol = massTolerance_;
    forEachActiveNode([&](Index I) { lumpedVelocityNode(g, vp, tol, I); });
}

template<class K, int D>
void MpmSystem::massToVelocity(std::array<std::vector<Real>, 3>& v)
{
    if (options_.massMatrix == MassMatrix::lumped) nodalVelocity(v);
    else solveMass<K, D>(grid_.momentum, v);
}

void FluidCoupling::resize(Index nNodes)
{
    K.assign(std::size_t(nNodes), 0.0);
    for (int d = 0; d < 3; ++d)
    {
        U[d].assign(std::size_t(nNodes), 0.0);
        F[d].assign(std::size_t(nNodes), 0.0);
        velocityIntegral[d].assign(std::size_t(nNodes), 0.0);
    }
}

void FluidCoupling::resetIntegral()
{
    for (auto& a : velocityIntegral) std::fill(a.begin(), a.end(), 0.0);
    time = 0;
}

template<class K, int D>
void MpmSystem::nodalUpdate(Real dt)
{
    const Index n = lattice_.nNodes;
    auto& g = grid_;
    auto& c = coupling_;
    const bool coupled = c.active();
    const bool addedMass = coupled && c.addedMassDensity > 0;
    if (coupled)
    {
        // Beyond an open face the fluid is the image cell's (zero
        // gradient): the material leaving feels the drag per unit solid
        // volume it felt inside (K = beta V_cell grows with the solid there)
        for (const auto& fi : boundary_.freeNodes())
        {
            const Real Vi = g.volume[fi.second];
            c.K[fi.first] = Vi > 0 ? c.K[fi.second]*g.volume[fi.first]/Vi : 0.0;
            for (int d = 0; d < 3; ++d)
            {
                c.U[d][fi.first] = c.U[d][fi.second];
                c.F[d][fi.first] = c.F[d][fi.second];
                if (addedMass) c.fluidAcceleration[d][fi.first] = c.fluidAcceleration[d][fi.second];
            }
        }
    }
    for (auto& a : nodeRhs_) a.resize(n);
    if (coupled) nodeDiag_.resize(n);
    // (M + D) v = p + dt f, with M lumped or consistent. Coupled, the drag
    // is implicit and the added mass M_a = Cvm rho_f V_s too:
    //   D = dt K + M_a,
    //   rhs += dt (V_s F + K U + M_a a_f) + M_a v_old.
    forEachActiveNode([&](Index I)
    {
        for (int d = 0; d < 3; ++d) nodeRhs_[d][I] = g.momentum[d][I] + dt*g.force[d][I];
        if (!coupled) return;
        const Real Ma = addedMass ? c.addedMassDensity*g.volume[I] : 0.0;
        nodeDiag_[I] = dt*c.K[I] + Ma;
        for (int d = 0; d < 3; ++d)
        {
            nodeRhs_[d][I] += dt*(g.volume[I]*c.F[d][I] + c.K[I]*c.U[d][I]);
            if (addedMass) nodeRhs_[d][I] += Ma*(g.velocityOld[d][I] + dt*c.fluidAcceleration[d][I]);
        }
    });
    solveMass<K, D>(nodeRhs_, g.velocity, coupled ? &nodeDiag_ : nullptr);
    applyFriction(g.velocity, dt);
    applyLevelSetWalls(g.velocity);
    fillGhosts(g.velocity);
    if (coupling_.active())
    {
        auto& c = coupling_;
        // Outside the region the velocity is zero: the integral keeps its sum
        forEachActiveNode([&](Index I)
        {
            for (int d = 0; d < 3; ++d) c.velocityIntegral[d][I] += dt*g.velocity[d][I];
        });
        c.time += dt;
    }
}

// x = M^-1 rhs for the lumped mass, or the consistent mass approximated by
// Jacobi sweeps x <- x + M_L^-1 (rhs - M_C x), where M_C x is evaluated
// matrix-free as the P2G of m_p times the G2P of x. Low wavenumbers converge
// fast (the error shrinks like ((kh)^2/3)^sweeps); the highest ones keep a
// lumped-like mass, so the scheme stays bounded where M_C is singular.
// With diag (the coupling's dt K + M_a, >= 0) it solves (M + diag) x = rhs,
// preconditioned by M_L + diag: a positive diagonal only speeds the sweeps.
template<class K, int D>
void MpmSystem::solveMass(const std::array<std::vector<Real>, 3>& rhs, std::array<std::vector<Real>, 3>& x,
                           const std::vector<Real>* diag)
{
    const Index nNodes = lattice_.nNodes;
    const Real tol = massTolerance_;
    const auto& m = grid_.mass;
    // Jacobi preconditioner: the lumped mass plus the extra diagonal
    auto diagonal = [&](Index I) { return diag ? m[I] + (*diag)[I] : m[I]; };
    forEachActiveNode([&](Index I)
    {
        const Real inv = m[I] > tol ? 1.0/diagonal(I) : 0.0;
        for (int d = 0; d < 3; ++d) x[d][I] = rhs[d][I]*inv;
    });
    if (options_.massMatrix == MassMatrix::lumped) return;

    fillGhosts(x);
    auto& P = particles_;
    const Lattice& L = lattice_;
    const Index nPoints = P.size();
    for (auto& a : pointScratch_) a.resize(nPoints);
    for (auto& a : nodeScratch_) a.resize(nNodes);
    Real* Mx[3] = {nodeScratch_[0].data(), nodeScratch_[1].data(), nodeScratch_[2].data()};
    for (int sweep = 0; sweep < options_.consistentMassIterations; ++sweep)
    {
        #pragma omp parallel for schedule(static) if(worthThreads(nPoints))
        for (Index p = 0; p < nPoints; ++p)
        {
            Stencil<K, D> s;
            s.compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
            Real u[3] = {0, 0, 0};
            s.forEach(L, [&](Index I, Real N, const Real*, const Real*)
            {
                for (int d = 0; d < 3; ++d) u[d] += N*x[d][I];
            });
            for (int d = 0; d < 3; ++d) pointScratch_[d][p] = P.mass[p]*u[d];
        }
        region_.zero({Mx[0], Mx[1], Mx[2]});
        forEachPointColoured([&](Index p)
        {
            Stencil<K, D> s;
            s.compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
            const Real u0 = pointScratch_[0][p], u1 = pointScratch_[1][p], u2 = pointScratch_[2][p];
            s.forEach(L, [&](Index I, Real N, const Real*, const Real*)
            {
                Mx[0][I] += N*u0; Mx[1][I] += N*u1; Mx[2][I] += N*u2;
            });
        });
        sumHalo({nodeScratch_[0].data(), nodeScratch_[1].data(), nodeScratch_[2].data()});
        foldVector(nodeScratch_);
        forEachActiveNode([&](Index I)
        {
            const Real inv = m[I] > tol ? 1.0/diagonal(I) : 0.0;
            const Real Dx = diag ? (*diag)[I] : 0.0;
            for (int d = 0; d < 3; ++d) x[d][I] += (rhs[d][I] - Mx[d][I] - Dx*x[d][I])*inv;
        });
        fillGhosts(x);
    }
}

// G2P: new point velocity (PIC/FLIP blend or APIC), displacement over the
// step, and the velocity gradient L from the updated grid velocity.
template<class K, int D>
void MpmSystem::gather(Real dt)
{
    if (options_.transfer == Transfer::apic) gatherKernel<K, D, true>(dt);
    else gatherKernel<K, D, false>(dt);
}

template<class K, int D, bool Apic>
void MpmSystem::gatherKernel(Real dt)
{
    const PointView P = pointView(particles_, L_, dx_);
    const GridView g = gridView(grid_);
    const Lattice& L = lattice_;
    const Index n = P.n;
    const Real alpha = options_.flipRatio;
    #pragma omp parallel for schedule(static) if(worthThreads(n))
    for (Index p = 0; p < n; ++p) g2pPoint<K, D, Apic>(L, P, g, alpha, dt, p);
}

template<class K, int D>
void MpmSystem::gradientFromGrid(const std::array<std::vector<Real>, 3>& v)
{
    const PointView P = pointView(particles_, L_, dx_);
    const Real* const vp[3] = {v[0].data(), v[1].data(), v[2].data()};
    const Lattice& L = lattice_;
    const Index n = P.n;
    #pragma omp parallel for schedule(static) if(worthThreads(n))
    for (Index p = 0; p < n; ++p) gradientPoint<K, D>(L, P, vp, p);
}

void MpmSystem::updateStress(Real dt)
{
    auto& P = particles_;
    const Index n = P.size();
    const std::vector<LawParams> laws = lawTable();
    const LawParams* table = laws.data();
    const PointView view = pointView(P, L_, dx_);
    Index firstBad = n;
    Index nInverted = 0;
    #pragma omp parallel for schedule(static) reduction(min:firstBad) reduction(+:nInverted) if(worthThreads(n))
    for (Index p = 0; p < n; ++p)
    {
        const StressPointStatus status = stressPoint(view, table, dt, p);
        if (status == StressPointStatus::bad) firstBad = std::min(firstBad, p);
        else if (status == StressPointStatus::inverted) ++nInverted;
    }
    stopIfNonFinite(firstBad, "stress or deformation");
    inverted_ = InvertedPoints{};
    inverted_.count = nInverted;
    if (nInverted > 0) findFirstInverted();
}

// The laws as kernel parameters, once per step (no virtual call per point)
std::vector<LawParams> MpmSystem::lawTable() const
{
    std::vector<LawParams> laws(materials_.size());
    for (std::size_t m = 0; m < materials_.size(); ++m) laws[m] = materials_[m]->params();
    return laws;
}

// 1/rho0 per material: a point's grain volume is its mass times it
std::vector<Real> MpmSystem::inverseDensities() const
{
    std::vector<Real> inv(materials_.size());
    for (std::size_t m = 0; m < materials_.size(); ++m) inv[m] = 1.0/materials_[m]->rho0();
    return inv;
}

// inverted_ for its count (host and device steps): the point of lowest id
// among those with J <= 0 or a volume not positive
void MpmSystem::findFirstInverted()
{
    const Particles& P = particles_;
    std::int64_t first = std::numeric_limits<std::int64_t>::max();
    Index at = -1;
    for (Index p = 0; p < P.size(); ++p)
    {
        if (!(P.J(p) <= 0 || P.volume[p] <= 0) || P.id[p] >= first) continue;
        first = P.id[p];
        at = p;
    }
    if (at < 0) return;
    inverted_.id = first;
    inverted_.material = P.material[at];
    inverted_.J = P.J(at);
    inverted_.volume = P.volume[at];
}

void MpmSystem::stopIfNonFinite(Index firstBad, const char* what)
{
    // Every rank takes the same decision and names the same point: the
    // lowest id among the ranks' first bad points.
    const auto& P = particles_;
    const std::int64_t none = std::numeric_limits<std::int64_t>::max();
    std::int64_t id = firstBad < P.size() ? P.id[firstBad] : none;
    std::int64_t material = firstBad < P.size() ? P.material[firstBad] : -1;
    if (subdomain_)
    {
        const Communicator& c = subdomain_->comm();
        id = c.min(id);
        if (id == none) return;
        if (firstBad >= P.size() || P.id[firstBad] != id) material = -1;
        material = c.max(material);
    }
    if (id == none) return;
    std::ostringstream os;
    os << "non-finite " << what << " at step " << stepCount_ + 1
       << " in material point id " << id;
    const bool ofMaterial = std::string(what) != "velocity";
    throw NonFiniteError(os.str(), stepCount_ + 1, id, ofMaterial ? int(material) : -1);
}

#ifdef MPM_HAVE_CUDA
// The cuda back-end's step (backend/deviceStep.hpp: the data flow and its
// cost). The point work runs on the device with the CPU's kernel bodies;
// the node work between the transfers is stepImpl's, here on the host.
template<class K, int D>
void MpmSystem::stepOnDevice(Real dt)
{
    DeviceStep& dev = *device_;
    const Index n = particles_.size();
    for (auto& a : L_) a.resize(n);
    for (auto& a : dx_) a.resize(n);
    updateMassTolerance();
    const bool withForce = plan_.forceWithScatter;
    const bool apic = options_.transfer == Transfer::apic;
    const bool grainVolume = options_.constantGrainVolume;
    const ShapeKind shape = options_.shape;
    const unsigned massMomentum = DeviceStep::gridMass | DeviceStep::gridVolume | DeviceStep::gridMomentum;
    const unsigned force = DeviceStep::gridForce;
    const std::vector<LawParams> laws = lawTable();
    const std::vector<Real> invRho0 = inverseDensities();
    const GridView host = gridView(grid_);
    // The host-assisted cuda phases, in the plan's order: point work on
    // the device, node work here, the grid's active nodes copied between
    runPlan(plan_, timers_, [&](Phase phase)
    {
        switch (phase)
        {
            case Phase::scatter:
                binPoints();   // first: the points go up in block order
                dev.setMaterials(laws);
                dev.uploadPoints(pointView(particles_, L_, dx_), apic);
                dev.setActiveNodes(lattice_.nNodes, region_.nodes());
                dev.zeroGrid(massMomentum | force);
                dev.p2g(lattice_, shape, true, withForce, apic, invRho0, grainVolume);
                dev.gridToHost(host, massMomentum | (withForce ? force : 0u));
                break;
            case Phase::nodalAfterScatter: nodalAfterScatter<K, D>(dt, withForce); break;
            case Phase::gradientFromOld:
                dev.gridFromHost(host, DeviceStep::gridVelocityOld);
                dev.gradient(lattice_, shape, true);
                break;
            case Phase::stress: stressOnDevice(dt); break;
            case Phase::scatterForce:
                // The internal force, added here to the gravity already there
                dev.zeroGrid(force);
                dev.p2g(lattice_, shape, false, true, apic, invRho0, grainVolume);
                dev.gridToHost(host, force, true);
                break;
            case Phase::foldForce: sumHalo(foldForce); foldGhosts(foldForce); break;
            case Phase::nodalUpdate: nodalUpdate<K, D>(dt); break;
            case Phase::gather:
                dev.gridFromHost(host, DeviceStep::gridVelocity | (apic ? 0u : unsigned(DeviceStep::gridVelocityOld)));
                dev.g2p(lattice_, shape, apic, options_.flipRatio, dt);
                dev.synchronise();
                break;
            case Phase::remapMomentum:
                dev.zeroGrid(DeviceStep::gridMomentum);
                dev.p2g(lattice_, shape, false, false, apic, invRho0, grainVolume);
                dev.gridToHost(host, DeviceStep::gridMomentum);
                break;
            case Phase::nodalAfterRemap: nodalAfterRemap<K, D>(); break;
            case Phase::gradientFromNew:
                dev.gridFromHost(host, DeviceStep::gridVelocity);
                dev.gradient(lattice_, shape, false);
                dev.synchronise();
                break;
            case Phase::move: movePointsOnDevice(apic, dt); break;
            case Phase::migrate: migrate(); break;
        }
    }, recordPhases_);
}

// The stress update on the device; the inverted point of lowest id is
// found on the host after the points come back (movePointsOnDevice)
void MpmSystem::stressOnDevice(Real dt)
{
    const DeviceStep::StressResult r = device_->stress(dt);
    stopIfNonFinite(r.firstBad, "stress or deformation");
    inverted_ = InvertedPoints{};
    inverted_.count = r.inverted;
}

// The advance on the device, then the points come back; the few beyond a
// face are classified here like movePoints does (removed or held)
void MpmSystem::movePointsOnDevice(bool apic, Real dt)
{
    const bool periodic[3] = {boundary_.periodic(0), boundary_.periodic(1), boundary_.periodic(2)};
    const bool frozen = options_.freezePositions;
    const Index flagged = device_->move(domain_, periodic, frozen, moveFlags_);
    const PointView P = pointView(particles_, L_, dx_);
    device_->downloadPoints(P, apic);
    if (inverted_.count > 0) findFirstInverted();
    const Index n = P.n;
    Index firstBad = n, clamped = 0, leaving = 0;
    leaving_.assign(boundary_.hasOpenFaces() || levelSet_.hasOutlets() ? n : 0, -1);
    if (flagged == 0)
    {
        if (!frozen) removeLeaving(containPoints(dt));
        return;
    }
    for (Index p = 0; p < n; ++p)
    {
        const int flags = moveFlags_[p];
        if (flags & moveBad) { firstBad = std::min(firstBad, p); continue; }
        if (frozen || !(flags & moveOutside)) continue;
        // The device left the unclamped new position
        const Real x[3] = {P.x[0][p], P.x[1][p], P.x[2][p]};
        if (leavesThroughFace(p, x, leaving, clamped)) continue;
        storePosition(domain_, periodic, P, p, x);
    }
    stopIfNonFinite(firstBad, "velocity");
    clamped_ += clamped;
    if (!frozen) leaving += containPoints(dt);
    removeLeaving(leaving);
}
#endif // MPM_HAVE_CUDA

Real MpmSystem::maxSignalSpeed() const
{
    // Resident points: reduced on the device, the host's copy being stale
    if (deviceAhead_) return maxAll(resident_->maxSignalSpeed());
    const std::vector<LawParams> laws = lawTable();
    auto& self = const_cast<MpmSystem&>(*this);
    const PointView P = pointView(self.particles_, self.L_, self.dx_);   // read only
    const Index n = P.n;
    Real cmax = 0;
    #pragma omp parallel for reduction(max:cmax) if(worthThreads(n))
    for (Index p = 0; p < n; ++p) cmax = std::max(cmax, signalSpeedPoint(P, laws.data(), p));
    return maxAll(cmax);
}

Real MpmSystem::stableDeltaT(Real courant) const
{
    const Real c = maxSignalSpeed();
    Real dt = c > 0 ? courant*lattice_.h/c : std::numeric_limits<Real>::infinity();
    for (const auto& m : materials_) dt = std::min(dt, m->maxStableDt(lattice_.h));
    return dt;
}

Index MpmSystem::countOutside() const
{
    pullPoints();
    Index count = 0;
    for (Index p = 0; p < particles_.size(); ++p)
    {
        for (int a = 0; a < 3; ++a)
        {
            if (!domain_.solved[a]) continue;
            const Real x = particles_.x[a][p];
            if (x < domain_.origin[a] || x > domain_.origin[a] + domain_.length(a)) { ++count; break; }
        }
    }
    return count;
}

} // namespace mpm

// The resident step (interface and coverage: residentStep.hpp), written
// once over an execution policy Exec that supplies:
//
//   Exec::Buffer<T>            resize, data, upload, download, zero
//   Exec::copyToDevice(d, h, n), copyToHost(h, d, n), zero(d, n)
//   Exec::forEach(n, body, s)  body(i) for i in [0, n), one thread each
//   Exec::add(a, x)            *a += x, atomically where threads race
//   Exec::P2gAdd<Warp>         P2G's add (kernels/p2g.hpp), the atomics
//                              pre-reduced over a warp's points or not
//   Exec::min(a, x)            *a = min(*a, x) on a counter, atomically
//   Exec::count(a)             ++*a on a counter, atomically
//   Exec::max(a, x)            *a = max(*a, x) for x >= 0 on a counter
//                              holding a double's bits, atomically
//
// The kernel bodies are the CPU step's (kernels/*.hpp); the node work that
// the CPU step does over the boundary's node lists (phases/walls.cpp's ghost
// folds, contact, fills) is written here as bodies over the ghost list,
// with Exec::add where ghosts share an image. The grid is dense: every
// node, zeroed by one fill per step, so no active region is built. Phase
// order: the plan's (step/stepPlan.hpp).
#pragma once
#include "pointArrays.hpp"
#include "pointBodies.hpp"
#include "residentStep.hpp"
#include "../kernels/frictionWall.hpp"
#include "../kernels/g2p.hpp"
#include "../kernels/levelSetWall.hpp"
#include "../kernels/movePoint.hpp"
#include "../kernels/nodal.hpp"
#include "../kernels/p2g.hpp"
#include "../kernels/signalSpeed.hpp"
#include "../kernels/stressPoint.hpp"
#include <algorithm>
#include <chrono>
#include <initializer_list>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace mpm::resident {

// The wall ghosts as arrays (Boundary::Ghost), and this step's reflection
// signs (the contact decision releases a unilateral wall's normal sign)
struct GhostView
{
    Index n = 0;
    const Index* ghost = nullptr;
    const Index* image = nullptr;
    const Real* sign[3] = {};
    const int* axis = nullptr;          // unilateral axis or -1
    const Real* outward = nullptr;
    const Real* mu = nullptr;           // Coulomb coefficient (friction walls) or 0
    Real* stepSign[3] = {};
};

// The friction walls' node work (kernels/frictionWall.hpp) grouped by node:
// node[i]'s operations are [start[i], start[i+1]), in applyFriction's
// (phases/walls.cpp) order (first-layer nodes, then the images' slides),
// which a node's thread runs in turn
struct FrictionView
{
    Index n = 0;
    const Index* node = nullptr;
    const Index* start = nullptr;
    const int* axis = nullptr;
    const int* firstLayer = nullptr;
    const Real* outward = nullptr;
    const Real* mu = nullptr;
};

// Counters: first bad (stress), first bad (move), inverted, beyond a wall,
// contained; the signal speed (a double's bits: for values >= 0 their
// order is the integers')
enum Counter { firstBadStress, firstBadMove, invertedPoints, beyondWall, containedPoints, signalSpeed, nCounters };

// The advance; a point beyond a box face keeps its unclamped position and
// its flag for the host (MpmSystem), then level-set containment
template<class Exec>
struct Move
{
    Lattice L; PointView P; bool periodic[3]; bool frozen; LevelSetView ls; Real dt;
    int* flags; unsigned long long* c;
    MPM_HOST_DEVICE void operator()(Index p) const
    {
        Real x[3];
        const int f = advancePoint(L, periodic, frozen, P, p, x);
        flags[p] = f;
        if (f & moveBad) { Exec::min(c + firstBadMove, (unsigned long long)p); return; }
        if (frozen) return;
        if (f & moveOutside)
        {
            Exec::count(c + beyondWall);
            for (int a = 0; a < 3; ++a) P.x[a][p] = x[a];
            return;
        }
        storePosition(L, periodic, P, p, x);
        if (ls && levelSetContainPoint(L, ls, P, p, dt) == 1) Exec::count(c + containedPoints);
    }
};

template<class Exec>
struct SignalSpeed
{
    PointView P; const LawParams* laws; unsigned long long* c;
    MPM_HOST_DEVICE void operator()(Index p) const { Exec::max(c + signalSpeed, signalSpeedPoint(P, laws, p)); }
};

struct Gravity
{
    GridView g; Real gravity[3];
    MPM_HOST_DEVICE void operator()(Index I) const { gravityNode(g, gravity, I); }
};

struct LumpedVelocity
{
    GridView g; Real* v[3]; Real tol;
    MPM_HOST_DEVICE void operator()(Index I) const { lumpedVelocityNode(g, v, tol, I); }
};

// The uncoupled lumped update v = (p + dt f)/m (nodalUpdate with solveMass,
// phases/nodalUpdate.cpp)
struct NodalUpdate
{
    GridView g; Real dt; Real tol;
    MPM_HOST_DEVICE void operator()(Index I) const
    {
        const Real m = g.mass[I];
        const Real inv = m > tol ? 1.0/m : 0.0;
        for (int d = 0; d < 3; ++d) g.velocity[d][I] = (g.momentum[d][I] + dt*g.force[d][I])*inv;
    }
};

// The friction walls' impulses: each contact ghost's into its image
template<class Exec>
struct FrictionImpulse
{
    GhostView G; GridView g; Real* J[3]; const Real* stuck[3]; Real dt;
    MPM_HOST_DEVICE void operator()(Index k) const
    {
        const int a = G.axis[k];
        // no friction, no contact, or stuck (the noSlip mirror did the work)
        if (!(G.mu[k] > 0) || G.stepSign[a][k] > 0 || stuck[a][G.image[k]] > 0) return;
        Exec::add(J[a] + G.image[k], frictionGhostImpulse(g, G.ghost[k], a, G.outward[k], dt));
    }
};

// ... then each node's first-layer operations and slides, in order
struct FrictionNodes
{
    FrictionView F; const Real* mass; Real* J[3]; const Real* stuck[3]; Real* v[3]; Real tol;
    MPM_HOST_DEVICE void operator()(Index i) const
    {
        const Index I = F.node[i];
        for (Index q = F.start[i]; q < F.start[i + 1]; ++q)
        {
            if (!F.firstLayer[q]) frictionSlide(J, mass, v, tol, I, F.axis[q], F.mu[q]);
            else if (!(stuck[F.axis[q]][I] > 0)) frictionFirstLayer(J, mass, v, tol, I, F.axis[q], F.outward[q], F.mu[q]);
        }
    }
};

struct LevelSetNode
{
    LevelSetView ls; const Real* mass; Real* v[3]; Real tol; Real muCap;
    MPM_HOST_DEVICE void operator()(Index I) const { levelSetWallNode(ls, mass, v, tol, I, muCap); }
};

// Ghost folds (phases/walls.hpp: foldScalar, foldVector): every ghost
// added into its image (with this step's signs for vectors), then, for
// scalars, the image's sum copied back to the ghost
template<class Exec>
struct FoldScalar
{
    GhostView G; Real* a;
    MPM_HOST_DEVICE void operator()(Index k) const { Exec::add(a + G.image[k], a[G.ghost[k]]); }
};

struct CopyToGhost
{
    GhostView G; Real* a;
    MPM_HOST_DEVICE void operator()(Index k) const { a[G.ghost[k]] = a[G.image[k]]; }
};

template<class Exec>
struct FoldVector
{
    GhostView G; Real* a[3];
    MPM_HOST_DEVICE void operator()(Index k) const
    {
        for (int d = 0; d < 3; ++d) Exec::add(a[d] + G.image[k], G.stepSign[d][k]*a[d][G.ghost[k]]);
    }
};

struct FillGhosts
{
    GhostView G; Real* v[3];
    MPM_HOST_DEVICE void operator()(Index k) const
    {
        for (int d = 0; d < 3; ++d) v[d][G.ghost[k]] = G.stepSign[d][k]*v[d][G.image[k]];
    }
};

// The serial halo of periodic axes (phases/halo.hpp: sumHalo, copyHalo): each
// periodic copy's values summed into its canonical node, or the canonical
// node's copied back (the canonical node is never a copy)
template<class Exec>
struct PeriodicSum
{
    const Index* copy; const Index* canonical; Real* a[6]; int count;
    MPM_HOST_DEVICE void operator()(Index k) const
    {
        for (int j = 0; j < count; ++j) Exec::add(a[j] + canonical[k], a[j][copy[k]]);
    }
};

struct PeriodicCopy
{
    const Index* copy; const Index* canonical; Real* a[3];
    MPM_HOST_DEVICE void operator()(Index k) const
    {
        for (int j = 0; j < 3; ++j) a[j][copy[k]] = a[j][canonical[k]];
    }
};

// The contact decision of unilateral walls (decideWallContact,
// phases/walls.hpp), in three launches: each image's own trial momentum,
// plus every ghost's, then the signs
struct ContactTrialImage
{
    GhostView G; GridView g; Real* trial[3]; Real dt; bool withForce; Real gravity[3];
    MPM_HOST_DEVICE void operator()(Index k) const
    {
        for (int d = 0; d < 3; ++d) G.stepSign[d][k] = G.sign[d][k];
        const int a = G.axis[k];
        if (a < 0) return;
        const Index I = G.image[k];
        // Ghosts sharing an image write the same value
        trial[a][I] = g.momentum[a][I] + (withForce ? dt*g.force[a][I] : dt*g.mass[I]*gravity[a]);
    }
};

template<class Exec>
struct ContactTrialGhost
{
    GhostView G; GridView g; Real* trial[3]; Real dt; bool withForce;
    MPM_HOST_DEVICE void operator()(Index k) const
    {
        const int a = G.axis[k];
        if (a < 0) return;
        const Index J = G.ghost[k];
        Exec::add(trial[a] + G.image[k], g.momentum[a][J] + (withForce ? dt*g.force[a][J] : 0.0));
    }
};

struct ContactSign
{
    GhostView G; Real* trial[3];
    MPM_HOST_DEVICE void operator()(Index k) const
    {
        const int a = G.axis[k];
        if (a < 0) return;
        if (!(trial[a][G.image[k]]*G.outward[k] >= 0)) G.stepSign[a][k] = 1.0;
    }
};

// Friction walls in contact: stick (the noSlip mirror this step, the node
// marked) or slide (phases/walls.cpp: decideFrictionStick), before the fold
struct FrictionStick
{
    GhostView G; GridView g; Real* stuck[3]; Real dt; bool withForce; Real gravity[3];
    MPM_HOST_DEVICE void operator()(Index k) const
    {
        const int a = G.axis[k];
        if (a < 0 || !(G.mu[k] > 0) || G.stepSign[a][k] > 0) return;
        if (!frictionSticks(g, G.image[k], a, G.outward[k], G.mu[k], dt, withForce, gravity)) return;
        for (int d = 0; d < 3; ++d) if (d != a) G.stepSign[d][k] = -1.0;
        stuck[a][G.image[k]] = 1.0;   // ghosts sharing an image write the same
    }
};

using bodies::dispatchKD;
using bodies::pick;

template<class Exec>
class Step final : public ResidentStep
{
    template<class T> using Buffer = typename Exec::template Buffer<T>;

public:
    void configure(const ResidentConfig& c) override
    {
        c_ = c;
        laws_.upload(c.laws.data(), c.laws.size());
        invRho0_.upload(c.invRho0.data(), c.invRho0.size());
        const Index nNodes = c.lattice.nNodes;
        if (g_.n != nNodes)
        {
            grid_.resize(std::size_t(nNodes)*realsPerNode);
            g_ = layGrid(grid_.data(), nNodes);
            trial_.resize(std::size_t(nNodes)*3);
            trial_.zero();
        }
        // The ghosts, as arrays
        const auto& gh = c.ghosts;
        const Index n = Index(gh.size());
        std::vector<Index> ghost(n), image(n);
        std::vector<int> axis(n);
        std::vector<Real> sign(3*std::size_t(n)), outward(n), mu(n);
        for (Index k = 0; k < n; ++k)
        {
            ghost[k] = gh[k].ghost; image[k] = gh[k].image;
            axis[k] = gh[k].unilateralAxis; outward[k] = gh[k].outward; mu[k] = gh[k].mu;
            for (int d = 0; d < 3; ++d) sign[d*std::size_t(n) + k] = gh[k].sign[d];
        }
        std::vector<Index> both(ghost);
        both.insert(both.end(), image.begin(), image.end());
        ghostIndex_.upload(both.data(), both.size());
        ghostAxis_.upload(axis.data(), axis.size());
        // sign[3], outward, stepSign[3], mu
        ghostReal_.resize(8*std::size_t(n));
        std::vector<Real> reals(sign);
        reals.insert(reals.end(), outward.begin(), outward.end());
        reals.resize(7*std::size_t(n), 0.0);
        reals.insert(reals.end(), mu.begin(), mu.end());
        if (n) ghostReal_.upload(reals.data(), reals.size());
        G_ = GhostView();
        G_.n = n;
        G_.ghost = ghostIndex_.data();
        G_.image = ghostIndex_.data() + n;
        for (int d = 0; d < 3; ++d)
        {
            G_.sign[d] = ghostReal_.data() + d*n;
            G_.stepSign[d] = ghostReal_.data() + (4 + d)*n;
        }
        G_.outward = ghostReal_.data() + 3*n;
        G_.mu = ghostReal_.data() + 7*n;
        G_.axis = ghostAxis_.data();
        configureFriction(c);
        nPeriodic_ = Index(c.periodicCopies.size());
        std::vector<Index> pc(2*c.periodicCopies.size());
        for (std::size_t k = 0; k < c.periodicCopies.size(); ++k)
        {
            pc[k] = c.periodicCopies[k].first;
            pc[c.periodicCopies.size() + k] = c.periodicCopies[k].second;
        }
        periodic_.upload(pc.data(), pc.size());
    }

    // The friction operations grouped by node, in applyFriction's order
    void configureFriction(const ResidentConfig& c)
    {
        struct Op { Index node; int axis; int firstLayer; Real outward; Real mu; };
        std::vector<Op> ops;
        for (const auto& f : c.frictionNodes) ops.push_back({f.node, f.axis, 1, f.outward, f.mu});
        for (const auto& g : c.ghosts) if (g.mu > 0) ops.push_back({g.image, g.unilateralAxis, 0, 0.0, g.mu});
        std::stable_sort(ops.begin(), ops.end(), [](const Op& a, const Op& b) { return a.node < b.node; });
        std::vector<Index> node, start;
        std::vector<int> ints(2*ops.size());
        std::vector<Real> reals(2*ops.size());
        for (std::size_t q = 0; q < ops.size(); ++q)
        {
            if (q == 0 || ops[q].node != ops[q - 1].node) { node.push_back(ops[q].node); start.push_back(Index(q)); }
            ints[q] = ops[q].axis; ints[ops.size() + q] = ops[q].firstLayer;
            reals[q] = ops[q].outward; reals[ops.size() + q] = ops[q].mu;
        }
        start.push_back(Index(ops.size()));
        const Index nNodes = Index(node.size());
        node.insert(node.end(), start.begin(), start.end());
        frictionIndex_.upload(node.data(), node.size());
        frictionInt_.upload(ints.data(), ints.size());
        frictionReal_.upload(reals.data(), reals.size());
        F_ = FrictionView();
        F_.n = ops.empty() ? 0 : nNodes;
        F_.node = frictionIndex_.data();
        F_.start = frictionIndex_.data() + nNodes;
        F_.axis = frictionInt_.data();
        F_.firstLayer = frictionInt_.data() + ops.size();
        F_.outward = frictionReal_.data();
        F_.mu = frictionReal_.data() + ops.size();
    }

    void setLevelSet(const LevelSetView& h, Index nNodes, Index nWalls) override
    {
        ls_ = LevelSetView();
        if (!h) return;
        lsReal_.resize(std::size_t(nNodes)*4 + std::size_t(nWalls)*4);
        std::vector<Real> r;
        r.reserve(lsReal_.size());
        r.insert(r.end(), h.phi, h.phi + nNodes);
        for (int a = 0; a < 3; ++a) r.insert(r.end(), h.normal[a], h.normal[a] + nNodes);
        r.insert(r.end(), h.mu, h.mu + nWalls);
        for (int a = 0; a < 3; ++a) r.insert(r.end(), h.velocity[a], h.velocity[a] + nWalls);
        lsReal_.upload(r.data(), r.size());
        std::vector<int> i(h.wall, h.wall + nNodes);
        i.insert(i.end(), h.type, h.type + nWalls);
        lsInt_.upload(i.data(), i.size());
        const Real* d = lsReal_.data();
        ls_.phi = d;
        for (int a = 0; a < 3; ++a) ls_.normal[a] = d + (1 + a)*nNodes;
        ls_.mu = d + 4*nNodes;
        for (int a = 0; a < 3; ++a) ls_.velocity[a] = d + 4*nNodes + (1 + a)*nWalls;
        ls_.wall = lsInt_.data();
        ls_.type = lsInt_.data() + nNodes;
        ls_.band = h.band;
        ls_.contact = h.contact;
        ls_.normalHold = h.normalHold;
    }

    void uploadPoints(const PointView& host) override
    {
        const Index n = host.n;
        points_.resize(std::size_t(n)*realsPerPoint);
        material_.resize(std::size_t(n));
        P_ = layPoints(points_.data(), material_.data(), n);
        forEachPointArray(P_, host, PointDirection::up, c_.apic, [&](Real* d, const Real* h, const char*)
        {
            Exec::copyToDevice(d, h, std::size_t(n));
        });
        if (n) Exec::copyToDevice(material_.data(), host.material, std::size_t(n));
        flags_.resize(std::size_t(n));
    }

    void downloadPoints(const PointView& host) override
    {
        if (host.n != P_.n) throw std::runtime_error("the resident step holds another number of points than the host");
        forEachPointArray(P_, host, PointDirection::down, c_.apic, [&](const Real* d, Real* h, const char*)
        {
            Exec::copyToHost(h, d, std::size_t(P_.n));
        });
    }

    void downloadMoveFlags(std::vector<int>& flags) override
    {
        flags.resize(std::size_t(P_.n));
        flags_.download(flags.data(), flags.size());
    }

    ResidentResult step(Real dt, Real tol, StepTimers& timers, std::vector<Phase>* record) override
    {
        const Index n = P_.n;
        const unsigned long long init[nCounters] = {(unsigned long long)n, (unsigned long long)n, 0, 0, 0, 0};
        counters_.upload(init, nCounters);
        dispatchKD(c_.shape, c_.lattice.dim, [&](auto k, auto d)
        {
            using K = decltype(k);
            constexpr int D = decltype(d)::value;
            runPlan(c_.plan, timers, [&](Phase phase) { run<K, D>(phase, dt, tol); }, record);
        });
        unsigned long long c[nCounters];
        counters_.download(c, nCounters);   // waits for the step
        return {Index(c[firstBadStress]), Index(c[firstBadMove]), Index(c[invertedPoints]),
                Index(c[beyondWall]), Index(c[containedPoints])};
    }

    Real maxSignalSpeed() override
    {
        const unsigned long long zero[nCounters] = {0, 0, 0, 0, 0, 0};
        counters_.upload(zero, nCounters);
        Exec::forEach(P_.n, SignalSpeed<Exec>{P_, laws_.data(), counters_.data()}, "the signal speed kernel");
        unsigned long long c[nCounters];
        counters_.download(c, nCounters);
        Real x;
        std::memcpy(&x, &c[signalSpeed], sizeof x);
        return x;
    }

private:
    template<class K, int D>
    void run(Phase phase, Real dt, Real tol)
    {
        const bool withForce = c_.plan.forceWithScatter;
        switch (phase)
        {
            case Phase::scatter:
                grid_.zero();
                scatter<K, D>(true, withForce);
                break;
            case Phase::nodalAfterScatter:
            {
                // nodalAfterScatter (phases/nodalUpdate.hpp) without halo (one rank)
                Gravity gr{g_, {c_.gravity[0], c_.gravity[1], c_.gravity[2]}};
                Exec::forEach(g_.n, gr, "the gravity kernel");
                if (withForce) sumPeriodic({g_.mass, g_.volume, g_.momentum[0], g_.momentum[1], g_.momentum[2]},
                                           g_.force);
                else sumPeriodic({g_.mass, g_.volume, g_.momentum[0], g_.momentum[1], g_.momentum[2]}, nullptr);
                foldScalar(g_.mass);
                foldScalar(g_.volume);
                contact(dt, withForce);
                foldVector(g_.momentum);
                if (withForce) foldVector(g_.force);
                LumpedVelocity lv{g_, {g_.velocityOld[0], g_.velocityOld[1], g_.velocityOld[2]}, tol};
                Exec::forEach(g_.n, lv, "the nodal velocity kernel");
                fillGhosts(g_.velocityOld);
                break;
            }
            case Phase::gradientFromOld: gradient<K, D>(g_.velocityOld); break;
            case Phase::stress:
            {
                bodies::Stress<Exec> s{P_, laws_.data(), dt, counters_.data() + firstBadStress,
                                       counters_.data() + invertedPoints};
                Exec::forEach(P_.n, s, "the stress update kernel");
                break;
            }
            case Phase::scatterForce:
            {
                // The internal force alone, added to the gravity there
                scatter<K, D>(false, true);
                break;
            }
            case Phase::foldForce:
                sumPeriodic({g_.force[0], g_.force[1], g_.force[2]}, nullptr);
                foldVector(g_.force);
                break;
            case Phase::nodalUpdate:
            {
                NodalUpdate u{g_, dt, tol};
                Exec::forEach(g_.n, u, "the nodal update kernel");
                walls(g_.velocity, dt, tol);
                break;
            }
            case Phase::gather:
                pick(c_.apic, [&](auto a)
                {
                    bodies::G2p<K, D, decltype(a)::value> body{c_.lattice, P_, g_, c_.flipRatio, dt};
                    Exec::forEach(P_.n, body, "the G2P kernel");
                });
                break;
            case Phase::remapMomentum:
                for (int d = 0; d < 3; ++d) Exec::zero(g_.momentum[d], std::size_t(g_.n));
                scatter<K, D>(false, false);
                break;
            case Phase::nodalAfterRemap:
            {
                sumPeriodic({g_.momentum[0], g_.momentum[1], g_.momentum[2]}, nullptr);
                foldVector(g_.momentum);
                LumpedVelocity lv{g_, {g_.velocity[0], g_.velocity[1], g_.velocity[2]}, tol};
                Exec::forEach(g_.n, lv, "the nodal velocity kernel");
                walls(g_.velocity, 0, tol);   // the re-map: no force, dt 0
                break;
            }
            case Phase::gradientFromNew: gradient<K, D>(g_.velocity); break;
            case Phase::move:
            {
                Move<Exec> m{c_.lattice, P_, {c_.periodic[0], c_.periodic[1], c_.periodic[2]}, c_.frozen, ls_, dt,
                             flags_.data(), counters_.data()};
                Exec::forEach(P_.n, m, "the point advance kernel");
                break;
            }
            case Phase::migrate: break;   // one rank
        }
    }

    template<class K, int D>
    void scatter(bool massMomentum, bool force)
    {
        pick(massMomentum, [&](auto mm)
        {
            pick(force, [&](auto f)
            {
                pick(c_.apic, [&](auto a)
                {
                    pick(c_.p2gWarpReduction, [&](auto w)
                    {
                        using Add = typename Exec::template P2gAdd<decltype(w)::value>;
                        bodies::P2g<K, D, decltype(mm)::value, decltype(f)::value, decltype(a)::value, Add> body
                        {c_.lattice, P_, g_, invRho0_.data(), c_.grainVolume};
                        Exec::forEach(P_.n, body, "the P2G kernel");
                    });
                });
            });
        });
    }

    template<class K, int D>
    void gradient(Real* const v[3])
    {
        bodies::Gradient<K, D> body{c_.lattice, P_, {v[0], v[1], v[2]}};
        Exec::forEach(P_.n, body, "the velocity gradient kernel");
    }

    // After an updated velocity, in the host phases' order: friction walls,
    // level-set walls, the ghost fill
    void walls(Real* const v[3], Real dt, Real tol)
    {
        if (F_.n > 0)
        {
            Real* J[3];
            for (int d = 0; d < 3; ++d) J[d] = trial_.data() + d*g_.n;
            Exec::zero(trial_.data(), 3*std::size_t(g_.n));
            const Real* stuck[3];
            for (int d = 0; d < 3; ++d) stuck[d] = stuck_.data() + d*g_.n;
            Exec::forEach(G_.n, FrictionImpulse<Exec>{G_, g_, {J[0], J[1], J[2]}, {stuck[0], stuck[1], stuck[2]}, dt},
                          "the friction impulse kernel");
            Exec::forEach(F_.n, FrictionNodes{F_, g_.mass, {J[0], J[1], J[2]}, {stuck[0], stuck[1], stuck[2]},
                                              {v[0], v[1], v[2]}, tol},
                          "the friction kernel");
        }
        if (ls_)
        {
            LevelSetNode w{ls_, g_.mass, {v[0], v[1], v[2]}, tol, c_.frictionCap};
            Exec::forEach(g_.n, w, "the level-set wall kernel");
        }
        fillGhosts(v);
    }

    void foldScalar(Real* a)
    {
        Exec::forEach(G_.n, FoldScalar<Exec>{G_, a}, "the ghost fold kernel");
        Exec::forEach(G_.n, CopyToGhost{G_, a}, "the ghost copy kernel");
    }

    void foldVector(Real* const a[3])
    {
        Exec::forEach(G_.n, FoldVector<Exec>{G_, {a[0], a[1], a[2]}}, "the ghost fold kernel");
    }

    void fillGhosts(Real* const v[3])
    {
        Exec::forEach(G_.n, FillGhosts{G_, {v[0], v[1], v[2]}}, "the ghost fill kernel");
        if (nPeriodic_ > 0)
        {
            Exec::forEach(nPeriodic_, PeriodicCopy{periodic_.data(), periodic_.data() + nPeriodic_, {v[0], v[1], v[2]}},
                          "the periodic copy kernel");
        }
    }

    // The periodic copies summed into their canonical nodes: the arrays
    // listed, and the three of `more` if given
    void sumPeriodic(std::initializer_list<Real*> arrays, Real* const* more)
    {
        if (nPeriodic_ == 0) return;
        PeriodicSum<Exec> s{periodic_.data(), periodic_.data() + nPeriodic_, {}, 0};
        for (Real* a : arrays) s.a[s.count++] = a;
        Exec::forEach(nPeriodic_, s, "the periodic sum kernel");
        if (!more) return;
        PeriodicSum<Exec> f{periodic_.data(), periodic_.data() + nPeriodic_, {more[0], more[1], more[2]}, 3};
        Exec::forEach(nPeriodic_, f, "the periodic sum kernel");
    }

    void contact(Real dt, bool withForce)
    {
        Real* trial[3];
        for (int d = 0; d < 3; ++d) trial[d] = trial_.data() + d*g_.n;
        ContactTrialImage a{G_, g_, {trial[0], trial[1], trial[2]}, dt, withForce,
                            {c_.gravity[0], c_.gravity[1], c_.gravity[2]}};
        Exec::forEach(G_.n, a, "the wall contact kernel");
        Exec::forEach(G_.n, ContactTrialGhost<Exec>{G_, g_, {trial[0], trial[1], trial[2]}, dt, withForce},
                      "the wall contact kernel");
        Exec::forEach(G_.n, ContactSign{G_, {trial[0], trial[1], trial[2]}}, "the wall contact kernel");
        if (F_.n > 0)
        {
            if (stuck_.size() != 3*std::size_t(g_.n)) stuck_.resize(3*std::size_t(g_.n));
            Exec::zero(stuck_.data(), stuck_.size());
            FrictionStick f{G_, g_, {}, dt, withForce, {c_.gravity[0], c_.gravity[1], c_.gravity[2]}};
            for (int d = 0; d < 3; ++d) f.stuck[d] = stuck_.data() + d*g_.n;
            Exec::forEach(G_.n, f, "the friction stick kernel");
        }
    }

    ResidentConfig c_;
    Buffer<LawParams> laws_;
    Buffer<Real> invRho0_;
    Buffer<Real> points_;
    Buffer<int> material_;
    Buffer<int> flags_;
    PointView P_;
    Buffer<Real> grid_;
    Buffer<Real> trial_;
    Buffer<Real> stuck_;   // per wall axis and node: 1 where a friction wall's image sticks this step
    GridView g_;
    Buffer<Index> ghostIndex_;
    Buffer<int> ghostAxis_;
    Buffer<Real> ghostReal_;
    GhostView G_;
    Buffer<Index> periodic_;             // copies, then their canonical nodes
    Index nPeriodic_ = 0;
    Buffer<Index> frictionIndex_;
    Buffer<int> frictionInt_;
    Buffer<Real> frictionReal_;
    FrictionView F_;
    Buffer<Real> lsReal_;
    Buffer<int> lsInt_;
    LevelSetView ls_;
    Buffer<unsigned long long> counters_;
};

} // namespace mpm::resident

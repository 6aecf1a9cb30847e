// The resident device step's launcher (backend/residentStep.hpp): the
// plan's phases on the device, the host told a few counters; the points
// come back only when the host reads them (MpmSystem::particles(),
// output) or a point went beyond a box wall.
#include "launchers.hpp"
#include "../phases/movePoints.hpp"
#include "../phases/nodalUpdate.hpp"
#include "../phases/walls.hpp"
#include "../kernels/movePoint.hpp"
#include "../transfer/stencil.hpp"
#include <algorithm>
#include <cstring>

namespace mpm {

std::string residentUnsupported(const SystemState& s)
{
    if (!s.resident) return "";
    if (s.subdomain) return "decomposed runs";
    if (s.coupling.active()) return "the fluid coupling";
    if (s.options.massMatrix != MassMatrix::lumped) return "consistent mass";
    if (s.boundary.hasOpenFaces() || !s.boundary.inletNodes().empty()) return "open faces";
    if (s.levelSet.hasOutlets()) return "level-set outlets";
    return "";
}

namespace {

ResidentConfig residentConfig(const SystemState& s)
{
    ResidentConfig c;
    c.lattice = s.lattice;
    c.shape = s.options.shape;
    c.plan = s.plan;
    c.apic = s.options.transfer == Transfer::apic;
    c.flipRatio = s.options.flipRatio;
    c.grainVolume = s.options.constantGrainVolume;
    c.frozen = s.options.freezePositions;
    c.p2gWarpReduction = s.options.p2gWarpReduction;
    c.gravity = s.options.gravity;
    c.laws = s.lawTable();
    c.invRho0 = s.inverseDensities();
    return c;
}

// Configures the resident step when it has not been, or when what may
// change between steps has: the laws' parameters, gravity, the grain volume
void configure(SystemState& s)
{
    const ResidentConfig c = residentConfig(s);
    const ResidentConfig& key = s.residentKey;
    const bool changed = !s.residentConfigured || c.gravity != key.gravity
        || c.grainVolume != key.grainVolume || c.invRho0 != key.invRho0
        || c.laws.size() != key.laws.size()
        || std::memcmp(c.laws.data(), key.laws.data(), c.laws.size()*sizeof(LawParams)) != 0;
    if (!changed) return;
    ResidentConfig full = c;
    full.ghosts = s.boundary.ghosts();
    full.frictionNodes = s.boundary.frictionNodes();
    // The friction walls' coefficients, at most the materials' friction
    // (computeFrictionCap): set again whenever the laws change
    const Real cap = computeFrictionCap(s);
    for (auto& g : full.ghosts) if (g.mu > 0) g.mu = std::min(g.mu, cap);
    for (auto& f : full.frictionNodes) f.mu = std::min(f.mu, cap);
    full.frictionCap = cap;
    full.periodicCopies = s.boundary.periodicCopies();
    for (int a = 0; a < 3; ++a) full.periodic[a] = s.boundary.periodic(a);
    s.resident->configure(full);
    s.residentKey = c;
    s.residentConfigured = true;
}

// The points in the order of their stencils' first nodes, for the resident
// step's P2G: the points of a run share every node, so a warp adds their
// sums together before one atomic per node (backend/residentCuda.cu), and
// consecutive runs are neighbours along x. (A cell's points do not share a
// stencil with linear hats and cubic B-splines, whose stencils start at
// the node below each point: block or cell order gives runs of one.)
void sortByStencil(SystemState& s)
{
    const Index n = s.particles.size();
    std::vector<Index> key(n), order(n);
    const auto& P = s.particles;
    const Lattice& L = s.lattice;
    s.dispatch([&](auto k, auto d)
    {
        using K = decltype(k);
        constexpr int D = decltype(d)::value;
        for (Index p = 0; p < n; ++p)
        {
            Stencil<K, D> st;
            st.compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
            Index first = 0;
            for (int a = 0; a < D; ++a) first += st.base[a]*L.stride[L.axes[a]];
            key[p] = first;
        }
    });
    if (std::is_sorted(key.begin(), key.end())) return;
    for (Index p = 0; p < n; ++p) order[p] = p;
    std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return key[a] < key[b]; });
    s.particles.permute(order);
}

// Points beyond a box wall (a step far too large): held just inside,
// counted, as movePoints does, here on the host
void holdBeyondWalls(SystemState& s, Real dt)
{
    s.pullPoints();
    s.resident->downloadMoveFlags(s.moveFlags);
    const PointView P = s.points();
    const Index n = P.n;
    const bool periodic[3] = {s.boundary.periodic(0), s.boundary.periodic(1), s.boundary.periodic(2)};
    s.leavingThrough.assign(0, -1);
    for (Index p = 0; p < n; ++p)
    {
        if (!(s.moveFlags[p] & moveOutside)) continue;
        const Real x[3] = {P.x[0][p], P.x[1][p], P.x[2][p]};
        bool beyondWall = false;
        exitCondition(s, x, beyondWall);
        s.clamped += beyondWall;
        storePosition(s.domain, periodic, P, p, x);
    }
    containPoints(s, dt);
    s.hostAhead = true;
}

} // namespace

void stepResident(SystemState& s, Real dt)
{
    ResidentStep& r = *s.resident;
    configure(s);
    if (s.levelSetChanged)
    {
        r.setLevelSet(s.levelSet.view(), s.lattice.nNodes, Index(s.levelSet.walls().size()));
        s.levelSetChanged = false;
    }
    if (s.hostAhead)
    {
        if (s.options.reorderPoints) sortByStencil(s);
        s.sizePointScratch();
        updateMassTolerance(s);
        r.uploadPoints(s.points());
        s.hostAhead = false;
    }
    const Index n = s.particles.size();
    const ResidentResult res = r.step(dt, s.massTolerance, s.timers, s.recordPhases);
    s.deviceAhead = true;
    // The host step's stops, in its order
    if (res.firstBadStress < n) { s.pullPoints(); s.stopIfNonFinite(res.firstBadStress, "stress or deformation"); }
    s.inverted = InvertedPoints{};
    s.inverted.count = res.inverted;
    if (res.inverted > 0) { s.pullPoints(); s.findFirstInverted(); }
    if (res.firstBadMove < n) { s.pullPoints(); s.stopIfNonFinite(res.firstBadMove, "velocity"); }
    s.contained += res.contained;
    if (res.beyondWall > 0) holdBeyondWalls(s, dt);
}

} // namespace mpm

// MpmSystem's launcher of the resident device step (backend/residentStep.hpp)
// and the host copy of its points.
#include "mpmSystemLoops.hpp"
#include "../kernels/movePoint.hpp"
#include "../kernels/views.hpp"
#include "../transfer/stencil.hpp"
#include <algorithm>
#include <cstring>

namespace mpm {

std::string MpmSystem::residentUnsupported() const
{
    if (!resident_) return "";
    if (subdomain_) return "decomposed runs";
    if (coupling_.active()) return "the fluid coupling";
    if (options_.massMatrix != MassMatrix::lumped) return "consistent mass";
    if (boundary_.hasOpenFaces() || !boundary_.inletNodes().empty()) return "open faces";
    if (levelSet_.hasOutlets()) return "level-set outlets";
    return "";
}

ResidentConfig MpmSystem::residentConfig() const
{
    ResidentConfig c;
    c.lattice = lattice_;
    c.shape = options_.shape;
    c.plan = plan_;
    c.apic = options_.transfer == Transfer::apic;
    c.flipRatio = options_.flipRatio;
    c.grainVolume = options_.constantGrainVolume;
    c.frozen = options_.freezePositions;
    c.p2gWarpReduction = options_.p2gWarpReduction;
    c.gravity = options_.gravity;
    c.laws = lawTable();
    c.invRho0 = inverseDensities();
    return c;
}

// The points in the order of their stencils' first nodes, for the resident
// step's P2G: the points of a run share every node, so a warp adds their
// sums together before one atomic per node (backend/residentCuda.cu), and
// consecutive runs are neighbours along x. (A cell's points do not share a
// stencil with linear hats and cubic B-splines, whose stencils start at
// the node below each point: block or cell order gives runs of one.)
void MpmSystem::sortByStencil()
{
    const Index n = particles_.size();
    std::vector<Index> key(n), order(n);
    const auto& P = particles_;
    dispatch([&](auto k, auto d)
    {
        using K = decltype(k);
        constexpr int D = decltype(d)::value;
        for (Index p = 0; p < n; ++p)
        {
            Stencil<K, D> s;
            s.compute(lattice_, P.x[0][p], P.x[1][p], P.x[2][p]);
            Index first = 0;
            for (int a = 0; a < D; ++a) first += s.base[a]*lattice_.stride[lattice_.axes[a]];
            key[p] = first;
        }
    });
    if (std::is_sorted(key.begin(), key.end())) return;
    for (Index p = 0; p < n; ++p) order[p] = p;
    std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return key[a] < key[b]; });
    particles_.permute(order);
}

void MpmSystem::pullPoints() const
{
    if (!deviceAhead_) return;
    // The host's points are a copy of the device's: refreshing it changes
    // no state of the model
    auto& self = const_cast<MpmSystem&>(*this);
    resident_->downloadPoints(pointView(self.particles_, self.L_, self.dx_));
    deviceAhead_ = false;
}

// The resident step (backend/residentStep.hpp): the plan's phases on the
// device, the host told a few counters; the points come back only when the
// host reads them (particles(), output) or a point went beyond a box wall.
void MpmSystem::stepResident(Real dt)
{
    ResidentStep& r = *resident_;
    const ResidentConfig c = residentConfig();
    // Set after setup and changeable between steps: the laws' parameters,
    // gravity, the grain volume
    const bool changed = !residentConfigured_ || c.gravity != residentKey_.gravity
        || c.grainVolume != residentKey_.grainVolume || c.invRho0 != residentKey_.invRho0
        || c.laws.size() != residentKey_.laws.size()
        || std::memcmp(c.laws.data(), residentKey_.laws.data(), c.laws.size()*sizeof(LawParams)) != 0;
    if (changed)
    {
        ResidentConfig full = c;
        full.ghosts = boundary_.ghosts();
        full.frictionNodes = boundary_.frictionNodes();
        // The friction walls' coefficients, at most the materials' friction
        // (frictionCap): set again whenever the laws change
        const Real cap = computeFrictionCap();
        for (auto& g : full.ghosts) if (g.mu > 0) g.mu = std::min(g.mu, cap);
        for (auto& f : full.frictionNodes) f.mu = std::min(f.mu, cap);
        full.frictionCap = cap;
        full.periodicCopies = boundary_.periodicCopies();
        for (int a = 0; a < 3; ++a) full.periodic[a] = boundary_.periodic(a);
        r.configure(full);
        residentKey_ = c;
        residentConfigured_ = true;
    }
    if (levelSetChanged_)
    {
        r.setLevelSet(levelSet_.view(), lattice_.nNodes, Index(levelSet_.walls().size()));
        levelSetChanged_ = false;
    }
    if (hostAhead_)
    {
        if (options_.reorderPoints) sortByStencil();
        const Index n = particles_.size();
        for (auto& a : L_) a.resize(n);
        for (auto& a : dx_) a.resize(n);
        updateMassTolerance();
        r.uploadPoints(pointView(particles_, L_, dx_));
        hostAhead_ = false;
    }
    const Index n = particles_.size();
    const ResidentResult res = r.step(dt, massTolerance_, timers_, recordPhases_);
    deviceAhead_ = true;
    // The host step's stops, in its order
    if (res.firstBadStress < n) { pullPoints(); stopIfNonFinite(res.firstBadStress, "stress or deformation"); }
    inverted_ = InvertedPoints{};
    inverted_.count = res.inverted;
    if (res.inverted > 0) { pullPoints(); findFirstInverted(); }
    if (res.firstBadMove < n) { pullPoints(); stopIfNonFinite(res.firstBadMove, "velocity"); }
    contained_ += res.contained;
    if (res.beyondWall == 0) return;
    // Points beyond a box wall (a step far too large): held just inside,
    // counted, as movePoints does, here on the host
    pullPoints();
    r.downloadMoveFlags(moveFlags_);
    const PointView P = pointView(particles_, L_, dx_);
    const bool periodic[3] = {boundary_.periodic(0), boundary_.periodic(1), boundary_.periodic(2)};
    leaving_.assign(0, -1);
    for (Index p = 0; p < n; ++p)
    {
        if (!(moveFlags_[p] & moveOutside)) continue;
        const Real x[3] = {P.x[0][p], P.x[1][p], P.x[2][p]};
        bool beyondWall = false;
        exitCondition(x, beyondWall);
        clamped_ += beyondWall;
        storePosition(domain_, periodic, P, p, x);
    }
    containPoints(dt);
    hostAhead_ = true;
}

} // namespace mpm

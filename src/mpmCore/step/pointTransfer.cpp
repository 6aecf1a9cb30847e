// MpmSystem's point motion at the step's end and between ranks: the
// advance with open faces and walls, level-set containment, the removal of
// leaving points, and migration to the owning rank.
#include "mpmSystemLoops.hpp"
#include "../kernels/levelSetWall.hpp"
#include "../kernels/movePoint.hpp"
#include "../kernels/views.hpp"
#include <algorithm>
#include <limits>
#include <sstream>

namespace mpm {

// Moves every point by the displacement G2P stored (dt already in it).
// A point that crosses an open face leaves the domain and is removed; one
// that would cross a wall is put back just inside it, and counted.
void MpmSystem::movePoints(Real dt)
{
    const PointView P = pointView(particles_, L_, dx_);
    const Lattice& L = domain_;   // walls and periodicity are the domain's
    const Index n = P.n;
    Index firstBad = n;
    Index clamped = 0, leaving = 0;
    const bool frozen = options_.freezePositions;
    const bool open = boundary_.hasOpenFaces() || levelSet_.hasOutlets();
    const bool periodic[3] = {boundary_.periodic(0), boundary_.periodic(1), boundary_.periodic(2)};
    leaving_.assign(open ? n : 0, -1);
    #pragma omp parallel for schedule(static) reduction(min:firstBad) reduction(+:clamped, leaving) if(worthThreads(n))
    for (Index p = 0; p < n; ++p)
    {
        Real x[3];
        const int flags = advancePoint(L, periodic, frozen, P, p, x);
        if (flags & moveBad) { firstBad = std::min(firstBad, p); continue; }
        if (frozen) continue;
        if ((flags & moveOutside) && leavesThroughFace(p, x, leaving, clamped)) continue;
        storePosition(L, periodic, P, p, x);
    }
    stopIfNonFinite(firstBad, "velocity");
    clamped_ += clamped;
    if (!frozen) leaving += containPoints(dt);
    removeLeaving(leaving);
}

// A point whose new position x lies beyond a face: marked as leaving
// through an open face (true), or counted as clamped at a wall (false; the
// caller then stores it just inside). The host and device moves share it.
bool MpmSystem::leavesThroughFace(Index p, const Real x[3], Index& leaving, Index& clamped)
{
    bool beyondWall = false;
    const int through = exitCondition(x, beyondWall);
    if (through >= 0)
    {
        leaving_[p] = through;
        ++leaving;
        return true;
    }
    clamped += beyondWall;
    return false;
}

// Which faces the new position x lies beyond: an open one lets the point
// out (the first such axis names the face), walls hold it, and so do the
// open faces that hold points (WallCondition::holdsPoints: the faces beyond
// a mesh, reached only through a level-set wall, whose containment, after
// this, puts the point back on the material's side).
int MpmSystem::exitCondition(const Real x[3], bool& beyondWall) const
{
    const Lattice& L = domain_;
    const BoundarySpec& spec = boundary_.spec();
    int through = -1;
    for (int a = 0; a < 3 && through < 0; ++a)
    {
        if (!L.solved[a] || boundary_.periodic(a)) continue;
        const Real lo = L.origin[a], hi = lo + L.length(a);
        if (x[a] >= lo && x[a] < hi) continue;
        const int c = spec.conditionAtPosition(L, 2*a + (x[a] < lo ? 0 : 1), x);
        const WallCondition& wc = spec.conditions[c];
        if (isOpen(wc.type) && !wc.holdsPoints) through = c;
        else beyondWall = beyondWall || x[a] < lo || x[a] > hi;
    }
    return through;
}

void MpmSystem::removeLeaving(Index leaving)
{
    if (leaving == 0) return;
    const Index n = particles_.size();
    // In index order, serially: the removed sums do not depend on threads
    std::vector<Index> out;
    out.reserve(leaving);
    for (Index p = 0; p < n; ++p)
    {
        const int c = leaving_[p];
        if (c < 0) continue;
        out.push_back(p);
        ++removedCount_[c];
        removedMass_[c] += particles_.mass[p];
    }
    particles_.remove(out);
}

Index MpmSystem::containPoints(Real dt)
{
    const LevelSetView ls = levelSet_.view();
    if (!ls) return 0;
    const PointView P = pointView(particles_, L_, dx_);
    const Lattice& L = lattice_;
    const Index n = P.n;
    const auto& walls = levelSet_.walls();
    const bool outlets = levelSet_.hasOutlets();
    Index moved = 0, leaving = 0;
    #pragma omp parallel for schedule(static) reduction(+:moved, leaving) if(worthThreads(n))
    for (Index p = 0; p < n; ++p)
    {
        // Already leaving through a side of the box
        if (outlets && leaving_[p] >= 0) continue;
        const int r = levelSetContainPoint(L, ls, P, p, dt);
        if (r == 1) ++moved;
        else if (r >= 2)
        {
            leaving_[p] = walls[r - 2].specCondition;
            ++leaving;
        }
    }
    contained_ += moved;
    return leaving;
}

Index MpmSystem::migrate()
{
    if (!subdomain_) return 0;
    const Subdomain& sd = *subdomain_;
    const Communicator& comm = sd.comm();
    const int me = comm.rank(), np = comm.size();
    auto& P = particles_;
    const Index n = P.size();
    std::vector<int> dest(n);
    const std::int64_t none = std::numeric_limits<std::int64_t>::max();
    std::int64_t lost = none;
    Index sent = 0;
    #pragma omp parallel for reduction(min:lost) reduction(+:sent) if(worthThreads(n))
    for (Index p = 0; p < n; ++p)
    {
        const Real x[3] = {P.x[0][p], P.x[1][p], P.x[2][p]};
        dest[p] = sd.ownerOf(x);
        // One step moves a point to a cell its stencil reached: its owner
        // shares halo nodes with this rank.
        if (dest[p] != me && !sd.isNeighbour(dest[p])) lost = std::min<std::int64_t>(lost, P.id[p]);
        sent += dest[p] != me;
    }
    lost = comm.min(lost);
    if (lost != none)
    {
        std::ostringstream os;
        os << "material point id " << lost << " moved beyond its processor's "
           << "halo in one step (more than " << stencilReach(options_.shape)
           << " cells): the time step is far too large for the Courant number";
        throw std::runtime_error(os.str());
    }
    std::vector<std::vector<char>> send(np), recv(np);
    std::vector<Index> leaving;
    leaving.reserve(sent);
    for (Index p = 0; p < n; ++p)
    {
        if (dest[p] == me) continue;
        P.pack(p, send[dest[p]]);
        leaving.push_back(p);
    }
    // Sizes to and from the halo neighbours only, then the points: no
    // all-to-all, whatever the number of ranks.
    std::vector<std::vector<char>> sizeOut(np), sizeIn(np);
    for (const int q : sd.neighbours())
    {
        const std::int64_t bytes = std::int64_t(send[q].size());
        appendBytes(sizeOut[q], &bytes, 1);
        sizeIn[q].resize(sizeof(std::int64_t));
    }
    comm.exchange(sizeOut, sizeIn, true);
    for (const int q : sd.neighbours())
    {
        std::int64_t bytes;
        std::size_t at = 0;
        readBytes(sizeIn[q], at, &bytes, 1);
        recv[q].resize(std::size_t(bytes));
    }
    comm.exchange(send, recv, true);
    P.remove(leaving);
    for (int q = 0; q < np; ++q) P.unpack(recv[q]);
    migrated_ += sent;
    return sent;
}

} // namespace mpm

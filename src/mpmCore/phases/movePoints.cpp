#include "movePoints.hpp"
#include "../kernels/levelSetWall.hpp"
#include "../kernels/movePoint.hpp"
#include <algorithm>

namespace mpm {

void movePoints(SystemState& s, Real dt)
{
    const PointView P = s.points();
    const Lattice& L = s.domain;   // walls and periodicity are the domain's
    const Boundary& b = s.boundary;
    const Index n = P.n;
    Index firstBad = n;
    Index clamped = 0, leaving = 0;
    const bool frozen = s.options.freezePositions;
    const bool open = b.hasOpenFaces() || s.levelSet.hasOutlets();
    const bool periodic[3] = {b.periodic(0), b.periodic(1), b.periodic(2)};
    s.leavingThrough.assign(open ? n : 0, -1);
    #pragma omp parallel for schedule(static) reduction(min:firstBad) reduction(+:clamped, leaving) if(s.worthThreads(n))
    for (Index p = 0; p < n; ++p)
    {
        Real x[3];
        const int flags = advancePoint(L, periodic, frozen, P, p, x);
        if (flags & moveBad) { firstBad = std::min(firstBad, p); continue; }
        if (frozen) continue;
        if ((flags & moveOutside) && leavesThroughFace(s, p, x, leaving, clamped)) continue;
        storePosition(L, periodic, P, p, x);
    }
    s.stopIfNonFinite(firstBad, "velocity");
    s.clamped += clamped;
    if (!frozen) leaving += containPoints(s, dt);
    removeLeaving(s, leaving);
}

bool leavesThroughFace(SystemState& s, Index p, const Real x[3], Index& leaving, Index& clamped)
{
    bool beyondWall = false;
    const int through = exitCondition(s, x, beyondWall);
    if (through >= 0)
    {
        s.leavingThrough[p] = through;
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
int exitCondition(const SystemState& s, const Real x[3], bool& beyondWall)
{
    const Lattice& L = s.domain;
    const BoundarySpec& spec = s.boundary.spec();
    int through = -1;
    for (int a = 0; a < 3 && through < 0; ++a)
    {
        if (!L.solved[a] || s.boundary.periodic(a)) continue;
        const Real lo = L.origin[a], hi = lo + L.length(a);
        if (x[a] >= lo && x[a] < hi) continue;
        const int c = spec.conditionAtPosition(L, 2*a + (x[a] < lo ? 0 : 1), x);
        const WallCondition& wc = spec.conditions[c];
        if (isOpen(wc.type) && !wc.holdsPoints) through = c;
        else beyondWall = beyondWall || x[a] < lo || x[a] > hi;
    }
    return through;
}

Index containPoints(SystemState& s, Real dt)
{
    const LevelSetView ls = s.levelSet.view();
    if (!ls) return 0;
    const PointView P = s.points();
    const Lattice& L = s.lattice;
    const Index n = P.n;
    const auto& walls = s.levelSet.walls();
    const bool outlets = s.levelSet.hasOutlets();
    auto& leavingThrough = s.leavingThrough;
    Index moved = 0, leaving = 0;
    #pragma omp parallel for schedule(static) reduction(+:moved, leaving) if(s.worthThreads(n))
    for (Index p = 0; p < n; ++p)
    {
        // Already leaving through a side of the box
        if (outlets && leavingThrough[p] >= 0) continue;
        const int r = levelSetContainPoint(L, ls, P, p, dt);
        if (r == 1) ++moved;
        else if (r >= 2)
        {
            leavingThrough[p] = walls[r - 2].specCondition;
            ++leaving;
        }
    }
    s.contained += moved;
    return leaving;
}

void removeLeaving(SystemState& s, Index leaving)
{
    if (leaving == 0) return;
    const Index n = s.particles.size();
    // In index order, serially: the removed sums do not depend on threads
    std::vector<Index> out;
    out.reserve(leaving);
    for (Index p = 0; p < n; ++p)
    {
        const int c = s.leavingThrough[p];
        if (c < 0) continue;
        out.push_back(p);
        ++s.removedCount[c];
        s.removedMass[c] += s.particles.mass[p];
    }
    s.particles.remove(out);
}

} // namespace mpm

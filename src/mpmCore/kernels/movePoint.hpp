// Point motion: the body of one point's move by the displacement G2P stored
// (dt already in it), over the whole domain's lattice (walls and periodic
// directions are the domain's, also on a decomposed rank).
//
// advancePoint computes the new position, wrapped in periodic directions,
// and says whether the point went non-finite or lies beyond a non-periodic
// face. The few points beyond a face are classified by the host (an open
// face lets them out, a wall holds them: phases/movePoints.hpp), because
// that needs the boundary's per-patch conditions. storePosition writes the
// position back, just inside the walls.
#pragma once
#include "../grid/lattice.hpp"
#include "views.hpp"
#include <cmath>

namespace mpm {

enum MoveFlags : int { moveBad = 1, moveOutside = 2 };

MPM_HOST_DEVICE inline int advancePoint
(
    const Lattice& L, const bool periodic[3], bool frozen, const PointView& P, Index p, Real x[3]
)
{
    int flags = 0;
    for (int a = 0; a < 3; ++a)
    {
        x[a] = P.x[a][p];
        if (!std::isfinite(P.v[a][p]) || !std::isfinite(P.dx[a][p])) { flags |= moveBad; continue; }
        if (frozen || !L.solved[a]) continue;
        x[a] += P.dx[a][p];
        if (periodic[a])
        {
            const Real lo = L.origin[a], len = L.length(a);
            x[a] = lo + std::fmod(std::fmod(x[a] - lo, len) + len, len);
        }
    }
    if (flags || frozen) return flags;
    for (int a = 0; a < 3; ++a)
    {
        if (!L.solved[a] || periodic[a]) continue;
        const Real lo = L.origin[a], hi = lo + L.length(a);
        if (!(x[a] >= lo && x[a] < hi)) flags |= moveOutside;
    }
    return flags;
}

// A wall is impenetrable: a point that would cross it stops just inside (a
// large step, not normal operation).
MPM_HOST_DEVICE inline void storePosition
(
    const Lattice& L, const bool periodic[3], const PointView& P, Index p, const Real x[3]
)
{
    for (int a = 0; a < 3; ++a)
    {
        if (!L.solved[a] || periodic[a]) { P.x[a][p] = x[a]; continue; }
        const Real lo = L.origin[a], len = L.length(a);
        const Real eps = 1e-9*L.h;
        const Real xa = x[a] < lo + eps ? lo + eps : x[a];
        P.x[a][p] = xa > lo + len - eps ? lo + len - eps : xa;
    }
}

} // namespace mpm

// Kernel bodies of the level-set walls (grid/levelSet.hpp): the wall
// condition on one node's updated velocity, and the containment of one point
// after it moved. Both read only the node arrays of the level set, so they
// run unchanged on every back-end.
#pragma once
#include "../grid/boundary.hpp"
#include "../grid/lattice.hpp"
#include "../grid/levelSet.hpp"
#include "views.hpp"
#include <cmath>

namespace mpm {

// A node inside a wall (phi < 0) with material: noSlip stops it; slip and
// friction act only while it approaches the wall (v.n < 0, n into the
// material's side), removing the normal speed; friction then reduces the
// tangential speed by mu times the normal speed removed (the wall's normal
// impulse per unit mass in this step), never reversing it. Summed over the
// nodes in contact, the normal impulse is the load the wall carries, so a
// body sliding on a level-set wall feels mu times its normal load.
// muCap: the largest friction coefficient applied (SystemState::frictionCap:
// a wall rougher than the material holds it as the material's own friction)
//
// A noSlip wall also stops the nodes within one cell outside it (phi <
// normalHold) from moving away from it, leaving their tangential velocity
// and their approach free. Why: a box wall's mirrored ghosts give the first
// node layer outside the wall the image of the material's stress, so its
// forces balance as inside the material; a level-set wall has no image, so
// that layer feels the stress from one side only and is pulled like a free
// end. Measured on the axial bar fixed at a level-set plane
// (tests/cases/axialBar.sh, part 4): held only inside the wall, it vibrated
// 4.6 % slow at 50 cells, as if the wall were 2.3 cells further away; now
// 0.21 % fast. Holding the band's approach too (both ways) also fixed the
// bar, but made a block dropped on the wall come to rest a cell above it
// (tests/cases/obstacles.sh, "resting on a noSlip plane"). The tangential
// velocity stays free, as at a mirrored noSlip wall, whose first node
// layer shears freely.
MPM_HOST_DEVICE inline void levelSetWallNode
(
    const LevelSetView& ls, const Real* mass, Real* const v[3], Real massTolerance, Index I, Real muCap
)
{
    const Real phi = ls.phi[I];
    if (!(phi < ls.contact || phi < ls.normalHold) || mass[I] <= massTolerance) return;
    const int w = ls.wall[I];
    if (ls.type[w] == int(WallType::outlet)) return;   // open: no condition
    if (ls.type[w] == int(WallType::inlet))
    {
        // Beyond an inlet (a Dirichlet band, as beyond an inlet face of
        // the box): the material there moves in at the inlet's velocity
        if (phi < ls.contact) for (int d = 0; d < 3; ++d) v[d][I] = ls.velocity[d][w];
        return;
    }
    const bool noSlip = ls.type[w] == int(WallType::noSlip);
    if (!(phi < ls.contact) && !noSlip) return;
    // Relative to the wall (a moving wall: its velocity; else zero)
    const Real vw[3] = {ls.velocity[0][w], ls.velocity[1][w], ls.velocity[2][w]};
    Real u[3] = {v[0][I] - vw[0], v[1][I] - vw[1], v[2][I] - vw[2]};
    const Real n[3] = {ls.normal[0][I], ls.normal[1][I], ls.normal[2][I]};
    const Real un = u[0]*n[0] + u[1]*n[1] + u[2]*n[2];
    if (noSlip)
    {
        if (phi < ls.contact) for (int d = 0; d < 3; ++d) v[d][I] = vw[d];
        else if (un > 0) for (int d = 0; d < 3; ++d) v[d][I] -= un*n[d];
        return;
    }
    if (un >= 0) return;   // leaving the wall: unilateral
    for (int d = 0; d < 3; ++d) u[d] -= un*n[d];
    if (ls.type[w] == int(WallType::friction))
    {
        const Real ut = std::sqrt(u[0]*u[0] + u[1]*u[1] + u[2]*u[2]);
        const Real du = -(ls.mu[w] < muCap ? ls.mu[w] : muCap)*un;
        const Real scale = ut > du ? 1 - du/ut : 0;
        for (int d = 0; d < 3; ++d) u[d] *= scale;
    }
    for (int d = 0; d < 3; ++d) v[d][I] = u[d] + vw[d];
}

// Whether wall w is open (an outlet or an inlet); spelled out rather than
// isOpen(), a host function, since the CUDA back-end runs these bodies
MPM_HOST_DEVICE inline bool levelSetWallOpen(const LevelSetView& ls, int w)
{
    return ls.type[w] == int(WallType::outlet) || ls.type[w] == int(WallType::inlet);
}

// The velocity of wall w's surface: a moving wall's; an open wall's (an
// inlet's velocity is its material's, not its own) zero
MPM_HOST_DEVICE inline Real levelSetSurfaceVelocity(const LevelSetView& ls, int w, int a)
{
    return levelSetWallOpen(ls, w) ? Real(0) : ls.velocity[a][w];
}

// Signed distance of x from the closest-point plane of node I, the plane
// moved on by its wall's velocity times dt (the wall at the step's end)
MPM_HOST_DEVICE inline Real levelSetPlaneDistance
(
    const Lattice& L, const LevelSetView& ls, const int c[3], Index I, const Real x[3], Real dt
)
{
    Real d = ls.phi[I];
    const int w = ls.wall[I];
    for (int a = 0; a < 3; ++a)
    {
        if (!L.solved[a]) continue;
        const Real xa = L.origin[a] + (c[a] + 0.5)*L.h;
        d += ls.normal[a][I]*(x[a] - xa - dt*levelSetSurfaceVelocity(ls, w, a));
    }
    return d;
}

// After a point moved: the most negative distance of its position from the
// closest-point planes of the 2^dim nodes around it; below zero the point
// lies inside a wall and is put back on that plane (a hair outside), and
// its velocity loses the part that approaches the wall. Repeated so that a
// point in a corner between two walls leaves both. A convex wall lies
// behind each of its tangent planes, so a point outside them all is outside
// the wall. Points more than a band from every wall cost one load. dt: the
// step's, over which a moving wall's planes move on. Returns 0 (left
// alone), 1 (put back), or 2 + w: the point lies beyond outlet (or inlet)
// w and leaves (nothing is changed).
MPM_HOST_DEVICE inline int levelSetContainPoint
(
    const Lattice& L, const LevelSetView& ls, const PointView& P, Index p, Real dt
)
{
    Real x[3] = {P.x[0][p], P.x[1][p], P.x[2][p]};
    // The cell holding the point (its node is the nearest) and the lower
    // corner of the 2^dim nodes around it
    int cell[3] = {0, 0, 0}, lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (int a = 0; a < 3; ++a)
    {
        if (!L.solved[a]) continue;
        const Real s = (x[a] - L.origin[a])/L.h;
        cell[a] = int(std::floor(s));
        lo[a] = int(std::floor(s - 0.5));
        hi[a] = lo[a] + 1;
        // Stay on the lattice's nodes (ghost layers included)
        if (lo[a] < -L.pad) lo[a] = -L.pad;
        if (hi[a] > L.nCells[a] + L.pad - 1) hi[a] = L.nCells[a] + L.pad - 1;
        if (cell[a] < -L.pad || cell[a] > L.nCells[a] + L.pad - 1) return 0;
    }
    if (ls.phi[L.realNode(cell[0], cell[1], cell[2])] > ls.band) return 0;
    bool moved = false;
    for (int pass = 0; pass < 3; ++pass)
    {
        Real worst = 0, n[3] = {0, 0, 0};
        int through = -1;
        for (int k = lo[2]; k <= hi[2]; ++k)
        for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i)
        {
            const int c[3] = {i, j, k};
            const Index I = L.realNode(i, j, k);
            // Beyond the band phi is only a bound and the normal arbitrary
            // (no surface within reach): no plane to test against. Such
            // nodes lie deep inside a wall, e.g. the ghosts beyond a box
            // face that stays a mirrored wall while other patches of the
            // mesh are level sets; testing them pushed the points beside
            // that face a band's width along an arbitrary normal.
            if (!(ls.phi[I] > -ls.band)) continue;
            const Real d = levelSetPlaneDistance(L, ls, c, I, x, dt);
            if (d < worst)
            {
                worst = d;
                through = ls.wall[I];
                for (int a = 0; a < 3; ++a) n[a] = ls.normal[a][I];
            }
        }
        if (worst >= 0) break;
        // Beyond an outlet or an inlet the point leaves, where it is (on
        // the first pass: a point put back from a wall stays)
        if (levelSetWallOpen(ls, through) && !moved) return 2 + through;
        const Real push = -worst + 1e-9*L.h;
        for (int a = 0; a < 3; ++a) x[a] += push*n[a];
        // The velocity relative to the wall loses its approaching part
        Real un = 0;
        for (int a = 0; a < 3; ++a) un += (P.v[a][p] - levelSetSurfaceVelocity(ls, through, a))*n[a];
        if (un < 0) for (int a = 0; a < 3; ++a) P.v[a][p] -= un*n[a];
        moved = true;
    }
    if (moved) for (int a = 0; a < 3; ++a) P.x[a][p] = x[a];
    return moved ? 1 : 0;
}

} // namespace mpm

#include "boundary.hpp"
#include "../common/enumTable.hpp"
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mpm {

namespace
{
const auto wallTypes = enumTable<WallType>
({{WallType::noSlip, "noSlip"}, {WallType::slip, "slip"}, {WallType::friction, "friction"},
  {WallType::periodic, "periodic"}, {WallType::outlet, "outlet"}, {WallType::inlet, "inlet"}});
const std::string wallTypeList = wallTypes.validNames();
}

const char* wallTypeName(WallType t) { return wallTypes.name(t); }
bool parseWallType(const std::string& name, WallType& t) { return wallTypes.parse(name, t); }
const char* validWallTypeNames() { return wallTypeList.c_str(); }

int BoundarySpec::conditionAt(const Lattice& L, int side, int i, int j, int k) const
{
    const auto& fc = faceCondition[side];
    if (fc.empty()) return 0;
    const int axis = side/2;
    const int r[3] = {i, j, k};
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    const int lo = a1 < a2 ? a1 : a2, hi = a1 < a2 ? a2 : a1;
    return fc[std::size_t(r[lo]) + std::size_t(L.nCells[lo])*std::size_t(r[hi])];
}

int BoundarySpec::conditionAtPosition(const Lattice& L, int side, const Real x[3]) const
{
    int r[3] = {0, 0, 0};
    for (int a = 0; a < 3; ++a)
    {
        if (!L.solved[a]) continue;
        const long c = long(std::floor((x[a] - L.origin[a])/L.h));
        r[a] = int(std::min<long>(std::max<long>(c, 0), L.nCells[a] - 1));
    }
    return conditionAt(L, side, r[0], r[1], r[2]);
}

std::array<bool, 3> Boundary::periodicAxes(const Lattice& L, const BoundarySpec& spec)
{
    std::array<bool, 3> periodic{false, false, false};
    for (int a = 0; a < 3; ++a)
    {
        if (!L.solved[a]) continue;
        const bool lo = spec.conditions.at(spec.conditionAt(L, 2*a, 0, 0, 0)).type == WallType::periodic;
        const bool hi = spec.conditions.at(spec.conditionAt(L, 2*a + 1, 0, 0, 0)).type == WallType::periodic;
        if (lo != hi)
        {
            throw std::invalid_argument
            (
                "boundary: direction " + std::to_string(a)
              + " is periodic on one side only"
            );
        }
        periodic[a] = lo;
    }
    return periodic;
}

void Boundary::build(const Lattice& L, const BoundarySpec& spec)
{
    build(L, spec, L, {0, 0, 0}, nullptr);
}

void Boundary::build
(
    const Lattice& L, const BoundarySpec& spec, const Lattice& B,
    const std::array<int, 3>& offset, const std::function<bool(Index)>& ownsCell
)
{
    ghosts_.clear();
    periodicCopies_.clear();
    friction_.clear();
    inlet_.clear();
    free_.clear();
    spec_ = spec;
    hasOpen_ = false;
    hasFriction_ = false;
    for (const auto& wc : spec.conditions)
    {
        hasOpen_ = hasOpen_ || isOpen(wc.type);
        hasFriction_ = hasFriction_ || wc.type == WallType::friction;
    }
    periodic_ = periodicAxes(L, spec);
    const bool decomposed = bool(ownsCell);

    for (int k = 0; k < B.nodes[2]; ++k)
    for (int j = 0; j < B.nodes[1]; ++j)
    for (int i = 0; i < B.nodes[0]; ++i)
    {
        // Global real indices
        int r[3] = {i - B.padOf(0) + offset[0], j - B.padOf(1) + offset[1], k - B.padOf(2) + offset[2]};
        bool wrapped = false;
        int c[3] = {r[0], r[1], r[2]};
        for (int a = 0; a < 3; ++a)
        {
            const int n = L.nCells[a];
            if (!L.solved[a] || !periodic_[a] || (r[a] >= 0 && r[a] < n)) continue;
            c[a] = ((r[a] % n) + n) % n;
            wrapped = true;
        }
        if (wrapped)
        {
            // A periodic copy: the halo's (serial: ours, as a pair).
            if (!decomposed)
            {
                periodicCopies_.emplace_back(B.node(i, j, k), B.node(c[0] + B.padOf(0), c[1] + B.padOf(1), c[2] + B.padOf(2)));
            }
            continue;
        }
        // A wall ghost: reflect each out-of-range solved coordinate in turn.
        // Across an open face (outlet, inlet) nothing is reflected: the node
        // is free along that axis (the lattice continues through the face).
        bool beyond = false, isGhost = false;
        int inletCondition = -1;
        std::array<Real, 3> sign{1, 1, 1};
        int reflections = 0, unilateralAxis = -1;
        Real outward = 0, mu = 0;
        // Every out-of-range coordinate reflected, open or not: the real
        // cell whose owner folds this node (decomposed runs), as the
        // Subdomain decides the node's owner.
        int full[3] = {r[0], r[1], r[2]};
        for (int a = 0; a < 3; ++a)
        {
            const int n = L.nCells[a];
            if (!L.solved[a] || (r[a] >= 0 && r[a] < n)) continue;
            beyond = true;
            const bool low = r[a] < 0;
            // The face this ghost lies across: other coordinates clamped.
            int f[3] = {r[0], r[1], r[2]};
            for (int b = 0; b < 3; ++b)
            {
                f[b] = f[b] < 0 ? 0 : (f[b] >= L.nCells[b] ? L.nCells[b] - 1 : f[b]);
            }
            const int ci = spec.conditionAt(L, 2*a + (low ? 0 : 1), f[0], f[1], f[2]);
            const auto& wc = spec.conditions.at(ci);
            full[a] = low ? -1 - r[a] : 2*n - 1 - r[a];
            if (isOpen(wc.type))
            {
                if (wc.type == WallType::inlet) inletCondition = ci;
                continue;
            }
            isGhost = true;
            r[a] = full[a];
            ++reflections;
            if (wc.type == WallType::noSlip) { for (auto& s : sign) s = -s; }
            else
            {
                sign[a] = -sign[a]; unilateralAxis = a; outward = low ? -1 : 1;
                mu = wc.type == WallType::friction ? wc.frictionCoefficient : 0.0;
            }
        }
        if (!beyond) continue;
        if (!isGhost)
        {
            // A free node beyond open faces only
            if (inletCondition >= 0) inlet_.push_back({B.node(i, j, k), inletCondition});
            if (!decomposed || ownsCell(L.cellIndex(full[0], full[1], full[2])))
            {
                free_.emplace_back
                (
                    B.node(i, j, k),
                    B.realNode(full[0] - offset[0], full[1] - offset[1], full[2] - offset[2])
                );
            }
            continue;
        }
        if (decomposed && !ownsCell(L.cellIndex(full[0], full[1], full[2]))) continue;
        // Corner ghosts (two or more reflections) stay bilateral.
        if (reflections != 1) unilateralAxis = -1;
        // The image: a real node, or a free node beyond an open face when
        // the ghost lies beyond a wall and an open face at once (a corner)
        const Index image = B.realNode(r[0] - offset[0], r[1] - offset[1], r[2] - offset[2]);
        ghosts_.push_back
        (
            {B.node(i, j, k), image, sign, unilateralAxis, unilateralAxis >= 0 ? outward : 0.0,
             unilateralAxis >= 0 ? mu : 0.0}
        );
    }

    // Friction contact acts on the first node layer next to friction faces.
    for (int a = 0; a < 3; ++a)
    {
        if (!L.solved[a]) continue;
        for (int lowHigh = 0; lowHigh < 2; ++lowHigh)
        {
            const int side = 2*a + lowHigh;
            for (int k = 0; k < B.nCells[2]; ++k)
            for (int j = 0; j < B.nCells[1]; ++j)
            for (int i = 0; i < B.nCells[0]; ++i)
            {
                const int r[3] = {i + offset[0], j + offset[1], k + offset[2]};
                if (r[a] != (lowHigh ? L.nCells[a] - 1 : 0)) continue;
                bool real = true;
                for (int b = 0; b < 3; ++b) real = real && r[b] >= 0 && r[b] < L.nCells[b];
                if (!real || (decomposed && !ownsCell(L.cellIndex(r[0], r[1], r[2])))) continue;
                const auto& wc = spec.conditions.at(spec.conditionAt(L, side, r[0], r[1], r[2]));
                if (wc.type != WallType::friction) continue;
                friction_.push_back({B.realNode(i, j, k), a, lowHigh ? 1.0 : -1.0, wc.frictionCoefficient});
            }
        }
    }
}

} // namespace mpm

// The 3D elastic block the throughput benchmarks step: n^3 cells of
// linear-elastic material (8 points per cell) in the middle of a no-slip
// box with 4 empty cells on each side, thrown sideways under gravity.
#pragma once
#include "constitutive/constitutiveLaw.hpp"
#include "step/mpmSystem.hpp"
#include <algorithm>
#include <random>

namespace mpm::bench {

// resident: with the cuda back-end, the resident step (false: host-assisted)
// and its P2G reduction (StepOptions::p2gWarpReduction)
inline MpmSystem makeBlock(ShapeKind shape, int n, bool reorder, bool shuffle, Backend backend = Backend::openmp,
                           bool resident = true, bool warpReduction = true)
{
    // The block is n^3 cells; the lattice adds 4 empty cells on each side.
    const int m = n + 8;
    Lattice L;
    L.h = 1.0/n;
    L.nCells = {m, m, m};
    BoundarySpec b;   // no-slip box
    StepOptions o;
    o.shape = shape;
    o.gravity = {0, 0, -9.81};
    o.reorderPoints = reorder;
    o.backend = backend;
    o.deviceResident = resident;
    o.p2gWarpReduction = warpReduction;
    MpmSystem s;
    s.setup(L, b, o);
    s.materials().push_back(makeLaw("linearElastic", {{"rho", 1000}, {"E", 1e6}, {"nu", 0.3}}));
    // Block filling the middle of the box, 2x2x2 points per cell.
    const int lo = 4, hi = n + 4;
    const Real h = L.h, vol = h*h*h/8;
    for (int k = lo; k < hi; ++k)
    for (int j = lo; j < hi; ++j)
    for (int i = lo; i < hi; ++i)
    for (int c = 0; c < 8; ++c)
    {
        const Real x = (i + 0.25 + 0.5*(c & 1))*h;
        const Real y = (j + 0.25 + 0.5*((c >> 1) & 1))*h;
        const Real z = (k + 0.25 + 0.5*((c >> 2) & 1))*h;
        s.particles().add({x, y, z}, {0.1, 0, 0}, 1000*vol, vol, 0);
    }
    if (shuffle)
    {
        // Storage order unrelated to space: points after long mixing
        std::vector<Index> order(s.particles().size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = Index(i);
        std::mt19937 rng(1);
        std::shuffle(order.begin(), order.end(), rng);
        s.particles().permute(order);
    }
    return s;
}


} // namespace mpm::bench

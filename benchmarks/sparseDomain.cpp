// Cost against the size of the empty domain: the same elastic ball (2176
// points, quadratic B-splines, 8 points per cell, falling and moving
// sideways) in boxes of 1x, 2x, 4x, 8x and 16x the volume of a 20^3-cell
// box, with the grid work over the active region only (sparseGrid, the
// default) and over the whole lattice (the dense reference). The sparse
// time per step should not grow with the box; the dense one does. All in
// one run, one thread, so the ratios share the machine's state.
//
//   build/benchmarks/sparseDomain [steps=300]
#include "constitutive/constitutiveLaw.hpp"
#include "step/mpmSystem.hpp"
#include "machine.hpp"
#include "timedSteps.hpp"
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <omp.h>
#include <string>

using namespace mpm;

namespace {


MpmSystem makeBall(int nx, int ny, int nz, bool sparse)
{
    const Real h = 0.05;
    Lattice L;
    L.h = h;
    L.nCells = {nx, ny, nz};
    BoundarySpec b;   // no-slip box
    StepOptions o;
    o.shape = ShapeKind::quadraticBSpline;
    o.gravity = {0, 0, -9.81};
    o.sparseGrid = sparse;
    MpmSystem s;
    s.setup(L, b, o);
    s.materials().push_back(makeLaw("linearElastic", {{"rho", 1000}, {"E", 1e5}, {"nu", 0.3}}));
    // Ball of radius 4.2 cells centred at (10, 10, 10) cells: the same
    // points in every box
    const Real r = 4.2*h, c = 10*h, vol = h*h*h/8;
    for (int k = 0; k < 40; ++k)
    for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i)
    {
        const Real x = (i + 0.5)*h/2, y = (j + 0.5)*h/2, z = (k + 0.5)*h/2;
        if (std::hypot(x - c, y - c, z - c) > r) continue;
        s.particles().add({x, y, z}, {0.5, 0.3, 0}, 1000*vol, vol, 0);
    }
    return s;
}

} // namespace

int main(int argc, char** argv)
{
    const int steps = argc > 1 ? std::atoi(argv[1]) : 300;
    omp_set_num_threads(1);
    std::printf("# sparseDomain: one elastic ball (QBS, 8 points/cell) in growing empty boxes, %d steps, 1 thread\n", steps);
    std::printf("# machine: %s\n", bench::machine().c_str());
    std::printf("%-6s %-12s %8s %8s %12s %10s %12s %10s %10s %12s\n", "grid", "box (cells)", "volume", "points",
                "ms/step", "vs 1x", "active nodes", "nodal%", "Mpt-st/s", "cpu Mpt-st/s");
    const int boxes[5][3] = {{20, 20, 20}, {40, 20, 20}, {40, 20, 40}, {40, 40, 40}, {80, 20, 80}};
    for (bool sparse : {true, false})
    {
        double base = 0;
        for (const auto& bx : boxes)
        {
            MpmSystem s = makeBall(bx[0], bx[1], bx[2], sparse);
            const bench::TimedSteps r = bench::timeSteps(s, s.stableDeltaT(0.5), 5, steps);
            const double sec = r.seconds;
            const double ms = 1e3*sec/steps;
            if (base == 0) base = ms;
            char name[32];
            std::snprintf(name, sizeof name, "%dx%dx%d", bx[0], bx[1], bx[2]);
            std::printf("%-6s %-12s %7dx %8lld %12.3f %10.2f %12lld %10.1f %10.2f %12.2f\n", sparse ? "sparse" : "dense", name,
                        bx[0]*bx[1]*bx[2]/8000, (long long)s.particles().size(), ms, ms/base,
                        (long long)s.activeNodeCount(), 100*r.phases.nodal/r.phases.total(),
                        s.particles().size()*double(steps)/sec/1e6,
                        s.particles().size()*double(steps)/r.cpuSeconds/1e6);
        }
    }
    return 0;
}

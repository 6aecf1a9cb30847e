// What a level-set wall costs per MPM step against today's mirrored box
// wall: the same 3D elastic block (cubic B-splines, APIC, 8 points per
// cell) sliding on a friction floor, the floor either the box's mirrored
// y- side or a level-set plane two cells above it (the box's floor then
// untouched), and a third run on a plane tilted 25 degrees about z (not
// aligned with the lattice, the block resting on it). Runs alternate A B C
// A B C ... on one thread, so the ratios share the machine's state; the
// medians are printed.
//
//   build/benchmarks/levelSetWalls [steps=60] [repeats=3]
#include "constitutive/constitutiveLaw.hpp"
#include "step/mpmSystem.hpp"
#include "machine.hpp"
#include "timedSteps.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <omp.h>
#include <vector>

using namespace mpm;

namespace {

constexpr Real h = 0.05;

enum class Floor { mirrored, levelSet, tilted };
const char* name(Floor f)
{
    return f == Floor::mirrored ? "mirrored box floor" : f == Floor::levelSet ? "level-set floor" : "level-set 25 deg";
}

MpmSystem makeBlock(Floor floor)
{
    Lattice L;
    L.h = h;
    L.nCells = {40, 24, 40};
    BoundarySpec b;
    b.conditions = {WallCondition{WallType::slip, 0}, WallCondition{WallType::friction, 0.3}};
    if (floor == Floor::mirrored) b.faceCondition[2].assign(std::size_t(40*40), 1);
    StepOptions o;
    o.transfer = Transfer::apic;
    o.gravity = {0, -9.81, 0};
    MpmSystem s;
    s.setup(L, b, o);
    const Real th = floor == Floor::tilted ? 25*M_PI/180 : 0;
    const Real base = floor == Floor::mirrored ? 0 : 2*h;
    const std::array<Real, 3> n{std::sin(th), std::cos(th), 0}, t{std::cos(th), -std::sin(th), 0};
    const std::array<Real, 3> origin{0, base + (floor == Floor::tilted ? 40*h*std::tan(th) : 0), 0};
    if (floor != Floor::mirrored)
    {
        s.setLevelSetWalls({{"floor", std::make_shared<HalfSpaceShape>(origin, n), WallCondition{WallType::friction, 0.3}}},
                           {0, 0, 0});
    }
    s.materials().push_back(makeLaw("linearElastic", {{"rho", 1000}, {"E", 1e6}, {"nu", 0.3}}));
    // A 24 x 8 x 24-cell block, 2 x 2 x 2 points per cell, on the floor,
    // moving at 1 m/s along it
    const Real dp = h/2, vol = dp*dp*dp;
    for (int k = 0; k < 48; ++k)
    for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 48; ++i)
    {
        const Real s0 = 8*h + (i + 0.5)*dp, r = (j + 0.5)*dp, z = 8*h + (k + 0.5)*dp;
        s.particles().add({origin[0] + s0*t[0] + r*n[0], origin[1] + s0*t[1] + r*n[1], z},
                          {t[0], t[1], 0}, 1000*vol, vol, 0);
    }
    return s;
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size()/2];
}

} // namespace

int main(int argc, char** argv)
{
    const int steps = argc > 1 ? std::atoi(argv[1]) : 60;
    const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
    omp_set_num_threads(1);
    std::printf("# levelSetWalls: a 3D block (CBS, APIC, 36864 points) sliding on a friction floor,"
                " %d steps x %d repeats, 1 thread\n", steps, repeats);
    std::printf("# machine: %s\n", bench::machine().c_str());
    const Floor floors[3] = {Floor::mirrored, Floor::levelSet, Floor::tilted};
    std::vector<double> ms[3], nodal[3], g2p[3];
    for (int r = 0; r < repeats; ++r)
    {
        for (int f = 0; f < 3; ++f)
        {
            MpmSystem s = makeBlock(floors[f]);
            const Real dt = s.stableDeltaT(0.3);
            const bench::TimedSteps t = bench::timeSteps(s, dt, 3, steps);
            ms[f].push_back(1e3*t.cpuSeconds/steps);
            nodal[f].push_back(1e3*t.phases.nodal/steps);
            g2p[f].push_back(1e3*t.phases.g2p/steps);
        }
    }
    std::printf("%-22s %12s %10s %14s %12s\n", "floor", "ms/step", "vs box", "nodal ms/step", "g2p+move ms");
    for (int f = 0; f < 3; ++f)
    {
        std::printf("%-22s %12.2f %10.3f %14.2f %12.2f\n", name(floors[f]), median(ms[f]),
                    median(ms[f])/median(ms[0]), median(nodal[f]), median(g2p[f]));
    }
    return 0;
}

// Controlled experiments on the transfer kernels of one thread (the
// "levers" of issue 10): the kernel bodies (kernels/*.hpp) timed alone on
// the 3D block of particleThroughput (n^3 cells, 8 points per cell, stored
// in cell order), without the step around them, so that each lever's effect
// is measured on the part it changes.
//
//   build/benchmarks/transferLevers [cells=32] [rounds=7]
//
// Per shape, CPU ns per point (this thread's CPU time: the machine is
// shared; minimum over the rounds, the median after it):
//   stencil       Stencil::compute alone (the 1D weights, K::eval)
//   nodeLoop      compute + forEach summing N: the node loop without grid
//   p2g           the USL scatter (mass, volume, momentum, force)
//   g2p           FLIP gather (velocity, displacement, gradient)
//   move          point motion (advancePoint + storePosition)
//   g2p+move      both in one loop over the points (fused)
//   store         compute every point's stencil and store it (the cost
//                 side of precomputing the weights once per step)
//   triad         a[i] = b[i] + s c[i] over 3 x 64 MiB: bytes/ns of one core
#include "kernels/g2p.hpp"
#include "kernels/movePoint.hpp"
#include "kernels/p2g.hpp"
#include "machine.hpp"
#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using namespace mpm;

namespace {

struct Arrays
{
    std::vector<std::vector<Real>> store;
    Real* add(Index n, Real value = 0)
    {
        store.emplace_back(n, value);
        return store.back().data();
    }
};

struct Block
{
    Lattice L;
    PointView P;
    GridView g;
    Arrays a;
    std::vector<int> material;
};

Block makeBlock(int n)
{
    Block b;
    const int m = n + 8;
    b.L.h = 1.0/n;
    b.L.nCells = {m, m, m};
    b.L.finalise();
    const Index np = Index(n)*n*n*8;
    PointView& P = b.P;
    P.n = np;
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> u(-1, 1);
    for (int d = 0; d < 3; ++d) { P.x[d] = b.a.add(np); P.v[d] = b.a.add(np); P.dx[d] = b.a.add(np); }
    for (int e = 0; e < 9; ++e) { P.F[e] = b.a.add(np); P.C[e] = b.a.add(np); P.L[e] = b.a.add(np); }
    for (int c = 0; c < 6; ++c) P.sigma[c] = b.a.add(np);
    const Real h = b.L.h, vol = h*h*h/8;
    P.mass = b.a.add(np, 1000*vol);
    P.volume = b.a.add(np, vol);
    P.volume0 = b.a.add(np, vol);
    P.eqPlasticStrain = b.a.add(np);
    b.material.assign(np, 0);
    P.material = b.material.data();
    Index p = 0;
    for (int k = 4; k < n + 4; ++k)
    for (int j = 4; j < n + 4; ++j)
    for (int i = 4; i < n + 4; ++i)
    for (int c = 0; c < 8; ++c, ++p)
    {
        P.x[0][p] = (i + 0.25 + 0.5*(c & 1))*h;
        P.x[1][p] = (j + 0.25 + 0.5*((c >> 1) & 1))*h;
        P.x[2][p] = (k + 0.25 + 0.5*((c >> 2) & 1))*h;
        for (int d = 0; d < 3; ++d) P.v[d][p] = 0.1*u(rng);
        for (int s = 0; s < 6; ++s) P.sigma[s][p] = 1e3*u(rng);
    }
    GridView& g = b.g;
    g.n = b.L.nNodes;
    g.mass = b.a.add(g.n);
    g.volume = b.a.add(g.n);
    for (int d = 0; d < 3; ++d)
    {
        g.momentum[d] = b.a.add(g.n);
        g.force[d] = b.a.add(g.n);
        g.velocityOld[d] = b.a.add(g.n);
        g.velocity[d] = b.a.add(g.n);
        for (Index I = 0; I < g.n; ++I) { g.velocity[d][I] = 0.1*u(rng); g.velocityOld[d][I] = 0.1*u(rng); }
    }
    return b;
}

// CPU time of this thread, ns: the machine is shared, and a time slice
// given to another process would count in the wall clock
double cpuNs()
{
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e9*double(t.tv_sec) + double(t.tv_nsec);
}

// CPU ns per point of fn() over all points: minimum and median over the rounds
template<class Fn>
void timeIt(const char* shape, const char* what, Index points, int rounds, Fn&& fn)
{
    std::vector<double> ns;
    for (int r = 0; r < rounds; ++r)
    {
        const double t0 = cpuNs();
        fn();
        ns.push_back((cpuNs() - t0)/points);
    }
    std::sort(ns.begin(), ns.end());
    std::printf("%-18s %-14s %10.2f %10.2f\n", shape, what, ns.front(), ns[ns.size()/2]);
}

volatile Real sink;

template<class K>
void levers(const char* shape, Block& b, int rounds)
{
    constexpr int D = 3;
    const Lattice& L = b.L;
    const PointView& P = b.P;
    const GridView& g = b.g;
    const Index n = P.n;
    const Real invRho0 = 1e-3, dt = 1e-5;
    const bool periodic[3] = {false, false, false};
    timeIt(shape, "stencil", n, rounds, [&]
    {
        Real s = 0;
        for (Index p = 0; p < n; ++p)
        {
            Stencil<K, D> st;
            st.compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
            s += st.w[0][0] + st.dw[1][0] + st.w[2][K::width - 1] + Real(st.base[0]);
        }
        sink = s;
    });
    timeIt(shape, "nodeLoop", n, rounds, [&]
    {
        Real s = 0;
        for (Index p = 0; p < n; ++p)
        {
            Stencil<K, D> st;
            st.compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
            st.forEach(L, [&](Index I, Real N, const Real* dN, const Real*) { s += N*dN[0] + Real(I); });
        }
        sink = s;
    });
    timeIt(shape, "p2g", n, rounds, [&]
    {
        for (Index p = 0; p < n; ++p) p2gPoint<K, D, true, true, false>(L, P, g, &invRho0, false, p, PlainAdd{});
    });
    timeIt(shape, "g2p", n, rounds, [&]
    {
        for (Index p = 0; p < n; ++p) g2pPoint<K, D, false>(L, P, g, 0.99, dt, p);
    });
    // The motion's inputs: a small displacement that keeps the points inside
    for (int d = 0; d < 3; ++d) for (Index p = 0; p < n; ++p) P.dx[d][p] = 0;
    timeIt(shape, "move", n, rounds, [&]
    {
        for (Index p = 0; p < n; ++p)
        {
            Real x[3];
            if (advancePoint(L, periodic, false, P, p, x) == 0) storePosition(L, periodic, P, p, x);
        }
    });
    timeIt(shape, "g2p+move", n, rounds, [&]
    {
        for (Index p = 0; p < n; ++p)
        {
            g2pPoint<K, D, false>(L, P, g, 0.99, 0.0, p);
            Real x[3];
            if (advancePoint(L, periodic, false, P, p, x) == 0) storePosition(L, periodic, P, p, x);
        }
    });
    // Precomputed weights: what storing every point's stencil costs (to be
    // read back by P2G and G2P), against "stencil", computing it
    std::vector<Stencil<K, D>> cache(n);
    timeIt(shape, "store", n, rounds, [&]
    {
        for (Index p = 0; p < n; ++p) cache[p].compute(L, P.x[0][p], P.x[1][p], P.x[2][p]);
    });
}

void triad(int rounds)
{
    const std::size_t n = (64u << 20)/sizeof(Real);
    std::vector<Real> a(n, 0), b(n, 1), c(n, 2);
    std::vector<double> rate;
    for (int r = 0; r < rounds; ++r)
    {
        const double t0 = cpuNs();
        for (std::size_t i = 0; i < n; ++i) a[i] = b[i] + 0.5*c[i];
        const double ns = cpuNs() - t0;
        rate.push_back(3.0*n*sizeof(Real)/ns);
    }
    sink = a[n/2];
    std::sort(rate.begin(), rate.end());
    // Bytes read and written as the code names them (no write-allocate)
    std::printf("%-18s %-14s %10.2f %10.2f   GB/s, best and median\n", "-", "triad", rate.back(), rate[rate.size()/2]);
}

} // namespace

int main(int argc, char** argv)
{
    const int n = argc > 1 ? std::atoi(argv[1]) : 32;
    const int rounds = argc > 2 ? std::atoi(argv[2]) : 7;
    double load[3] = {0, 0, 0};
    if (getloadavg(load, 3) < 0) load[0] = -1;
    std::printf("# transferLevers: %d^3 cells x 8 points, 1 thread, %d rounds\n", n, rounds);
    std::printf("# machine: %s, load average %.2f\n", bench::machine().c_str(), load[0]);
    std::printf("%-18s %-14s %10s %10s\n", "shape", "part", "min ns/pt", "median");
    Block b = makeBlock(n);
    levers<LinearHat>("linearHat", b, rounds);
    levers<QuadraticBSpline>("quadraticBSpline", b, rounds);
    levers<CubicBSpline>("cubicBSpline", b, rounds);
    triad(rounds);
    return 0;
}

// The point kernel bodies of kernels/*.hpp as functors of one point, for
// the launchers that run them one thread (or one loop iteration) per point:
// the host-assisted cuda step (deviceStep.cu) and the resident step
// (residentStepImpl.hpp, on CUDA and its host stand-in). Functors rather
// than lambdas: a device lambda may not sit in the generic lambdas of the
// dispatch. Also the dispatch of the shape function and dimension as types.
#pragma once
#include "../kernels/g2p.hpp"
#include "../kernels/p2g.hpp"
#include "../kernels/stressPoint.hpp"
#include <type_traits>

namespace mpm::bodies {

// P2G with the launcher's add (atomic, warp-reduced, or plain)
template<class K, int D, bool MassMomentum, bool Force, bool Apic, class Add>
struct P2g
{
    Lattice L; PointView P; GridView g; const Real* invRho0; bool grainVolume;
    MPM_HOST_DEVICE void operator()(Index p) const
    {
        p2gPoint<K, D, MassMomentum, Force, Apic>(L, P, g, invRho0, grainVolume, p, Add{});
    }
};

template<class K, int D, bool Apic>
struct G2p
{
    Lattice L; PointView P; GridView g; Real flipRatio; Real dt;
    MPM_HOST_DEVICE void operator()(Index p) const { g2pPoint<K, D, Apic>(L, P, g, flipRatio, dt, p); }
};

template<class K, int D>
struct Gradient
{
    Lattice L; PointView P; Real* v[3];
    MPM_HOST_DEVICE void operator()(Index p) const
    {
        const Real* const w[3] = {v[0], v[1], v[2]};
        gradientPoint<K, D>(L, P, w, p);
    }
};

// The stress update, reducing the lowest index of a point that went
// non-finite (atomic min) and the number of inverted points (count) with
// the launcher's Atomics (min, count)
template<class Atomics>
struct Stress
{
    PointView P; const LawParams* laws; Real dt;
    unsigned long long* firstBad; unsigned long long* inverted;
    MPM_HOST_DEVICE void operator()(Index p) const
    {
        const StressPointStatus r = stressPoint(P, laws, dt, p);
        if (r == StressPointStatus::bad) Atomics::min(firstBad, (unsigned long long)p);
        else if (r == StressPointStatus::inverted) Atomics::count(inverted);
    }
};

// Shape function and number of solved directions as types, like
// SystemState::dispatch
template<class Fn>
void dispatchKD(ShapeKind shape, int dim, Fn&& f)
{
    dispatchShape(shape, [&](auto k)
    {
        switch (dim)
        {
            case 1: f(k, std::integral_constant<int, 1>{}); break;
            case 2: f(k, std::integral_constant<int, 2>{}); break;
            default: f(k, std::integral_constant<int, 3>{}); break;
        }
    });
}

template<class F>
void pick(bool x, F&& f) { if (x) f(std::true_type{}); else f(std::false_type{}); }

} // namespace mpm::bodies

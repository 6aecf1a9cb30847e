// 1D B-spline family kernels on a unit-spaced lattice.
//
// Nodes sit at integer lattice coordinates xi = 0, 1, 2, ...  A point at
// lattice coordinate xi touches `width` consecutive nodes starting at `base`.
// Weights are tensor products of these 1D kernels in each solved direction,
// so one kernel body serves 1D, 2D and 3D (unsolved directions use width 1,
// weight 1, gradient 0).
//
// Gradients are returned per unit lattice spacing: divide by h.
#pragma once
#include "../types.hpp"
#include "../common/hostDevice.hpp"
#include <cmath>
#include <string>

namespace mpm {

enum class ShapeKind { linearHat = 0, quadraticBSpline = 1, cubicBSpline = 2 };

// Linear hat (tent) function: C0, support radius 1.
struct LinearHat
{
    static constexpr int width = 2;
    static constexpr Real radius = 1.0;
    // The first node of the stencil at xi (eval's base), alone
    MPM_HOST_DEVICE static inline Index baseOf(Real xi) { return static_cast<Index>(std::floor(xi)); }
    MPM_HOST_DEVICE static inline void eval(Real xi, Index& base, Real* w, Real* dw)
    {
        const Real fb = std::floor(xi);
        base = static_cast<Index>(fb);
        const Real f = xi - fb;
        w[0] = 1.0 - f;  w[1] = f;
        dw[0] = -1.0;    dw[1] = 1.0;
    }
};

// Quadratic B-spline: C1, support radius 1.5.
struct QuadraticBSpline
{
    static constexpr int width = 3;
    static constexpr Real radius = 1.5;
    MPM_HOST_DEVICE static inline Index baseOf(Real xi) { return static_cast<Index>(std::floor(xi + 0.5) - 1.0); }
    MPM_HOST_DEVICE static inline void eval(Real xi, Index& base, Real* w, Real* dw)
    {
        const Real fb = std::floor(xi + 0.5) - 1.0;
        base = static_cast<Index>(fb);
        const Real f = xi - fb;                 // in [0.5, 1.5)
        const Real a = 1.5 - f, b = f - 1.0, c = f - 0.5;
        w[0] = 0.5*a*a;  w[1] = 0.75 - b*b;  w[2] = 0.5*c*c;
        dw[0] = -a;      dw[1] = -2.0*b;     dw[2] = c;
    }
};

// Cubic B-spline: C2, support radius 2.
struct CubicBSpline
{
    static constexpr int width = 4;
    static constexpr Real radius = 2.0;
    MPM_HOST_DEVICE static inline Index baseOf(Real xi) { return static_cast<Index>(std::floor(xi) - 1.0); }
    MPM_HOST_DEVICE static inline void eval(Real xi, Index& base, Real* w, Real* dw)
    {
        const Real fb = std::floor(xi) - 1.0;
        base = static_cast<Index>(fb);
        const Real t = xi - fb - 1.0;           // in [0, 1): offset past node base+1
        const Real t2 = t*t, t3 = t2*t;
        const Real s = 1.0 - t;
        w[0] = s*s*s/6.0;
        w[1] = (3.0*t3 - 6.0*t2 + 4.0)/6.0;
        w[2] = (-3.0*t3 + 3.0*t2 + 3.0*t + 1.0)/6.0;
        w[3] = t3/6.0;
        dw[0] = -0.5*s*s;
        dw[1] = 1.5*t2 - 2.0*t;
        dw[2] = -1.5*t2 + t + 0.5;
        dw[3] = 0.5*t2;
    }
};

// Value of the 1D kernel centred at a node, at signed distance d (lattice
// units). Used by the stability analysis and by tests, not by hot loops.
Real kernelValue(ShapeKind kind, Real d);
Real kernelGradient(ShapeKind kind, Real d);
Real kernelRadius(ShapeKind kind);
int kernelWidth(ShapeKind kind);

// Names as they appear in dictionaries; parse returns false on unknown name.
const char* shapeName(ShapeKind kind);
bool parseShape(const std::string& name, ShapeKind& kind);
const char* validShapeNames();   // "linearHat quadraticBSpline cubicBSpline"

// Call f.template operator()<Kernel>() with the kernel type for `kind`, so
// kernels are compiled per shape function with no run-time branching inside.
template<class Visitor>
inline decltype(auto) dispatchShape(ShapeKind kind, Visitor&& f)
{
    switch (kind)
    {
        case ShapeKind::linearHat: return f(LinearHat{});
        case ShapeKind::quadraticBSpline: return f(QuadraticBSpline{});
        default: return f(CubicBSpline{});
    }
}

} // namespace mpm

#include "shapeFunctions.hpp"

namespace mpm {

namespace {

template<class K>
void evalAt(Real d, Real& value, Real& grad)
{
    // A node at lattice 0 and a point at xi = d: find the node's slot.
    Index base; Real w[K::width], dw[K::width];
    K::eval(d, base, w, dw);
    value = 0; grad = 0;
    const Index slot = -base;
    if (slot >= 0 && slot < K::width) { value = w[slot]; grad = dw[slot]; }
}

} // namespace

Real kernelValue(ShapeKind kind, Real d)
{
    Real v, g;
    dispatchShape(kind, [&](auto k) { evalAt<decltype(k)>(d, v, g); });
    return v;
}

Real kernelGradient(ShapeKind kind, Real d)
{
    Real v, g;
    dispatchShape(kind, [&](auto k) { evalAt<decltype(k)>(d, v, g); });
    return g;
}

Real kernelRadius(ShapeKind kind)
{
    return dispatchShape(kind, [](auto k) { return decltype(k)::radius; });
}

int kernelWidth(ShapeKind kind)
{
    return dispatchShape(kind, [](auto k) { return decltype(k)::width; });
}

const char* shapeName(ShapeKind kind)
{
    switch (kind)
    {
        case ShapeKind::linearHat: return "linearHat";
        case ShapeKind::quadraticBSpline: return "quadraticBSpline";
        default: return "cubicBSpline";
    }
}

bool parseShape(const std::string& name, ShapeKind& kind)
{
    if (name == "linearHat" || name == "LH") { kind = ShapeKind::linearHat; return true; }
    if (name == "quadraticBSpline" || name == "QBS") { kind = ShapeKind::quadraticBSpline; return true; }
    if (name == "cubicBSpline" || name == "CBS") { kind = ShapeKind::cubicBSpline; return true; }
    return false;
}

const char* validShapeNames()
{
    return "linearHat quadraticBSpline cubicBSpline (or LH QBS CBS)";
}

} // namespace mpm

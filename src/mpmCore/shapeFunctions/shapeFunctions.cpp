#include "shapeFunctions.hpp"
#include "../common/enumTable.hpp"

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

namespace
{
// LH, QBS, CBS: accepted aliases
const auto shapes = enumTable<ShapeKind>
({{ShapeKind::linearHat, "linearHat"}, {ShapeKind::quadraticBSpline, "quadraticBSpline"},
  {ShapeKind::cubicBSpline, "cubicBSpline"}, {ShapeKind::linearHat, "LH"},
  {ShapeKind::quadraticBSpline, "QBS"}, {ShapeKind::cubicBSpline, "CBS"}});
const std::string shapeList = shapes.validNames() + " (or LH QBS CBS)";
}

const char* shapeName(ShapeKind kind) { return shapes.name(kind); }
bool parseShape(const std::string& name, ShapeKind& kind) { return shapes.parse(name, kind); }
const char* validShapeNames() { return shapeList.c_str(); }

} // namespace mpm

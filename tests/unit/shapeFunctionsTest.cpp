// Shape functions: partition of unity, linear completeness and zero-sum
// gradients at random points, for every kernel.
#include "shapeFunctions/shapeFunctions.hpp"
#include <gtest/gtest.h>
#include <random>

using namespace mpm;

namespace {

template<class K>
void checkKernel()
{
    std::mt19937 rng(42);
    std::uniform_real_distribution<Real> u(-5.0, 5.0);
    for (int s = 0; s < 10000; ++s)
    {
        const Real xi = u(rng);
        Index base; Real w[K::width], dw[K::width];
        K::eval(xi, base, w, dw);
        Real sw = 0, sdw = 0, sx = 0, sxdw = 0;
        for (int a = 0; a < K::width; ++a)
        {
            const Real xn = Real(base + a);
            EXPECT_GE(w[a], -1e-15);
            EXPECT_LE(std::abs(xi - xn), K::radius + 1e-12);
            sw += w[a]; sdw += dw[a]; sx += w[a]*xn; sxdw += dw[a]*xn;
        }
        EXPECT_NEAR(sw, 1.0, 1e-13) << "partition of unity at " << xi;
        EXPECT_NEAR(sdw, 0.0, 1e-13) << "gradients sum to zero at " << xi;
        EXPECT_NEAR(sx, xi, 1e-12) << "linear completeness at " << xi;
        EXPECT_NEAR(sxdw, 1.0, 1e-12) << "gradient of x is 1 at " << xi;
    }
}

} // namespace

TEST(ShapeFunctions, LinearHat) { checkKernel<LinearHat>(); }
TEST(ShapeFunctions, QuadraticBSpline) { checkKernel<QuadraticBSpline>(); }
TEST(ShapeFunctions, CubicBSpline) { checkKernel<CubicBSpline>(); }

TEST(ShapeFunctions, GradientMatchesFiniteDifference)
{
    for (auto kind : {ShapeKind::linearHat, ShapeKind::quadraticBSpline, ShapeKind::cubicBSpline})
    {
        for (Real d = -2.3; d < 2.3; d += 0.0173)
        {
            const Real e = 1e-6;
            // Skip the kinks of the linear hat.
            if (kind == ShapeKind::linearHat && (std::abs(d) < 2*e || std::abs(std::abs(d) - 1) < 2*e)) continue;
            const Real fd = (kernelValue(kind, d + e) - kernelValue(kind, d - e))/(2*e);
            EXPECT_NEAR(kernelGradient(kind, d), fd, 1e-6) << shapeName(kind) << " at " << d;
        }
    }
}

TEST(ShapeFunctions, KnownValues)
{
    EXPECT_NEAR(kernelValue(ShapeKind::linearHat, 0.25), 0.75, 1e-15);
    EXPECT_NEAR(kernelValue(ShapeKind::quadraticBSpline, 0.0), 0.75, 1e-15);
    EXPECT_NEAR(kernelValue(ShapeKind::quadraticBSpline, 1.0), 0.125, 1e-15);
    EXPECT_NEAR(kernelValue(ShapeKind::cubicBSpline, 0.0), 2.0/3.0, 1e-15);
    EXPECT_NEAR(kernelValue(ShapeKind::cubicBSpline, 1.0), 1.0/6.0, 1e-15);
    EXPECT_NEAR(kernelValue(ShapeKind::cubicBSpline, 2.5), 0.0, 1e-15);
    ShapeKind k;
    EXPECT_TRUE(parseShape("CBS", k));
    EXPECT_EQ(k, ShapeKind::cubicBSpline);
    EXPECT_FALSE(parseShape("cubic", k));
}

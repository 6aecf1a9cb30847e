// Fluid coupling in the nodal update: stiff drag (relaxation time / dt =
// 1e-3) is stable and gives the analytic equilibrium slip
//   v = (m g + F) / K   (gravity, buoyancy F, drag K (U - v) in balance),
// and the time integral of the solid velocity is accumulated for the fluid.
#include "testHelpers.hpp"
#include <gtest/gtest.h>

using namespace mpm;
using namespace mpm::test;

namespace
{

// A periodic box of n^3 cells (h = 0.1) filled with a uniform suspension:
// 8 points per cell, solid fraction alphaS, grain density rhoS, points at
// rest, stress-free; the coupling arrays sized and zero.
void uniformSuspension(MpmSystem& s, int n, const StepOptions& o, Real alphaS, Real rhoS)
{
    BoundarySpec b;
    b.conditions = {WallCondition{WallType::periodic, 0}};
    s.setup(box(n, n, n, 0.1), b, o);
    s.materials().push_back(std::make_unique<NoStress>());
    const Real h = 0.1, vol = alphaS*h*h*h/8;
    for (int k = 0; k < 2*n; ++k)
    for (int j = 0; j < 2*n; ++j)
    for (int i = 0; i < 2*n; ++i)
    {
        s.particles().add({(i + 0.5)*h/2, (j + 0.5)*h/2, (k + 0.5)*h/2}, {0, 0, 0}, rhoS*vol, vol, 0);
    }
    s.coupling().resize(s.lattice().nNodes);
}

} // namespace

TEST(FluidCoupling, StiffDragReachesEquilibriumSlip)
{
    for (auto shape : {ShapeKind::linearHat, ShapeKind::cubicBSpline})
    for (Real alpha : {0.0, 1.0})
    for (auto mass : {MassMatrix::lumped, MassMatrix::consistent})
    {
        MpmSystem s;
        StepOptions o;
        o.shape = shape; o.flipRatio = alpha; o.massMatrix = mass;
        o.gravity = {0, 0, -9.81};
        // Grains of density 2500 in water (1000), solid fraction 0.3
        const Real h = 0.1, cellV = h*h*h, alphaS = 0.3, rhoS = 2500, rhoF = 1000;
        uniformSuspension(s, 8, o, alphaS, rhoS);
        const Lattice& L = s.lattice();
        const Real m = rhoS*alphaS*cellV;             // solid mass per node
        const Real dt = 1e-3, tau = 1e-3*dt;          // relaxation time / dt = 1e-3
        const Real Kval = m/tau;                      // K = beta V, tau = m/K
        auto& c = s.coupling();
        for (int kk = 0; kk < 8; ++kk)
        for (int jj = 0; jj < 8; ++jj)
        for (int ii = 0; ii < 8; ++ii)
        {
            const Index I = L.realNode(ii, jj, kk);
            c.K[I] = Kval;
            c.F[2][I] = rhoF*9.81;                    // buoyancy per solid volume: -rho_f g
        }
        for (int n = 0; n < 20; ++n) s.step(dt);
        const Real vEq = (m*(-9.81) + alphaS*cellV*rhoF*9.81)/Kval;
        for (Index p = 0; p < s.particles().size(); ++p)
        {
            ASSERT_NEAR(s.particles().v[2][p], vEq, 1e-9*std::abs(vEq)) << shapeName(shape) << " alpha " << alpha;
            ASSERT_NEAR(s.particles().v[0][p], 0.0, 1e-15);
        }
        EXPECT_NEAR(c.time, 20*dt, 1e-15);
        const Index I = L.realNode(3, 3, 3);
        // Implicit drag: the first step already reaches the equilibrium to
        // O(tau/dt), so the time average is the equilibrium to ~1e-4.
        EXPECT_NEAR(c.velocityIntegral[2][I]/c.time, vEq, 1e-3*std::abs(vEq));
    }
}


// Virtual mass: grains (rho_s 2500) in water (1000) that accelerates
// uniformly at a_f, no drag, no gravity, buoyancy F = rho_f a_f per solid
// volume (-grad p of the accelerating fluid). Then
//   (rho_s + Cvm rho_f) a_s = rho_f a_f + Cvm rho_f a_f
// so a_s/a_f = 1500/3000 = 0.5 with Cvm = 0.5 (0.4 without virtual mass).
// Exact for the implicit update at any dt: the velocity grows linearly.
TEST(FluidCoupling, VirtualMassAccelerationRatio)
{
    for (Real Cvm : {0.0, 0.5, 2.0})
    for (auto mass : {MassMatrix::lumped, MassMatrix::consistent})
    {
        MpmSystem s;
        StepOptions o;
        o.shape = ShapeKind::cubicBSpline; o.flipRatio = 1.0; o.massMatrix = mass;
        o.gravity = {0, 0, 0};
        const Real rhoS = 2500, rhoF = 1000, af = 2.0;
        uniformSuspension(s, 4, o, 0.3, rhoS);
        const Lattice& L = s.lattice();
        auto& c = s.coupling();
        for (int d = 0; d < 3; ++d) c.fluidAcceleration[d].assign(L.nNodes, 0.0);
        c.addedMassDensity = Cvm*rhoF;
        for (Index I = 0; I < L.nNodes; ++I)
        {
            c.F[1][I] = rhoF*af;
            c.fluidAcceleration[1][I] = af;
        }
        const Real dt = 1e-3;
        for (int n = 0; n < 10; ++n) s.step(dt);
        const Real expected = (1 + Cvm)*rhoF/(rhoS + Cvm*rhoF)*af*10*dt;
        for (Index p = 0; p < s.particles().size(); ++p)
        {
            ASSERT_NEAR(s.particles().v[1][p], expected, 1e-12) << "Cvm " << Cvm;
            ASSERT_NEAR(s.particles().v[0][p], 0.0, 1e-15);
        }
    }
}

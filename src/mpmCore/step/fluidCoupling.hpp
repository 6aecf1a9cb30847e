// The node arrays through which a fluid exchanges momentum with the points
// (filled by the OpenFOAM layer's fluidCoupling, used by the nodal update).
#pragma once
#include "../types.hpp"
#include <array>
#include <vector>

namespace mpm {

// Momentum exchange with a fluid, per node (each real node is a fluid
// cell). The nodal update is implicit in the solid velocity v:
//   (m + dt K) v_new = p + dt (f + V_s F + K U)
// with V_s the node's solid volume (sum N V_p), so F is a force per unit
// solid volume (buoyancy: -rho_f grad p) that follows the material.
// so stiff drag (relaxation time << dt) stays stable and relaxes v to the
// fluid velocity plus the correct equilibrium slip. Empty K: no coupling,
// nothing is computed. The step also integrates v_new over time, for the
// fluid's drag source (the solid velocity averaged over the sub-cycles).
struct FluidCoupling
{
    std::vector<Real> K;                      // beta V_cell [kg/s], padded nodes
    std::array<std::vector<Real>, 3> U;       // fluid velocity at the nodes
    std::array<std::vector<Real>, 3> F;       // force per solid volume [N/m^3]
    std::array<std::vector<Real>, 3> velocityIntegral;  // sum dt v_new
    Real time = 0;                            // sum dt
    // Virtual mass (optional; 0: none, nothing is computed): the grains
    // carry added mass Cvm rho_f V_s and receive Cvm rho_f V_s a_f, with
    // a_f the fluid acceleration DU/Dt at the nodes, so the update becomes
    // (m + M_a + dt K) v = p + M_a v_old + dt (f + V_s F + K U + M_a a_f).
    Real addedMassDensity = 0;                // Cvm rho_f [kg/m^3]
    std::array<std::vector<Real>, 3> fluidAcceleration;

    // MPM_NO_FLUID_COUPLING compiles the step without the coupling terms
    // (benchmarks/effectsCost: what the hooks cost a pure-MPM run)
#ifdef MPM_NO_FLUID_COUPLING
    static constexpr bool active() { return false; }
#else
    bool active() const { return !K.empty(); }
#endif
    void resetIntegral();
    // Sizes the arrays to nNodes padded nodes, all zero (no drag, force or
    // fluid velocity yet); the added mass stays off, its array empty
    void resize(Index nNodes);
};

} // namespace mpm

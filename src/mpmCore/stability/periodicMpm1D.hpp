// Direct particle-grid loop of the same 1D MPM step the Fourier symbol
// describes, on a periodic grid of `cells` cells with physical h, rho, nu, E.
// It exists to verify the symbol independently: it uses the kernels' own
// eval() stencils, real arithmetic, and an explicit (dense) consistent mass
// solve, with no Fourier algebra at all.
#pragma once
#include "stabilitySetup.hpp"

namespace mpm {
namespace stability {

struct PhysicalParameters
{
    Real h = 1.0;     // cell size
    Real rho = 1.0;   // density
    Real nu = 1.0;    // viscosity (diffusion model)
    Real E = 1.0;     // Young's modulus (wave model)
};

class PeriodicMpm1D
{
public:
    PeriodicMpm1D(const AnalysisSetup&, int cells, const PhysicalParameters& = {});

    int cells() const { return cells_; }
    int points() const { return cells_*npc_; }
    // dt for the given Fo (diffusion) or CFL (wave).
    Real timeStep(Real number) const;

    // One explicit step; point index p = cell*npc + l. sigma is the point
    // stress (wave model state); the diffusion model ignores it.
    void step(std::vector<Real>& v, std::vector<Real>& sigma, Real dt) const;

    // Symbol measured by stepping Fourier-mode states of grid wavenumber
    // theta = 2 pi q / cells (real and imaginary parts run separately).
    // Same scaling as amplificationSymbol (stress divided by rho c).
    // cellSpread (optional) = largest difference between the matrices read
    // from different cells: ~1e-15 confirms the block-circulant structure.
    ComplexMatrix measureSymbol(int q, Real number, Real* cellSpread = nullptr) const;

    // Dense row-major matrix of one diffusion step on all point velocities.
    std::vector<Real> stepMatrix(Real number) const;

private:
    AnalysisSetup setup_;
    int cells_, npc_, width_;
    PhysicalParameters par_;
    Real pointMass_, pointVolume_;
    std::vector<Index> node_;      // points x width: periodic node indices
    std::vector<Real> w_, grad_;   // weights and physical gradients dN/dx
    std::vector<Real> lumpedMass_; // per node
    std::vector<Real> massInverse_;// dense cells x cells (consistent mass only)

    void solveMass(std::vector<Real>& rhs) const;                  // rhs <- M^-1 rhs
    std::vector<Real> pointsToGrid(const std::vector<Real>& v) const; // M^-1 sum m N v
    std::vector<Real> gradientAtPoints(const std::vector<Real>& vI) const;
    std::vector<Real> gridForce(const std::vector<Real>& sigma) const; // M^-1 f
    void gridToPoints(std::vector<Real>& v, const std::vector<Real>& vOld,
                      const std::vector<Real>& vNew) const;
};

} // namespace stability
} // namespace mpm

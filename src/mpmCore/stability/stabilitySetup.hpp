// Configuration of the 1D von Neumann (Fourier) stability analysis of the
// discrete MPM velocity update (see docs/stabilityAnalysis.md).
//
// Setting: periodic 1D grid, spacing h, nodes at integer lattice coordinates;
// every cell holds the same set of material points at lattice offsets
// `offsets` in [0,1) from its left node; equal constant point masses
// m = rho h / npc and volumes V = h / npc; frozen positions; no body force.
#pragma once
#include "../types.hpp"
#include "../shapeFunctions/shapeFunctions.hpp"
#include "../step/stepOptions.hpp"
#include <complex>
#include <string>
#include <vector>

namespace mpm {
namespace stability {

using Complex = std::complex<Real>;

// diffusion: rho Dv/Dt = d/dx(nu dv/dx), parameter Fo = nu dt/(rho h^2)
// wave:      rho v' = d sigma/dx, sigma' = E dv/dx, parameter CFL = c dt/h
// The mass matrix and the stress-update order are the step's own
// (step/stepOptions.hpp); the order matters to the wave model only (the
// diffusion model's stress is an instantaneous function of the P2G grid
// velocity).
enum class Model { diffusion, wave };

struct AnalysisSetup   // (not "Setup": GoogleTest reserves Test::Setup)
{
    Model model = Model::diffusion;
    ShapeKind shape = ShapeKind::linearHat;
    Real alpha = 0.0;                      // FLIP fraction: 0 = PIC, 1 = FLIP
    MassMatrix mass = MassMatrix::lumped;
    StressUpdate scheme = StressUpdate::USL;
    std::vector<Real> offsets{0.5};        // point offsets per cell, lattice units

    int pointsPerCell() const { return static_cast<int>(offsets.size()); }
    // Size of the per-mode amplification symbol: one state slot per point
    // for diffusion (v), two for the wave (v, sigma).
    int stateSize() const { return (model == Model::wave ? 2 : 1)*pointsPerCell(); }
};

// Small dense row-major complex matrix, so the public headers need no Eigen.
struct ComplexMatrix
{
    int rows = 0, cols = 0;
    std::vector<Complex> data;

    ComplexMatrix() = default;
    ComplexMatrix(int r, int c) : rows(r), cols(c), data(std::size_t(r)*c) {}
    Complex& operator()(int r, int c) { return data[std::size_t(r)*cols + c]; }
    const Complex& operator()(int r, int c) const { return data[std::size_t(r)*cols + c]; }
};

const char* modelName(Model);
bool parseModel(const std::string&, Model&);
// Short label such as "CBS" used in tables and CSV files.
const char* shapeShortName(ShapeKind);
// One-line description: "diffusion LH alpha=0 lumped offsets=0.5".
std::string describe(const AnalysisSetup&);

} // namespace stability
} // namespace mpm

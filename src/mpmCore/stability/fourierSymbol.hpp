// Fourier symbol A(theta) of one explicit MPM step on the periodic 1D lattice.
//
// With the same points in every cell the one-step map is block-circulant, so
// a grid Fourier mode theta = k h in (-pi, pi] decouples into a small matrix
// of size npc (diffusion, state v_p) or 2 npc (wave, state v_p and
// s_p = sigma_p/(rho c)). Point amplitudes are taken relative to the phase
// exp(i theta xi_p) at the point's own lattice position xi_p = j + offset, so
// with one point per cell A(theta) is exactly G_MPM(k) = sum_m A_lm
// exp(ik(x_m - x_l)). Everything is dimensionless (h = rho = 1, dt = Fo or CFL).
#pragma once
#include "stabilitySetup.hpp"

namespace mpm {
namespace stability {

// Per-mode transfer symbols of one cell's points (lattice units):
//   a_l    = sum_n N (o_l - n) exp(-i theta (o_l - n))   (grid -> point value)
//   beta_l = sum_n N'(o_l - n) exp(-i theta (o_l - n))   (grid -> point gradient * h)
// and mu = rho h / M(theta): 1 for lumped mass, npc/|a|^2 for consistent mass.
struct TransferSymbols
{
    std::vector<Complex> a, beta;
    Real mu = 1.0;
    bool singular = false;   // consistent mass matrix has a zero at this theta
};

TransferSymbols transferSymbols(const AnalysisSetup&, Real theta);

// Amplification symbol for parameter `number` (Fo for diffusion, CFL for the
// wave). If the consistent mass symbol vanishes at theta the entries are NaN
// and *singular (if given) is set.
ComplexMatrix amplificationSymbol(const AnalysisSetup&, Real theta, Real number, bool* singular = nullptr);

std::vector<Complex> eigenvalues(const ComplexMatrix&);

// Largest |eigenvalue| of A(theta); +inf where the mass symbol is singular.
Real spectralRadius(const AnalysisSetup&, Real theta, Real number);

// max over theta_j = pi j / thetaIntervals, j = 0..thetaIntervals. A(-theta)
// is the complex conjugate of A(theta), so [0, pi] covers every mode, and the
// npc (or 2 npc) eigenvalues at each theta cover the point-lattice aliases
// theta + 2 pi r as well.
Real maxSpectralRadius(const AnalysisSetup&, Real number, int thetaIntervals = 360);

// Result for one physical wavenumber.
struct ModeResult
{
    Real kh = 0;            // physical k h (may exceed pi with several points per cell)
    Real theta = 0;         // kh folded into the grid zone (-pi, pi]
    int branch = 0;         // 0 diffusion; +1 right-going, -1 left-going wave
    Complex G;              // eigenvalue whose eigenvector best matches the sampled physical mode
    Complex exact;          // exact one-step amplification of that mode
    Real match = 1;         // |cos| between that eigenvector and the physical mode
    Real spectralRadius = 0;// max |eigenvalue| of A(theta): decides stability
    bool singular = false;
};

// Exact one-step factor: exp(-Fo kh^2) (diffusion) or exp(-i branch CFL kh) (wave).
Complex exactAmplification(const AnalysisSetup&, Real kh, Real number, int branch);

// One result for diffusion, two (branch +1, -1) for the wave.
std::vector<ModeResult> analyseMode(const AnalysisSetup&, Real kh, Real number);

} // namespace stability
} // namespace mpm

// Global (all points of a periodic grid) matrix form of the diffusion step,
// written with the transfer operators used in the literature:
//   T_{P->I} = M^-1 C,  C_Ip = m_p N_I(x_p)      (P2G velocity)
//   T_{I->P} = N^T,     (N^T)_pI = N_I(x_p)      (G2P interpolation)
//   G_{I->P} = D^T,     (D^T)_pI = dN_I/dx(x_p)  (point velocity gradient)
//   G_{P->I} = M^-1 D V, so dt M^-1 f = -Fo G_{P->I} sigma/nu (h = rho = 1)
//   Theta    = -Fo G_{P->I} G_{I->P}              (grid diffusion operator)
// `derived` is what the algorithm actually does,
//   A = alpha (I - T_{I->P} T_{P->I}) + T_{I->P} (I + Theta) T_{P->I},
// `published` is the quoted form
//   A = alpha I + T_{I->P} Theta T_{P->I} + (1-alpha) T_{I->P} (I - Theta) T_{P->I}.
// They differ by (1 - alpha) T_{I->P} Theta T_{P->I}: only FLIP agrees.
#pragma once
#include "stabilitySetup.hpp"

namespace mpm {
namespace stability {

enum class DiffusionFormula { derived, published };

// Dense row-major (cells*npc)^2 matrix, lattice units (h = rho = nu = 1, dt = Fo).
std::vector<Real> globalDiffusionMatrix(const AnalysisSetup&, int cells, Real Fo, DiffusionFormula);

} // namespace stability
} // namespace mpm

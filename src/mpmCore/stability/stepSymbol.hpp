// One MPM step of the periodic 1D lattice applied, in Fourier space, to a
// block of basis states (Eigen columns). Shared by the pure-MPM symbol
// (fourierSymbol.cpp) and the coupled MPM-fluid symbol (coupledSymbol.cpp),
// which differ only in the nodal update: this header is internal to the
// stability sources (it needs Eigen, the public headers do not).
#pragma once
#include "fourierSymbol.hpp"
#include <Eigen/Dense>
#include <functional>

namespace mpm {
namespace stability {
namespace detail {

using Mat = Eigen::MatrixXcd;
using Vec = Eigen::VectorXcd;
using RowVec = Eigen::RowVectorXcd;

Mat toEigen(const ComplexMatrix&);
ComplexMatrix fromEigen(const Mat&);

// The nodal update of one step: the updated grid velocity from the P2G
// velocity vo and the pure-MPM update vnPure = vo + dt M^-1 f.
using NodalUpdate = std::function<RowVec(const RowVec& vo, const RowVec& vnPure)>;

struct StepResult
{
    Mat v, sigma;      // point velocities and scaled stresses after the step
    RowVec vGrid;      // grid velocity after the nodal update (coupling integral)
};

// v: npc rows, sigma: npc rows (wave) or empty (diffusion), same columns.
// `number` is Fo or CFL of this step. t must come from transferSymbols(s, theta)
// and not be singular.
StepResult mpmStep(const AnalysisSetup& s, const TransferSymbols& t, Real number,
                   const Mat& v, const Mat& sigma, const NodalUpdate& nodal);

// The P2G grid velocity row of the point velocities v.
RowVec gridVelocity(const AnalysisSetup& s, const TransferSymbols& t, const Mat& v);

} // namespace detail
} // namespace stability
} // namespace mpm

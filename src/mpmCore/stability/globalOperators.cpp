#include "globalOperators.hpp"
#include <Eigen/Dense>
#include <cmath>

namespace mpm {
namespace stability {

std::vector<Real> globalDiffusionMatrix(const AnalysisSetup& s, int cells, Real Fo, DiffusionFormula formula)
{
    using Mat = Eigen::MatrixXd;
    const int npc = s.pointsPerCell();
    const int np = cells*npc;
    const Real m = 1.0/npc, V = 1.0/npc;   // rho = h = 1

    // N(I,p) = N_I(x_p), D(I,p) = dN_I/dx(x_p), summed over periodic images.
    Mat N = Mat::Zero(cells, np), D = Mat::Zero(cells, np);
    const int reach = int(std::ceil(kernelRadius(s.shape))) + 1;
    for (int j = 0; j < cells; ++j)
        for (int l = 0; l < npc; ++l)
        {
            const int p = j*npc + l;
            const Real xi = j + s.offsets[l];
            for (int node = j - reach; node <= j + 1 + reach; ++node)
            {
                const int I = ((node % cells) + cells) % cells;
                N(I, p) += kernelValue(s.shape, xi - node);
                D(I, p) += kernelGradient(s.shape, xi - node);
            }
        }

    const Mat C = m*N;
    Mat M;
    if (s.mass == MassMatrix::lumped) M = Mat(C.rowwise().sum().asDiagonal());
    else M = m*N*N.transpose();
    const Eigen::FullPivLU<Mat> lu(M);

    const Mat TPI = lu.solve(C);
    const Mat TIP = N.transpose();
    const Mat GIP = D.transpose();
    const Mat GPI = lu.solve(V*D);
    const Mat Theta = -Fo*GPI*GIP;
    const Mat Ig = Mat::Identity(cells, cells);
    const Mat Ip = Mat::Identity(np, np);
    const Real alpha = s.alpha;

    Mat A;
    if (formula == DiffusionFormula::derived)
        A = alpha*(Ip - TIP*TPI) + TIP*(Ig + Theta)*TPI;
    else
        A = alpha*Ip + TIP*Theta*TPI + (1.0 - alpha)*TIP*(Ig - Theta)*TPI;

    std::vector<Real> out(std::size_t(np)*np);
    for (int r = 0; r < np; ++r)
        for (int c = 0; c < np; ++c) out[std::size_t(r)*np + c] = A(r, c);
    return out;
}

} // namespace stability
} // namespace mpm

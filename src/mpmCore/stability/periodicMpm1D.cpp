#include "periodicMpm1D.hpp"
#include <Eigen/Dense>
#include <cmath>

namespace mpm {
namespace stability {

namespace {
constexpr Real pi = 3.14159265358979323846;
}

PeriodicMpm1D::PeriodicMpm1D(const AnalysisSetup& s, int cells, const PhysicalParameters& par)
  : setup_(s), cells_(cells), npc_(s.pointsPerCell()), width_(kernelWidth(s.shape)), par_(par)
{
    pointMass_ = par.rho*par.h/npc_;
    pointVolume_ = par.h/npc_;
    const int np = points();
    node_.resize(std::size_t(np)*width_);
    w_.resize(node_.size());
    grad_.resize(node_.size());
    for (int j = 0; j < cells_; ++j)
        for (int l = 0; l < npc_; ++l)
        {
            const int p = j*npc_ + l;
            const Real xi = j + s.offsets[l];
            dispatchShape(s.shape, [&](auto k) {
                using K = decltype(k);
                Index base; Real w[K::width], dw[K::width];
                K::eval(xi, base, w, dw);
                for (int a = 0; a < K::width; ++a)
                {
                    node_[std::size_t(p)*width_ + a] = ((base + a) % cells_ + cells_) % cells_;
                    w_[std::size_t(p)*width_ + a] = w[a];
                    grad_[std::size_t(p)*width_ + a] = dw[a]/par.h;
                }
            });
        }

    lumpedMass_.assign(cells_, 0.0);
    for (std::size_t i = 0; i < node_.size(); ++i) lumpedMass_[node_[i]] += pointMass_*w_[i];

    if (s.mass == MassMatrix::consistent)
    {
        Eigen::MatrixXd M = Eigen::MatrixXd::Zero(cells_, cells_);
        for (int p = 0; p < np; ++p)
            for (int a = 0; a < width_; ++a)
                for (int b = 0; b < width_; ++b)
                    M(node_[p*width_ + a], node_[p*width_ + b])
                        += pointMass_*w_[p*width_ + a]*w_[p*width_ + b];
        const Eigen::MatrixXd Minv = M.fullPivLu().inverse();
        massInverse_.assign(Minv.data(), Minv.data() + Minv.size());   // symmetric: layout irrelevant
    }
}

Real PeriodicMpm1D::timeStep(Real number) const
{
    if (setup_.model == Model::diffusion) return number*par_.rho*par_.h*par_.h/par_.nu;
    return number*par_.h/std::sqrt(par_.E/par_.rho);
}

void PeriodicMpm1D::solveMass(std::vector<Real>& rhs) const
{
    if (setup_.mass == MassMatrix::lumped)
    {
        for (int I = 0; I < cells_; ++I) rhs[I] /= lumpedMass_[I];
        return;
    }
    std::vector<Real> out(cells_, 0.0);
    for (int I = 0; I < cells_; ++I)
        for (int J = 0; J < cells_; ++J) out[I] += massInverse_[std::size_t(I)*cells_ + J]*rhs[J];
    rhs = out;
}

std::vector<Real> PeriodicMpm1D::pointsToGrid(const std::vector<Real>& v) const
{
    std::vector<Real> mom(cells_, 0.0);
    for (int p = 0; p < points(); ++p)
        for (int a = 0; a < width_; ++a)
            mom[node_[p*width_ + a]] += pointMass_*w_[p*width_ + a]*v[p];
    solveMass(mom);
    return mom;
}

std::vector<Real> PeriodicMpm1D::gradientAtPoints(const std::vector<Real>& vI) const
{
    std::vector<Real> g(points(), 0.0);
    for (int p = 0; p < points(); ++p)
        for (int a = 0; a < width_; ++a) g[p] += grad_[p*width_ + a]*vI[node_[p*width_ + a]];
    return g;
}

std::vector<Real> PeriodicMpm1D::gridForce(const std::vector<Real>& sigma) const
{
    std::vector<Real> f(cells_, 0.0);
    for (int p = 0; p < points(); ++p)
        for (int a = 0; a < width_; ++a)
            f[node_[p*width_ + a]] -= pointVolume_*sigma[p]*grad_[p*width_ + a];
    solveMass(f);
    return f;
}

void PeriodicMpm1D::gridToPoints(std::vector<Real>& v, const std::vector<Real>& vOld,
                                 const std::vector<Real>& vNew) const
{
    const Real alpha = setup_.alpha;
    for (int p = 0; p < points(); ++p)
    {
        Real flip = v[p], pic = 0;
        for (int a = 0; a < width_; ++a)
        {
            const int I = int(node_[p*width_ + a]);
            flip += w_[p*width_ + a]*(vNew[I] - vOld[I]);
            pic += w_[p*width_ + a]*vNew[I];
        }
        v[p] = alpha*flip + (1.0 - alpha)*pic;
    }
}

void PeriodicMpm1D::step(std::vector<Real>& v, std::vector<Real>& sigma, Real dt) const
{
    const std::vector<Real> vOld = pointsToGrid(v);
    std::vector<Real> vNew = vOld;
    auto advanceGrid = [&](const std::vector<Real>& stress) {
        const std::vector<Real> a = gridForce(stress);
        for (int I = 0; I < cells_; ++I) vNew[I] = vOld[I] + dt*a[I];
    };
    auto updateStress = [&](const std::vector<Real>& vI) {
        const std::vector<Real> g = gradientAtPoints(vI);
        for (int p = 0; p < points(); ++p) sigma[p] += dt*par_.E*g[p];
    };

    if (setup_.model == Model::diffusion)
    {
        std::vector<Real> stress = gradientAtPoints(vOld);
        for (Real& x : stress) x *= par_.nu;
        advanceGrid(stress);
        gridToPoints(v, vOld, vNew);
        return;
    }
    switch (setup_.scheme)
    {
        case StressUpdate::USF:
            updateStress(vOld);
            advanceGrid(sigma);
            gridToPoints(v, vOld, vNew);
            break;
        case StressUpdate::USL:
            advanceGrid(sigma);
            gridToPoints(v, vOld, vNew);
            updateStress(vNew);
            break;
        case StressUpdate::MUSL:
            advanceGrid(sigma);
            gridToPoints(v, vOld, vNew);
            updateStress(pointsToGrid(v));
            break;
    }
}

ComplexMatrix PeriodicMpm1D::measureSymbol(int q, Real number, Real* cellSpread) const
{
    const int K = setup_.stateSize();
    const Real impedance = std::sqrt(par_.E*par_.rho);   // rho c
    const Real theta = 2*pi*q/cells_;
    const Real dt = timeStep(number);
    auto phase = [&](int p) { return std::polar(1.0, theta*(p/npc_ + setup_.offsets[p % npc_])); };

    ComplexMatrix A(K, K);
    Real spread = 0;
    for (int col = 0; col < K; ++col)
    {
        const int lc = col % npc_;
        const bool stressColumn = col >= npc_;
        // Run the real and imaginary parts of the complex initial mode.
        std::vector<Complex> out(std::size_t(points())*2, Complex(0));
        for (int part = 0; part < 2; ++part)
        {
            std::vector<Real> v(points(), 0.0), sigma(points(), 0.0);
            for (int j = 0; j < cells_; ++j)
            {
                const int p = j*npc_ + lc;
                const Complex z = phase(p);
                const Real x = part == 0 ? z.real() : z.imag();
                if (stressColumn) sigma[p] = impedance*x;
                else v[p] = x;
            }
            step(v, sigma, dt);
            const Complex unit = part == 0 ? Complex(1, 0) : Complex(0, 1);
            for (int p = 0; p < points(); ++p)
            {
                out[p] += unit*v[p];
                out[points() + p] += unit*sigma[p]/impedance;
            }
        }
        for (int row = 0; row < K; ++row)
        {
            const int lr = row % npc_;
            const std::size_t block = row >= npc_ ? points() : 0;
            Complex first;
            for (int j = 0; j < cells_; ++j)
            {
                const int p = j*npc_ + lr;
                const Complex z = out[block + p]/phase(p);
                if (j == 0) first = z;
                spread = std::max(spread, std::abs(z - first));
            }
            A(row, col) = first;
        }
    }
    if (cellSpread) *cellSpread = spread;
    return A;
}

std::vector<Real> PeriodicMpm1D::stepMatrix(Real number) const
{
    const int np = points();
    const Real dt = timeStep(number);
    std::vector<Real> A(std::size_t(np)*np);
    for (int c = 0; c < np; ++c)
    {
        std::vector<Real> v(np, 0.0), sigma(np, 0.0);
        v[c] = 1.0;
        step(v, sigma, dt);
        for (int r = 0; r < np; ++r) A[std::size_t(r)*np + c] = v[r];
    }
    return A;
}

} // namespace stability
} // namespace mpm

#include "fourierSymbol.hpp"
#include "stepSymbol.hpp"
#include <cmath>
#include <limits>

namespace mpm {
namespace stability {

namespace {

using namespace detail;
constexpr Real pi = 3.14159265358979323846;
const Real nan = std::numeric_limits<Real>::quiet_NaN();

// PIC/FLIP blend of the G2P update, for vo/vn = grid velocity before/after
// the nodal update (1 x K rows, one column per basis state):
//   v_p' = alpha (v_p + a (vn - vo)) + (1 - alpha) a vn
Mat gridToPoints(Real alpha, const Mat& v, const Vec& a, const RowVec& vo, const RowVec& vn)
{
    return alpha*v + a*(alpha*(vn - vo) + (1.0 - alpha)*vn);
}

} // namespace

namespace detail {

Mat toEigen(const ComplexMatrix& m)
{
    Mat e(m.rows, m.cols);
    for (int r = 0; r < m.rows; ++r)
        for (int c = 0; c < m.cols; ++c) e(r, c) = m(r, c);
    return e;
}

ComplexMatrix fromEigen(const Mat& e)
{
    ComplexMatrix m(int(e.rows()), int(e.cols()));
    for (int r = 0; r < m.rows; ++r)
        for (int c = 0; c < m.cols; ++c) m(r, c) = e(r, c);
    return m;
}

RowVec gridVelocity(const AnalysisSetup& s, const TransferSymbols& t, const Mat& v)
{
    const int n = s.pointsPerCell();
    const Vec a = Eigen::Map<const Vec>(t.a.data(), n);
    return (t.mu/n)*a.adjoint()*v;
}

StepResult mpmStep(const AnalysisSetup& s, const TransferSymbols& t, Real number,
                   const Mat& v, const Mat& sig, const NodalUpdate& nodal)
{
    const int n = s.pointsPerCell();
    const Vec a = Eigen::Map<const Vec>(t.a.data(), n);
    const Vec beta = Eigen::Map<const Vec>(t.beta.data(), n);
    // P2G velocity: v_I = M^-1 sum_p m N_I v_p          -> vI = P v
    // grid force:   dt M^-1 f_I = -dt M^-1 sum_p V G_I sigma_p -> number * Q s
    // point gradient * dt (stress increment / rho c):   -> number * B vI
    const RowVec Q = -(t.mu/n)*beta.adjoint();
    const Vec& B = beta;
    const RowVec vo = gridVelocity(s, t, v);
    StepResult r;
    if (s.model == Model::diffusion)
    {
        const Complex gridDiffusion = number*(Q*B)(0, 0);   // Theta = -Fo mu |beta|^2 / npc
        r.vGrid = nodal(vo, (1.0 + gridDiffusion)*vo);
        r.v = gridToPoints(s.alpha, v, a, vo, r.vGrid);
        return r;
    }
    const Real lam = number;
    switch (s.scheme)
    {
        case StressUpdate::USF:
        {
            r.sigma = sig + lam*B*vo;                  // stress first, from P2G velocity
            r.vGrid = nodal(vo, vo + lam*Q*r.sigma);
            r.v = gridToPoints(s.alpha, v, a, vo, r.vGrid);
            break;
        }
        case StressUpdate::USL:
        {
            r.vGrid = nodal(vo, vo + lam*Q*sig);
            r.v = gridToPoints(s.alpha, v, a, vo, r.vGrid);
            r.sigma = sig + lam*B*r.vGrid;             // stress last, from updated grid velocity
            break;
        }
        case StressUpdate::MUSL:
        {
            r.vGrid = nodal(vo, vo + lam*Q*sig);
            r.v = gridToPoints(s.alpha, v, a, vo, r.vGrid);
            r.sigma = sig + lam*B*gridVelocity(s, t, r.v);   // re-map updated point momentum
            break;
        }
    }
    return r;
}

} // namespace detail

TransferSymbols transferSymbols(const AnalysisSetup& s, Real theta)
{
    const int n = s.pointsPerCell();
    TransferSymbols t;
    t.a.assign(n, Complex(0));
    t.beta.assign(n, Complex(0));
    const int reach = int(std::ceil(kernelRadius(s.shape))) + 1;
    for (int l = 0; l < n; ++l)
    {
        const Real o = s.offsets[l];
        // Every node n whose kernel can touch the point: the "sum over
        // lattice images" of the block-circulant operator.
        for (int node = int(std::floor(o)) - reach; node <= int(std::floor(o)) + reach; ++node)
        {
            const Real d = o - node;
            const Complex phase = std::polar(1.0, -theta*d);
            t.a[l] += kernelValue(s.shape, d)*phase;
            t.beta[l] += kernelGradient(s.shape, d)*phase;
        }
    }
    if (s.mass == MassMatrix::consistent)
    {
        // M(theta) = m sum_l |a_l|^2 with m = rho h / npc.
        Real norm2 = 0;
        for (const Complex& al : t.a) norm2 += std::norm(al);
        t.singular = norm2 < 1e-12*n;
        t.mu = t.singular ? nan : n/norm2;
    }
    return t;
}

ComplexMatrix amplificationSymbol(const AnalysisSetup& s, Real theta, Real number, bool* singular)
{
    const int n = s.pointsPerCell();
    const int K = s.stateSize();
    const TransferSymbols t = transferSymbols(s, theta);
    if (singular) *singular = t.singular;
    if (t.singular)
    {
        ComplexMatrix m(K, K);
        for (Complex& z : m.data) z = Complex(nan, nan);
        return m;
    }

    // Apply the algorithm, step by step, to every basis state at once
    // (columns), so the matrix is read off the code rather than re-derived.
    const Mat I = Mat::Identity(K, K);
    const Mat sig = s.model == Model::wave ? Mat(I.bottomRows(n)) : Mat();
    const StepResult r = mpmStep(s, t, number, I.topRows(n), sig,
                                 [](const RowVec&, const RowVec& vn) { return vn; });
    if (s.model == Model::diffusion) return fromEigen(r.v);
    Mat A(K, K);
    A.topRows(n) = r.v;
    A.bottomRows(n) = r.sigma;
    return fromEigen(A);
}

std::vector<Complex> eigenvalues(const ComplexMatrix& m)
{
    Eigen::ComplexEigenSolver<Mat> es(toEigen(m), false);
    const Vec ev = es.eigenvalues();
    return std::vector<Complex>(ev.data(), ev.data() + ev.size());
}

Real spectralRadius(const AnalysisSetup& s, Real theta, Real number)
{
    bool singular = false;
    const ComplexMatrix A = amplificationSymbol(s, theta, number, &singular);
    if (singular) return std::numeric_limits<Real>::infinity();
    if (A.rows == 1) return std::abs(A(0, 0));
    Real r = 0;
    for (const Complex& z : eigenvalues(A)) r = std::max(r, std::abs(z));
    return r;
}

Real maxSpectralRadius(const AnalysisSetup& s, Real number, int thetaIntervals)
{
    Real r = 0;
    for (int j = 0; j <= thetaIntervals; ++j)
        r = std::max(r, spectralRadius(s, pi*j/thetaIntervals, number));
    return r;
}

Complex exactAmplification(const AnalysisSetup& s, Real kh, Real number, int branch)
{
    if (s.model == Model::diffusion) return Complex(std::exp(-number*kh*kh), 0.0);
    return std::polar(1.0, -branch*number*kh);
}

std::vector<ModeResult> analyseMode(const AnalysisSetup& s, Real kh, Real number)
{
    const int n = s.pointsPerCell();
    const int K = s.stateSize();
    // Fold kh into (-pi, pi]: kh = theta + 2 pi r. Sampled at the points the
    // physical mode exp(i kh xi) has relative amplitudes u_l = exp(2 pi i r o_l).
    const Real r = std::ceil((kh - pi)/(2*pi) - 1e-12);
    const Real theta = kh - 2*pi*r;
    Vec u(n);
    for (int l = 0; l < n; ++l) u(l) = std::polar(1.0, 2*pi*r*s.offsets[l]);

    ModeResult base;
    base.kh = kh;
    base.theta = theta;
    bool singular = false;
    const ComplexMatrix Am = amplificationSymbol(s, theta, number, &singular);
    base.singular = singular;
    if (singular)
    {
        base.G = Complex(nan, nan);
        base.match = nan;
        base.spectralRadius = std::numeric_limits<Real>::infinity();
        std::vector<ModeResult> out;
        for (int b : (s.model == Model::wave ? std::vector<int>{1, -1} : std::vector<int>{0}))
        {
            ModeResult m = base;
            m.branch = b;
            m.exact = exactAmplification(s, kh, number, b);
            out.push_back(m);
        }
        return out;
    }

    Eigen::ComplexEigenSolver<Mat> es(toEigen(Am), true);
    const Vec ev = es.eigenvalues();
    const Mat W = es.eigenvectors();
    for (int i = 0; i < K; ++i) base.spectralRadius = std::max(base.spectralRadius, std::abs(ev(i)));

    // Physical mode vectors: diffusion u; wave right-going (u, -u) since
    // sigma = -rho c v for exp(i(kx - wt)), left-going (u, +u).
    auto cosine = [&](int i, int branch) {
        Vec target(K);
        if (branch == 0) target = u;
        else { target.head(n) = u; target.tail(n) = -Real(branch)*u; }
        return std::abs(W.col(i).dot(target))/(W.col(i).norm()*target.norm());
    };

    std::vector<ModeResult> out;
    if (s.model == Model::diffusion)
    {
        int best = 0;
        for (int i = 1; i < K; ++i) if (cosine(i, 0) > cosine(best, 0)) best = i;
        ModeResult m = base;
        m.G = ev(best);
        m.match = cosine(best, 0);
        m.exact = exactAmplification(s, kh, number, 0);
        out.push_back(m);
        return out;
    }
    // Wave: assign two distinct eigenvectors to the two travelling waves,
    // maximising the summed match.
    int bp = 0, bm = 1;
    Real bestSum = -1;
    for (int i = 0; i < K; ++i)
        for (int j = 0; j < K; ++j)
        {
            if (i == j) continue;
            const Real sum = cosine(i, 1) + cosine(j, -1);
            if (sum > bestSum) { bestSum = sum; bp = i; bm = j; }
        }
    for (int b : {1, -1})
    {
        const int i = (b == 1 ? bp : bm);
        ModeResult m = base;
        m.branch = b;
        m.G = ev(i);
        m.match = cosine(i, b);
        m.exact = exactAmplification(s, kh, number, b);
        out.push_back(m);
    }
    return out;
}

} // namespace stability
} // namespace mpm

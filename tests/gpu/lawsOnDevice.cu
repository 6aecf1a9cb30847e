// GPU test: the constitutive laws and the per-point stress kernel are
// written once (constitutive/lawKernels.hpp, kernels/stressPoint.hpp) and
// must give the same result on the device as on the host.
//
// 1. Every law (the six types, Drucker-Prager also with cohesion, dilatancy
//    and a contact threshold), 20000 random kinematics each: velocity
//    gradient, F_old, F_new, stress, plastic strain and solid fraction drawn
//    such that elastic, plastic (cone and apex return, mu(I) flow), tensile
//    and disconnected states all occur; the test counts them and fails if a
//    state the law has is never reached. The law parameters are the
//    LawParams of laws built by makeLaw on the host, copied to the device.
// 2. stressPoint over a PointView: 20000 points of mixed materials, the
//    whole per-point step (F update, J, solid fraction, law, checks,
//    write-back, status).
//
// Tolerance: each output must equal the host's to 1e-12 relative to the
// case's stress scale (largest |sigma| before or after the update), for F
// to the point's largest entry of F, for the volume to V0 times Hadamard's
// bound on det F, else to the value itself. (Relative to each entry of F
// and to J itself the check gave 1.9e-12 on an H200: an entry or a
// determinant that is a near-cancelling difference of terms of order one
// carries their rounding, not its own.) The compilers fuse
// multiply-adds differently (nvcc -fmad=true, g++ -ffp-contract=fast), so
// an operation may round once instead of twice: 1 ulp (1.1e-16) of an
// operand of the stress scale per operation, times the ~100 operations and
// the mild cancellations of a return map, stays below 1e-13 of the scale.
// A wrong or missing term (say the spin term dt(W sigma - sigma W), or the
// plastic correction) changes the stress by dt|L| ~ 1e-3 of the scale.
//
// Exit codes: 0 pass, 1 fail, 77 no usable GPU (ctest reports it skipped).
#include "gpuTest.cuh"
#include "constitutive/constitutiveLaw.hpp"
#include "kernels/stressPoint.hpp"
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>
#include <cuda_runtime.h>

using namespace mpm;

namespace {

constexpr Real tolerance = 1e-12;

// One law evaluation: inputs and, after the update, outputs.
struct LawCase
{
    int law;
    Real dt, solidFraction;
    Real L[9], Fold[9], Fnew[9];
    Real sigma[6];
    Real ep;
};

MPM_HOST_DEVICE void evaluate(const LawParams* laws, LawCase& c)
{
    const PointKinematics k{c.L, c.Fold, c.Fnew, c.dt, c.solidFraction};
    PointStress s{c.sigma, &c.ep};
    updateStress(laws[c.law], k, s);
}

__global__ void lawKernel(const LawParams* laws, LawCase* cases, int n)
{
    const int i = blockIdx.x*blockDim.x + threadIdx.x;
    if (i < n) evaluate(laws, cases[i]);
}

__global__ void stressPointKernel(PointView P, const LawParams* laws, Real dt, unsigned char* status)
{
    const Index p = Index(blockIdx.x)*blockDim.x + threadIdx.x;
    if (p < P.n) status[p] = static_cast<unsigned char>(stressPoint(P, laws, dt, p));
}

bool check(cudaError_t e, const char* what)
{
    if (e == cudaSuccess) return true;
    std::printf("CUDA error in %s: %s\n", what, cudaGetErrorString(e));
    return false;
}

template<class T>
T* toDevice(const std::vector<T>& h)
{
    T* d = nullptr;
    if (!check(cudaMalloc(&d, h.size()*sizeof(T)), "cudaMalloc")) return nullptr;
    cudaMemcpy(d, h.data(), h.size()*sizeof(T), cudaMemcpyHostToDevice);
    return d;
}

struct NamedLaw
{
    std::string label;
    std::unique_ptr<ConstitutiveLaw> law;
};

std::vector<NamedLaw> makeTestLaws()
{
    std::vector<NamedLaw> laws;
    auto add = [&](const char* label, const char* name, const Coefficients& c)
    {
        laws.push_back({label, makeLaw(name, c)});
    };
    add("linearElastic", "linearElastic", {{"rho", 1000}, {"E", 1e6}, {"nu", 0.3}});
    add("neoHookean", "neoHookean", {{"rho", 1000}, {"E", 1e6}, {"nu", 0.3}});
    add("newtonianFluid", "newtonianFluid", {{"rho", 1000}, {"K", 1e4}, {"gamma", 7}, {"mu", 1e-3}});
    add("druckerPrager", "druckerPrager",
        {{"rho", 1500}, {"E", 1e6}, {"nu", 0.3}, {"phi", 30}, {"c", 0}, {"psi", 0}, {"alphaContact", 0}});
    add("druckerPrager c psi alphaContact", "druckerPrager",
        {{"rho", 1500}, {"E", 1e6}, {"nu", 0.3}, {"phi", 35}, {"c", 2e3}, {"psi", 10}, {"alphaContact", 0.9}});
    add("muIRheology", "muIRheology",
        {{"rho", 1470}, {"E", 1e6}, {"nu", 0.3}, {"muS", 0.38}, {"mu2", 0.64}, {"I0", 0.279},
         {"d", 0.53e-3}, {"rhoS", 2450}, {"alphaCritical", 0.6}});
    add("dilute", "dilute", {{"rho", 1000}});
    return laws;
}

// Random kinematics and state: F_old near identity, a strain increment
// dt|L| up to 1e-2 (1e4 Pa of elastic stress), a stress of up to 2e4 Pa in
// compression or tension with a deviator up to twice the mean stress.
LawCase randomCase(int law, std::mt19937& rng)
{
    std::uniform_real_distribution<Real> u(-1, 1), u01(0, 1);
    LawCase c{};
    c.law = law;
    c.dt = 1e-3;
    for (int e = 0; e < 9; ++e)
    {
        c.L[e] = 10*u(rng);
        c.Fold[e] = (e % 4 == 0 ? 1.0 : 0.0) + 0.1*u(rng);
    }
    for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
    {
        Real s = c.Fold[3*i + j];
        for (int k = 0; k < 3; ++k) s += c.dt*c.L[3*i + k]*c.Fold[3*k + j];
        c.Fnew[3*i + j] = s;
    }
    const Real p = 2e4*(u01(rng) - 0.2);
    for (int a = 0; a < 6; ++a) c.sigma[a] = (a < 3 ? -p : 0.0) + 2*std::abs(p)*0.5*u(rng);
    c.ep = 0.1*u01(rng);
    c.solidFraction = 0.8 + 0.4*u01(rng);
    return c;
}

Real stressScale(const Real* a, const Real* b)
{
    Real s = 1e-300;
    for (int c = 0; c < 6; ++c) s = std::max(s, std::max(std::abs(a[c]), std::abs(b[c])));
    return s;
}

int testLaws(const std::vector<NamedLaw>& named, LawParams* dLaws)
{
    const int perLaw = 20000;
    std::mt19937 rng(7);
    std::vector<LawCase> in;
    for (int l = 0; l < int(named.size()); ++l)
        for (int i = 0; i < perLaw; ++i) in.push_back(randomCase(l, rng));
    LawCase* dCases = toDevice(in);
    if (!dCases) return 1;
    const int n = int(in.size());
    lawKernel<<<(n + 127)/128, 128>>>(dLaws, dCases, n);
    if (!check(cudaGetLastError(), "law kernel launch") || !check(cudaDeviceSynchronize(), "law kernel")) return 1;
    std::vector<LawCase> device(in.size());
    cudaMemcpy(device.data(), dCases, n*sizeof(LawCase), cudaMemcpyDeviceToHost);
    cudaFree(dCases);

    std::vector<LawParams> laws;
    for (const auto& l : named) laws.push_back(l.law->params());
    int failures = 0;
    for (int l = 0; l < int(named.size()); ++l)
    {
        Real worst = 0;
        int plastic = 0, stressFree = 0, elastic = 0, disconnected = 0;
        for (int i = l*perLaw; i < (l + 1)*perLaw; ++i)
        {
            LawCase host = in[i];
            evaluate(laws.data(), host);
            const Real scale = stressScale(in[i].sigma, host.sigma);
            for (int a = 0; a < 6; ++a)
                worst = std::max(worst, std::abs(host.sigma[a] - device[i].sigma[a])/scale);
            worst = std::max(worst, std::abs(host.ep - device[i].ep)/std::max(host.ep, Real(1e-300)));
            bool zero = true;
            for (int a = 0; a < 6; ++a) zero = zero && host.sigma[a] == 0;
            // stress-free: disconnected, tension (mu(I)) or the apex of a
            // cohesionless cone; plastic: a return with a stress left
            if (zero) ++stressFree;
            else if (host.ep > in[i].ep) ++plastic;
            else ++elastic;
            const LawParams& lp = laws[l];
            if (lp.type == LawType::muIRheology
             && in[i].solidFraction*lp.rho0/lp.muIRheology.rhoS < lp.muIRheology.alphaCritical) ++disconnected;
            if (lp.type == LawType::druckerPrager && in[i].solidFraction < lp.druckerPrager.alphaContact) ++disconnected;
        }
        // The states each law has must all have been exercised
        const LawType t = laws[l].type;
        const bool plasticLaw = t == LawType::druckerPrager || t == LawType::muIRheology;
        bool covered = elastic > 0 || t == LawType::dilute;
        if (plasticLaw) covered = covered && plastic > 0 && stressFree > 0;
        if (t == LawType::muIRheology || (t == LawType::druckerPrager && laws[l].druckerPrager.alphaContact > 0))
            covered = covered && disconnected > 0;
        if (t == LawType::dilute) covered = stressFree == perLaw;
        const bool ok = worst <= tolerance && covered;
        std::printf("%s %-34s %d cases (elastic %d, plastic %d, stress-free %d, of which disconnected %d), "
                    "largest relative difference host/device %.3e\n", ok ? "PASS" : "FAIL",
                    named[l].label.c_str(), perLaw, elastic, plastic, stressFree, disconnected, worst);
        failures += !ok;
    }
    return failures;
}

// The whole per-point stress step, over a PointView of mixed materials.
int testStressPoint(const std::vector<NamedLaw>& named, LawParams* dLaws)
{
    const Index n = 20000;
    // Field layout of one flat array: mass, volume0, volume, F[9], sigma[6],
    // eqPlasticStrain, L[9], dx[3] (unused), then the materials apart.
    constexpr int nFields = 3 + 9 + 6 + 1 + 9 + 3;
    std::vector<Real> host(std::size_t(nFields)*n);
    std::vector<int> material(n);
    std::mt19937 rng(11);
    std::uniform_real_distribution<Real> u01(0, 1);
    std::vector<LawParams> laws;
    for (const auto& l : named) laws.push_back(l.law->params());
    for (Index p = 0; p < n; ++p)
    {
        const int m = int(p % Index(named.size()));
        const LawCase c = randomCase(m, rng);
        material[p] = m;
        Real* f = host.data();
        f[p] = c.solidFraction*laws[m].rho0*1e-6;     // mass: solid fraction c at J = 1
        f[n + p] = 1e-6;                                // volume0
        f[2*n + p] = 1e-6;
        for (int e = 0; e < 9; ++e) f[(3 + e)*n + p] = laws[m].deforms ? c.Fold[e] : (e % 4 == 0);
        for (int a = 0; a < 6; ++a) f[(12 + a)*n + p] = c.sigma[a];
        f[18*n + p] = c.ep;
        for (int e = 0; e < 9; ++e) f[(19 + e)*n + p] = c.L[e];
    }
    auto view = [n](Real* f, int* mat)
    {
        PointView P;
        P.n = n;
        P.mass = f; P.volume0 = f + n; P.volume = f + 2*n;
        for (int e = 0; e < 9; ++e) P.F[e] = f + (3 + e)*n;
        for (int a = 0; a < 6; ++a) P.sigma[a] = f + (12 + a)*n;
        P.eqPlasticStrain = f + 18*n;
        for (int e = 0; e < 9; ++e) P.L[e] = f + (19 + e)*n;
        for (int a = 0; a < 3; ++a) P.dx[a] = f + (28 + a)*n;
        P.material = mat;
        return P;
    };
    const std::vector<Real> before = host;
    Real* dField = toDevice(host);
    int* dMaterial = toDevice(material);
    unsigned char* dStatus = nullptr;
    if (!dField || !dMaterial || !check(cudaMalloc(&dStatus, n), "cudaMalloc")) return 1;
    const Real dt = 1e-3;
    stressPointKernel<<<int((n + 127)/128), 128>>>(view(dField, dMaterial), dLaws, dt, dStatus);
    if (!check(cudaGetLastError(), "stressPoint launch") || !check(cudaDeviceSynchronize(), "stressPoint")) return 1;
    std::vector<Real> device(host.size());
    std::vector<unsigned char> deviceStatus(n);
    cudaMemcpy(device.data(), dField, host.size()*sizeof(Real), cudaMemcpyDeviceToHost);
    cudaMemcpy(deviceStatus.data(), dStatus, n, cudaMemcpyDeviceToHost);
    cudaFree(dField); cudaFree(dMaterial); cudaFree(dStatus);

    const PointView H = view(host.data(), material.data());
    Real worst = 0;
    int worstField = -1;
    Index statusMismatch = 0;
    for (Index p = 0; p < n; ++p)
    {
        const StressPointStatus s = stressPoint(H, laws.data(), dt, p);
        statusMismatch += static_cast<unsigned char>(s) != deviceStatus[p];
        Real sigmaBefore[6], sigmaAfter[6];
        for (int a = 0; a < 6; ++a) { sigmaBefore[a] = before[(12 + a)*n + p]; sigmaAfter[a] = host[(12 + a)*n + p]; }
        const Real scale = stressScale(sigmaBefore, sigmaAfter);
        // F's entries against the point's largest (an entry near zero is
        // a difference of products of order one), the volume J V0 against
        // V0 times Hadamard's bound on |det F| (the product of the rows'
        // norms): the size of the determinant's terms, which set its
        // rounding
        Real Fmax = 0, hadamard = 1;
        for (int e = 0; e < 9; ++e) Fmax = std::max(Fmax, std::abs(host[(3 + e)*n + p]));
        for (int r = 0; r < 3; ++r)
        {
            Real row = 0;
            for (int c = 0; c < 3; ++c) row += host[(3 + 3*r + c)*n + p]*host[(3 + 3*r + c)*n + p];
            hadamard *= std::sqrt(row);
        }
        for (int f = 0; f < nFields; ++f)
        {
            const std::size_t i = std::size_t(f)*n + p;
            Real ref = std::max(std::abs(host[i]), Real(1e-300));
            if (f >= 12 && f < 18) ref = scale;
            else if (f >= 3 && f < 12) ref = std::max(Fmax, Real(1e-300));
            else if (f == 2) ref = std::max(host[n + p]*hadamard, ref);
            const Real d = std::abs(host[i] - device[i])/ref;
            if (d > worst) { worst = d; worstField = f; }
        }
    }
    const bool ok = worst <= tolerance && statusMismatch == 0;
    static const char* const fieldNames[] = {"mass", "volume0", "volume", "F", "F", "F", "F", "F", "F", "F", "F",
                                             "F", "sigma", "sigma", "sigma", "sigma", "sigma", "sigma",
                                             "eqPlasticStrain", "L", "L", "L", "L", "L", "L", "L", "L", "L",
                                             "dx", "dx", "dx"};
    std::printf("%s stressPoint over a PointView: %lld points of %d materials, status mismatches %lld, "
                "largest relative difference host/device %.3e (%s)\n", ok ? "PASS" : "FAIL", (long long)n,
                int(named.size()), (long long)statusMismatch, worst, worstField >= 0 ? fieldNames[worstField] : "-");
    return ok ? 0 : 1;
}

} // namespace

int main()
{
    if (!gpuPresent()) return 77;

    const std::vector<NamedLaw> named = makeTestLaws();
    std::vector<LawParams> laws;
    for (const auto& l : named) laws.push_back(l.law->params());
    LawParams* dLaws = toDevice(laws);
    if (!dLaws) return 1;
    int failures = testLaws(named, dLaws);
    failures += testStressPoint(named, dLaws);
    cudaFree(dLaws);
    return failures ? 1 : 0;
}

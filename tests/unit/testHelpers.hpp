// Small builders shared by the unit tests.
#pragma once
#include "step/mpmSystem.hpp"
#include <random>

namespace mpm::test {

// A law with zero stress (no wave speed): isolates the transfers.
class NoStress : public ConstitutiveLaw
{
public:
    const char* typeName() const override { return "noStress"; }
    void updateStress(const PointKinematics& k, PointStress& s) const override { diluteStress(k, s); }
    // Stress-free like dilute grains, but deforming (F and the volume follow
    // the flow, as for a continuum)
    LawParams params() const override { return baseParams(LawType::dilute); }
    Real storedEnergy(const Real*, const Real*) const override { return 0; }
};

inline Lattice box(int nx, int ny, int nz, Real h = 0.1)
{
    Lattice L;
    L.h = h;
    L.nCells = {nx, ny, nz};
    L.solved = {nx > 1, ny > 1, nz > 1};
    L.origin = {0, 0, 0};
    return L;
}

// Random points inside [lo, hi] of the box, random velocities.
inline void seedRandom(MpmSystem& s, Index n, Real lo, Real hi, unsigned seed = 1)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> u(0, 1), uv(-1, 1), um(0.5, 1.5);
    const Lattice& L = s.lattice();
    for (Index i = 0; i < n; ++i)
    {
        std::array<Real, 3> x{}, v{};
        for (int a = 0; a < 3; ++a)
        {
            const Real len = L.length(a);
            x[a] = L.solved[a] ? L.origin[a] + (lo + (hi - lo)*u(rng))*len : L.origin[a] + 0.5*L.h;
            v[a] = L.solved[a] ? uv(rng) : 0;
        }
        s.particles().add(x, v, um(rng), 1e-3, 0);
    }
}

// A time series: time and a mean point velocity (the wall tests)
struct History
{
    std::vector<Real> t, u;
};

// Least-squares slope of u(t) over t in [t0, t1]
inline Real slope(const History& r, Real t0, Real t1)
{
    Real n = 0, st = 0, su = 0, stt = 0, stu = 0;
    for (std::size_t i = 0; i < r.t.size(); ++i)
    {
        if (r.t[i] < t0 || r.t[i] > t1) continue;
        n += 1; st += r.t[i]; su += r.u[i]; stt += r.t[i]*r.t[i]; stu += r.t[i]*r.u[i];
    }
    return (n*stu - st*su)/(n*stt - st*st);
}

// The three algorithms the wall tests run: the granular tutorials' (cubic,
// APIC, USL), quadratic APIC MUSL, and linear hats with FLIP and USF
inline std::vector<std::pair<const char*, StepOptions>> algorithms()
{
    StepOptions tutorial;
    tutorial.transfer = Transfer::apic;
    StepOptions musl = tutorial;
    musl.stressUpdate = StressUpdate::MUSL;
    musl.shape = ShapeKind::quadraticBSpline;
    StepOptions usf = tutorial;
    usf.stressUpdate = StressUpdate::USF;
    usf.shape = ShapeKind::linearHat;
    usf.transfer = Transfer::picFlip;
    usf.flipRatio = 0.95;
    return {{"cubic APIC USL", tutorial}, {"quadratic APIC MUSL", musl}, {"linear PICFLIP USF", usf}};
}

} // namespace mpm::test

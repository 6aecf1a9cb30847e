// Small builders shared by the unit tests.
#pragma once
#include "step/mpmSystem.hpp"
#include <random>

namespace mpm::test {

// A law with zero stress and a fixed wave speed: isolates the transfers.
class NoStress : public ConstitutiveLaw
{
public:
    explicit NoStress(Real c = 1.0) : c_(c) {}
    const char* typeName() const override { return "noStress"; }
    void updateStress(const PointKinematics& k, PointStress& s) const override { diluteStress(k, s); }
    // Stress-free like dilute grains, but deforming (F and the volume follow
    // the flow, as for a continuum)
    LawParams params() const override { return baseParams(LawType::dilute); }
    Real waveSpeed(Real) const override { return c_; }
    Real storedEnergy(const Real*, const Real*) const override { return 0; }
private:
    Real c_;
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

} // namespace mpm::test

// Stress-free material points: a dilute suspension of grains that do not
// touch, moved only by gravity and the fluid (drag, buoyancy). The signal
// speed is zero, so the MPM step is limited by the point speed and the
// fluid step alone.
#pragma once
#include "constitutiveLaw.hpp"
#include "diluteKernel.hpp"

namespace mpm {

class Dilute : public ConstitutiveLaw
{
public:
    explicit Dilute(Real rho) { rho0_ = rho; }
    static std::unique_ptr<ConstitutiveLaw> create(const Coefficients& c)
    {
        return std::make_unique<Dilute>(c.at("rho"));
    }

    const char* typeName() const override { return "dilute"; }
    void updateStress(const PointKinematics& k, PointStress& s) const override
    {
        diluteStress(k, s);
    }
    LawParams params() const override { return baseParams(LawType::dilute); }
    Real storedEnergy(const Real*, const Real*) const override { return 0; }
    bool needsDeformation() const override { return false; }
};

} // namespace mpm

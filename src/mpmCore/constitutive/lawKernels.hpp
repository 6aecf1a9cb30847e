// The constitutive laws as kernel bodies: one trivially copyable parameter
// struct per material (LawParams, built on the host once per step by
// ConstitutiveLaw::params()) and one switch on the law's type, callable per
// point on the host and on the device. No virtual call, no allocation, no
// exception in this path; each law's update exists once, in its
// <law>Kernel.hpp, and the law class's virtual updateStress calls the same
// function.
#pragma once
#include "diluteKernel.hpp"
#include "druckerPragerKernel.hpp"
#include "linearElasticKernel.hpp"
#include "muIRheologyKernel.hpp"
#include "neoHookeanKernel.hpp"
#include "newtonianFluidKernel.hpp"

namespace mpm {

enum class LawType : int
{
    linearElastic,
    neoHookean,
    newtonianFluid,
    druckerPrager,
    muIRheology,
    dilute
};

// The type plus the parameters of every law (only those of `type` are
// meaningful): a fixed-size value, so a table of them indexed by material
// is a plain array on either side.
struct LawParams
{
    LawType type = LawType::dilute;
    Real rho0 = 1;            // reference density (for the solid fraction)
    // Whether F is updated; a law that needs no deformation (dilute grains)
    // keeps F at identity and J = 1.
    bool deforms = true;
    LinearElasticParams linearElastic{};
    NeoHookeanParams neoHookean{};
    NewtonianFluidParams newtonianFluid{};
    DruckerPragerParams druckerPrager{};
    MuIRheologyParams muIRheology{};
};

// Whether the law reads PointKinematics::solidFraction (the step skips a
// division per point for the others).
MPM_HOST_DEVICE inline bool readsSolidFraction(LawType type)
{
    return type == LawType::druckerPrager || type == LawType::muIRheology;
}

// Whether the law accumulates the equivalent plastic strain (the step
// neither reads nor writes it for the others).
MPM_HOST_DEVICE inline bool changesPlasticStrain(LawType type)
{
    return type == LawType::druckerPrager || type == LawType::muIRheology;
}

MPM_HOST_DEVICE inline void updateStress
(
    const LawParams& law, const PointKinematics& k, PointStress& s
)
{
    switch (law.type)
    {
        case LawType::linearElastic: linearElasticStress(law.linearElastic, k, s); break;
        case LawType::neoHookean: neoHookeanStress(law.neoHookean, k, s); break;
        case LawType::newtonianFluid: newtonianFluidStress(law.newtonianFluid, k, s); break;
        case LawType::druckerPrager: druckerPragerStress(law.druckerPrager, k, s); break;
        case LawType::muIRheology: muIRheologyStress(law.muIRheology, k, s); break;
        case LawType::dilute: diluteStress(k, s); break;
    }
}

// Largest signal speed of a law at volume ratio J, at its reference density
// rho0 (the CFL time step): the dilatational wave speed of the elastic part
// (plastic flow only softens a material), the Tait fluid's sound speed
MPM_HOST_DEVICE inline Real lawWaveSpeed(const LawParams& law, Real J)
{
    switch (law.type)
    {
        case LawType::linearElastic: return std::sqrt(law.linearElastic.el.pWaveModulus()/law.rho0);
        case LawType::neoHookean:
        {
            // The tangent p-wave modulus grows under compression
            const Real reference = law.neoHookean.el.pWaveModulus();
            const Real current = reference - 2.0*law.neoHookean.el.lambda*std::log(J);
            return std::sqrt((current > reference ? current : reference)/law.rho0);
        }
        case LawType::newtonianFluid:
        {
            const NewtonianFluidParams& c = law.newtonianFluid;
            return std::sqrt(c.gamma*c.K/law.rho0*std::pow(J, 1.0 - c.gamma));
        }
        case LawType::druckerPrager: return std::sqrt(law.druckerPrager.el.pWaveModulus()/law.rho0);
        case LawType::muIRheology: return std::sqrt(law.muIRheology.el.pWaveModulus()/law.rho0);
        case LawType::dilute: return 0;
    }
    return 0;
}

} // namespace mpm

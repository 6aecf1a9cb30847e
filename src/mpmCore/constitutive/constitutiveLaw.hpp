// Interface of a constitutive law in the core (plain C++17, no OpenFOAM).
//
// The step computes, for each material point, the velocity gradient L over
// the step and the updated deformation gradient F_new = (I + dt L) F_old,
// then updates the stress. It does so without a virtual call per point: it
// asks each material once per step for its params() (a LawParams value) and
// runs the kernel body of lawKernels.hpp, which switches on the law's type
// and works the same on the host and on a GPU. The class keeps what is not
// per point (names, wave speed, energy, the registry) and a virtual
// updateStress() that calls the same kernel, for tests and tools.
#pragma once
#include "../common/modelRegistry.hpp"
#include "lawKernels.hpp"
#include "pointState.hpp"
#include "../types.hpp"
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mpm {

class ConstitutiveLaw
{
public:
    virtual ~ConstitutiveLaw() = default;

    virtual const char* typeName() const = 0;

    // Stress update for one point over one step (the kernel of params()).
    virtual void updateStress(const PointKinematics& k, PointStress& s) const = 0;

    // The law as a kernel parameter value: its type, its parameters, rho0
    // and needsDeformation(). Called on the host once per step, not per point.
    virtual LawParams params() const = 0;

    // Largest signal speed (e.g. dilatational wave speed) at reference
    // density rho0 and volume ratio J, for the CFL time step: the kernel
    // lawWaveSpeed (lawKernels.hpp) of params(), which the step calls per
    // point on the host and the device
    Real waveSpeed(Real J) const { return lawWaveSpeed(params(), J); }

    // Extra stability bound on dt for cell size h (e.g. viscous diffusion);
    // +infinity when the law has none.
    virtual Real maxStableDt(Real h) const;

    // The largest ratio of shear to normal stress the material carries in
    // simple shear (the friction it mobilises), or +infinity when its shear
    // strength is not a friction alone (elastic solids, fluids, cohesive or
    // stress-free grains). A friction wall cannot hold the material harder
    // than this: the material next to it yields first
    // (MpmSystem::computeFrictionCap, docs/druckerPrager.md).
    virtual Real shearStrengthRatio() const;

    // One line on how the parameters given were read (the friction match
    // of druckerPrager), echoed at start-up; empty when there is nothing
    // to add
    virtual std::string note() const { return std::string(); }

    // Stored (recoverable) elastic energy per unit reference volume, for
    // energy diagnostics: the strain energy of hyperelastic laws, the
    // complementary energy sigma:C^-1:sigma/2 (times J) of hypoelastic and
    // elastoplastic laws, the compression energy of the fluid.
    virtual Real storedEnergy(const Real* sigma, const Real* F) const = 0;

    // Whether the law needs the deformation gradient. Stress-free grains do
    // not: their F is left at identity, so unbounded compaction of a
    // sediment cannot make it singular.
    virtual bool needsDeformation() const { return true; }

    // Reference (initial) density.
    Real rho0() const { return rho0_; }

protected:
    // A LawParams of the given type with rho0 and needsDeformation() filled.
    LawParams baseParams(LawType type) const
    {
        LawParams p;
        p.type = type;
        p.rho0 = rho0_;
        p.deforms = needsDeformation();
        return p;
    }

    Real rho0_ = 1.0;
};

// Creation by name, with a parameter list per law. Lives in the core so that
// tests and benchmarks can build laws without OpenFOAM; the OpenFOAM layer
// wraps it in a run-time selection.
using LawInfo = ModelInfo<ConstitutiveLaw>;

const std::vector<LawInfo>& availableLaws();
const LawInfo* findLaw(const std::string& name);

// Throws std::invalid_argument naming the law and parameter if a required
// parameter is missing, a value is out of range or a name is not one of the
// law's parameters (catches typos); for an unknown law the message lists the
// valid law names. Optional parameters absent from c take their default.
std::unique_ptr<ConstitutiveLaw> makeLaw(const std::string& name, const Coefficients& c);

} // namespace mpm

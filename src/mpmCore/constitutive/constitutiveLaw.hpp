// Interface of a constitutive law in the core (plain C++17, no OpenFOAM).
//
// The step computes, for each material point, the velocity gradient L over
// the step and the updated deformation gradient F_new = (I + dt L) F_old,
// then calls updateStress() once per point. A virtual call per point costs a
// few ns, negligible against the 8..64-node stencil loops, and keeps each law
// a small self-contained class.
#pragma once
#include "../common/modelRegistry.hpp"
#include "../types.hpp"
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace mpm {

// Everything a law may read or change at one material point.
struct PointKinematics
{
    const Real* L;        // velocity gradient, row-major, L_ij = dv_i/dx_j
    const Real* Fold;     // deformation gradient at the start of the step
    const Real* Fnew;     // deformation gradient at the end of the step
    Real dt;
    // Grain volume fraction of the point's parcel at the end of the step,
    // mass / (rho0 volume): 1/J for a continuum, the local packing for
    // grains seeded with a solidFraction < 1.
    Real solidFraction = 1;
};

struct PointStress
{
    Real* sigma;          // Cauchy stress (xx yy zz xy yz xz), updated in place
    Real* eqPlasticStrain;// accumulated equivalent plastic strain (history)
};

class ConstitutiveLaw
{
public:
    virtual ~ConstitutiveLaw() = default;

    virtual const char* typeName() const = 0;

    // Stress update for one point over one step.
    virtual void updateStress(const PointKinematics& k, PointStress& s) const = 0;

    // Largest signal speed (e.g. dilatational wave speed) at reference
    // density rho0 and volume ratio J, for the CFL time step.
    virtual Real waveSpeed(Real J) const = 0;

    // Extra stability bound on dt for cell size h (e.g. viscous diffusion);
    // +infinity when the law has none.
    virtual Real maxStableDt(Real h) const;

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

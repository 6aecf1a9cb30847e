// What a constitutive law reads and changes at one material point: plain
// pointers and values, so the same structs are built by the host loop and
// by a device kernel (see lawKernels.hpp).
#pragma once
#include "../types.hpp"

namespace mpm {

// Everything a law may read at one material point.
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

} // namespace mpm

// Plain views of the structure-of-arrays data, for the kernel bodies.
//
// A kernel body (kernels/*.hpp) is written once, as an MPM_HOST_DEVICE
// function of one point or one node over these views, and launched by every
// back-end (the host phases' loops, phases/*.cpp: serial, OpenMP;
// backend/forEachOnDevice.cuh: CUDA; backend/residentStepImpl.hpp: the
// resident step on CUDA and its host stand-in). The
// views hold raw pointers only, so they are trivially copyable into a CUDA
// kernel's arguments; on the host they point into Particles and GridState,
// on the device into the device mirror of the same arrays.
#pragma once
#include "../common/hostDevice.hpp"
#include "../types.hpp"
#include <array>
#include <vector>
#include "../common/staggeredArray.hpp"

namespace mpm {

struct Particles;
struct GridState;

// One material point's arrays, plus the step's per-point scratch.
struct PointView
{
    Index n = 0;
    Real* x[3] = {};
    Real* v[3] = {};
    Real* mass = nullptr;
    Real* volume0 = nullptr;
    Real* volume = nullptr;
    Real* F[9] = {};
    Real* sigma[6] = {};
    Real* C[9] = {};
    Real* eqPlasticStrain = nullptr;
    int* material = nullptr;
    // Scratch of the step: the velocity gradient and the displacement
    Real* L[9] = {};
    Real* dx[3] = {};
};

// Nodal arrays on the padded lattice.
struct GridView
{
    Index n = 0;
    Real* mass = nullptr;
    Real* volume = nullptr;
    Real* momentum[3] = {};
    Real* force[3] = {};
    Real* velocityOld[3] = {};
    Real* velocity[3] = {};
    // Optional (null where not built): per node, 8 values
    // (v0 v1 v2 0 | v0-vOld0 v1-vOld1 v2-vOld2 0), so that the 3D PIC/FLIP
    // G2P reads one node's velocities as two 4-wide loads instead of six
    // scalar streams (kernels/g2p.hpp; built by phases/gather.cpp on the
    // region's nodes after the nodal update)
    const Real* velocityPack = nullptr;
};

// Host views of the step's arrays (defined in kernels/views.cpp).
PointView pointView
(
    Particles& P, std::array<StaggeredArray<Real>, 9>& L, std::array<StaggeredArray<Real>, 3>& dx
);
GridView gridView(GridState& g);

} // namespace mpm

// Material points as a structure of arrays: one flat array per component,
// so kernels stream through memory and map directly to OpenMP/CUDA.
#pragma once
#include "../types.hpp"
#include <array>
#include <vector>
#include "../common/staggeredArray.hpp"

namespace mpm {

struct Particles
{
    std::array<StaggeredArray<Real>, 3> x;      // position
    std::array<StaggeredArray<Real>, 3> v;      // velocity
    StaggeredArray<Real> mass;
    StaggeredArray<Real> volume0;               // initial volume
    StaggeredArray<Real> volume;                // current volume = J volume0
    std::array<StaggeredArray<Real>, 9> F;      // deformation gradient (row-major)
    std::array<StaggeredArray<Real>, 6> sigma;  // Cauchy stress (xx yy zz xy yz xz)
    std::array<StaggeredArray<Real>, 9> C;      // APIC affine velocity matrix
    StaggeredArray<Real> eqPlasticStrain;       // history of plastic laws
    StaggeredArray<int> material;               // index into the material list
    std::vector<std::int64_t> id;            // stable id, for diagnostics

    Index size() const { return Index(mass.size()); }

    void resize(Index n);

    // Appends a point at rest-state kinematics (F = I, C = 0).
    Index add
    (
        const std::array<Real, 3>& pos, const std::array<Real, 3>& vel,
        Real m, Real vol, int mat
    );

    // Reorders every array by `order` (new i = old order[i]).
    void permute(const std::vector<Index>& order);

    // Migration between ranks: appends point p (every field) to a byte
    // buffer; appends every point of such a buffer; removes the points at
    // the given indices (ascending), filling each hole with the last point
    // (O(removed), not O(points): a few points leave per step).
    void pack(Index p, std::vector<char>& buf) const;
    void unpack(const std::vector<char>& buf);
    void remove(const std::vector<Index>& ascending);

    Real J(Index p) const;
};

} // namespace mpm

// Basic types shared by every core kernel. Plain C++17, no OpenFOAM.
#pragma once
#include <cstddef>
#include <cstdint>

namespace mpm {

using Real = double;
using Index = std::int64_t;

// Symmetric tensors are stored in Voigt-like order (xx, yy, zz, xy, yz, xz)
// so a stress is six flat arrays in the particle SoA.
enum SymmComponent { XX = 0, YY = 1, ZZ = 2, XY = 3, YZ = 4, XZ = 5 };

// Full 3x3 tensors are row-major: T_ij at [3*i + j].
inline constexpr int ij(int i, int j) { return 3*i + j; }

} // namespace mpm

// The back-end that launches the step's kernel bodies (kernels/*.hpp).
//
//   serial  one thread: the reference;
//   openmp  OpenMP threads; bitwise equal to serial whatever the thread
//           count (P2G by colours, every other loop independent per item);
//   cuda    the GPU (backend/deviceStep.hpp), where the build found nvcc.
#pragma once
#include "../types.hpp"
#include <string>

namespace mpm {

enum class Backend { serial = 0, openmp = 1, cuda = 2 };

const char* backendName(Backend b);
bool parseBackend(const std::string& name, Backend& b);
const char* validBackendNames();

// Why this build or this machine cannot run back-end b, or "" when it can:
// cuda needs a core built where nvcc was found (MPM_HAVE_CUDA) and a
// usable GPU at run time.
std::string backendUnavailableReason(Backend b);

} // namespace mpm

#include "backend.hpp"
#include <initializer_list>

namespace mpm {

const char* backendName(Backend b)
{
    switch (b)
    {
        case Backend::serial: return "serial";
        case Backend::openmp: return "openmp";
        case Backend::cuda: return "cuda";
    }
    return "?";
}

bool parseBackend(const std::string& name, Backend& b)
{
    for (Backend c : {Backend::serial, Backend::openmp, Backend::cuda})
    {
        if (name == backendName(c)) { b = c; return true; }
    }
    return false;
}

const char* validBackendNames() { return "serial openmp cuda"; }

#ifdef MPM_HAVE_CUDA
std::string cudaUnavailableReason();   // backend/ (the CUDA library)
#endif

std::string backendUnavailableReason(Backend b)
{
    if (b != Backend::cuda) return "";
#ifdef MPM_HAVE_CUDA
    return cudaUnavailableReason();
#else
    return "this build has no CUDA back-end (nvcc was not found when the"
           " core was built; see docs/backends.md)";
#endif
}

} // namespace mpm

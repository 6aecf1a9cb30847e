#include "backend.hpp"
#include "../common/enumTable.hpp"
#include <initializer_list>

namespace mpm {

namespace
{
const auto backends = enumTable<Backend>({{Backend::serial, "serial"}, {Backend::openmp, "openmp"}, {Backend::cuda, "cuda"}});
const std::string backendList = backends.validNames();
}

const char* backendName(Backend b) { return backends.name(b); }
bool parseBackend(const std::string& name, Backend& b) { return backends.parse(name, b); }
const char* validBackendNames() { return backendList.c_str(); }

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

// cudaUnavailableReason of a build without the CUDA back-end (CMake
// compiles this file only when nvcc was not found or MPM_DISABLE_CUDA is
// on; the CUDA build's definition is deviceQuery.cu).
#include "deviceStep.hpp"

namespace mpm {

std::string cudaUnavailableReason()
{
    return "this build has no cuda back-end: nvcc was not found when the core was "
           "built (or it was configured with -DMPM_DISABLE_CUDA=ON); install the CUDA "
           "toolkit and rebuild (./Allwmake), or choose the openmp or serial back-end";
}

} // namespace mpm

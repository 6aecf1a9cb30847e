#include "fluidCoupling.hpp"
#include <algorithm>

namespace mpm {

void FluidCoupling::resize(Index nNodes)
{
    K.assign(std::size_t(nNodes), 0.0);
    for (int d = 0; d < 3; ++d)
    {
        U[d].assign(std::size_t(nNodes), 0.0);
        F[d].assign(std::size_t(nNodes), 0.0);
        velocityIntegral[d].assign(std::size_t(nNodes), 0.0);
    }
}

void FluidCoupling::resetIntegral()
{
    for (auto& a : velocityIntegral) std::fill(a.begin(), a.end(), 0.0);
    time = 0;
}

} // namespace mpm

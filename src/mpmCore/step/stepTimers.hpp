// Wall-clock time spent in each phase of the step: what accuracy costs.
#pragma once
#include <chrono>

namespace mpm {

struct StepTimers
{
    double p2g = 0;           // binning + particle-to-grid scatter
    double nodal = 0;         // nodal momentum update + boundary conditions
    double g2p = 0;           // grid-to-particle gather + position update
    double constitutive = 0;  // deformation gradient + stress update
    double migration = 0;     // decomposed runs: points to their new owners
    // Decomposed runs: halo sums and copies, already inside the phases (a
    // share of them, not a phase of its own), in all and per phase
    // category (runPlan books each phase's share to its category)
    double halo = 0;
    struct { double p2g = 0, nodal = 0, g2p = 0, constitutive = 0; } haloIn;

    double total() const { return p2g + nodal + g2p + constitutive + migration; }
};

// Adds the lifetime of the scope to one timer.
class ScopedTimer
{
public:
    explicit ScopedTimer(double& acc)
    : acc_(acc), t0_(std::chrono::steady_clock::now()) {}
    ~ScopedTimer()
    {
        acc_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    }
private:
    double& acc_;
    std::chrono::steady_clock::time_point t0_;
};

} // namespace mpm

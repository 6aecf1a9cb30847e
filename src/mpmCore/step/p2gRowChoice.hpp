// Whether the 3D P2G without APIC walks each row of W nodes along x as one
// vector loop (kernels/p2g.hpp) or node by node, chosen per run by timing.
//
// Why: the row loop halves the cubic P2G of a large block (32^3 cells,
// 85 000 nodes) but makes it 1.4 times slower on the small grid of the
// coupled mppicComparison scene (benchmarks/mppicComparison/README.md), and
// which wins was not predictable from the case. Both add the same terms in
// the same order to every node, so the choice changes the time, never a bit
// of the result (Transfer.P2gRowLoopChangesNoBit).
//
// Automatic: after `warmupSteps` (first-touch allocation), the next
// `trialSteps` alternate the two loops, summing each one's P2G time over
// every scatter of its steps; from then on the faster one runs. Each rank
// of a decomposed run decides for its own points.
#pragma once
#include "../types.hpp"

namespace mpm {

enum class P2gRowLoop { automatic = 0, always = 1, never = 2 };

class P2gRowChoice
{
public:
    static constexpr Index warmupSteps = 1;
    static constexpr Index trialSteps = 6;
    // Steps before the choice is final (benchmarks warm up this long)
    static constexpr Index tuningSteps = warmupSteps + trialSteps;

    explicit P2gRowChoice(P2gRowLoop mode = P2gRowLoop::automatic) : mode_(mode) {}

    // The loop for the scatters of `step`
    bool rows(Index step)
    {
        if (mode_ != P2gRowLoop::automatic) return mode_ == P2gRowLoop::always;
        if (!decided_ && step >= tuningSteps)
        {
            decided_ = true;
            rows_ = seconds_[1] <= seconds_[0];
        }
        if (decided_) return rows_;
        return step < warmupSteps || (step - warmupSteps) % 2 == 0;
    }

    // Time of one scatter of `step` that ran with the loop `rows`
    void record(Index step, bool rows, double seconds)
    {
        if (mode_ == P2gRowLoop::automatic && !decided_ && step >= warmupSteps)
            seconds_[rows ? 1 : 0] += seconds;
    }

    bool decided() const { return mode_ != P2gRowLoop::automatic || decided_; }
    // The loop that runs once decided (rows, or node by node)
    bool chosenRows() const { return mode_ == P2gRowLoop::automatic ? rows_ : mode_ == P2gRowLoop::always; }
    // Trial time of each loop [s]: node by node, by rows
    double trialSeconds(bool rows) const { return seconds_[rows ? 1 : 0]; }

private:
    P2gRowLoop mode_;
    bool decided_ = false;
    bool rows_ = true;
    double seconds_[2] = {0, 0};
};

} // namespace mpm

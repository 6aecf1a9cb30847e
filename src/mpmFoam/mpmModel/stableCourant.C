#include "stableCourant.H"
#include "stability/stabilityLimit.hpp"
#include <algorithm>
#include <sstream>

mpm::stability::AnalysisSetup Foam::analysedStep(const mpm::StepOptions& o)
{
    namespace st = mpm::stability;
    st::AnalysisSetup s;
    s.shape = o.shape;
    // APIC ignores flipRatio: its point velocity is the PIC interpolation
    // (kernels/g2p.hpp), so its analysed part is PIC, alpha 0; the affine
    // term it adds to P2G is not analysed. Not the unused flipRatio (0.99
    // by default, absent from APIC cases): the coupled advice analysed
    // that FLIP blend for APIC before (issue 28 item 4)
    s.alpha = o.transfer == mpm::Transfer::apic ? 0 : o.flipRatio;
    s.mass = mpm::MassMatrix::lumped;
    s.scheme = o.stressUpdate;
    s.offsets = {0};
    return s;
}

Foam::stableCourant Foam::analysedCourantLimit(const mpm::StepOptions& o)
{
    namespace st = mpm::stability;
    stableCourant result;
    if (o.transfer == mpm::Transfer::apic)
    {
        result.description = "APIC transfer is not analysed";
        return result;
    }
    if (o.massMatrix == mpm::MassMatrix::consistent)
    {
        result.description = "consistent mass is not analysed";
        return result;
    }
    st::AnalysisSetup s = analysedStep(o);
    s.model = st::Model::wave;
    // The offsets of docs/stabilityAnalysis.md's "limit vs offset" table,
    // (i + 0.5)/20. The kernels are symmetric, so offsets o and 1 - o have
    // the same limit: the first half is enough.
    const int nShift = 20;
    std::vector<mpm::Real> shifts;
    for (int i = 0; i < nShift/2; ++i) shifts.push_back((i + 0.5)/nShift);
    // The tool's search, with a coarser scan (steps of 0.04 instead of 0.01,
    // still far finer than the stable interval) and bisection to 1e-9: the
    // same limit to the printed digits, 6x cheaper (start-up cost).
    st::LimitOptions options = st::defaultLimitOptions(s.model);
    options.scanPoints = 100;
    options.relTolerance = 1e-9;
    const auto limits = st::limitVersusShift(s, shifts, options);
    result.limit = limits.front().second.limit;
    for (const auto& l : limits) result.limit = std::min(result.limit, scalar(l.second.limit));

    std::ostringstream d;
    d   << "1D wave, " << mpm::shapeName(o.shape) << ", "
        << mpm::stressUpdateName(s.scheme) << ", flipRatio " << o.flipRatio
        << ", lumped mass, worst of " << nShift << " point offsets";
    result.description = d.str();
    return result;
}

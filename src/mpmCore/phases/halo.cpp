#include "halo.hpp"

namespace mpm {

void sumHalo(SystemState& s, unsigned what)
{
    auto& g = s.grid;
    std::vector<Real*> a;
    if (what & foldMass) { a.push_back(g.mass.data()); a.push_back(g.volume.data()); }
    for (int d = 0; d < 3; ++d)
    {
        if (what & foldMomentum) a.push_back(g.momentum[d].data());
        if (what & foldForce) a.push_back(g.force[d].data());
    }
    sumHalo(s, a);
}

void sumHalo(const SystemState& s, const std::vector<Real*>& arrays, Subdomain::HaloKind kind)
{
    if (s.subdomain)
    {
        ScopedTimer t(s.timers.halo);
        s.subdomain->sum(arrays, kind);
        return;
    }
    // Serial: the periodic copies are the halo.
    const auto& pc = s.boundary.periodicCopies();
    for (Real* a : arrays) for (const Index c : s.region.periodicCopies()) a[pc[c].second] += a[pc[c].first];
}

void copyHalo(const SystemState& s, const std::vector<Real*>& arrays, Subdomain::HaloKind kind)
{
    if (s.subdomain)
    {
        ScopedTimer t(s.timers.halo);
        s.subdomain->copy(arrays, kind);
        return;
    }
    const auto& pc = s.boundary.periodicCopies();
    for (Real* a : arrays) for (const Index c : s.region.periodicCopies()) a[pc[c].first] = a[pc[c].second];
}

} // namespace mpm

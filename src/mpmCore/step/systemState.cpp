#include "systemState.hpp"
#include "nonFiniteError.hpp"
#include <algorithm>
#include <sstream>
#include <string>

namespace mpm {

Index SystemState::parallelThreshold = 50000;

int stencilReach(ShapeKind kind)
{
    return dispatchShape(kind, [](auto k) { return decltype(k)::width/2; });
}

void SystemState::buildNodes(const BoundarySpec& spec)
{
    if (subdomain)
    {
        const Subdomain& sd = *subdomain;
        lattice = sd.local();
        boundary.build(domain, spec, lattice, sd.offset(), [&sd](Index c) { return sd.ownsCell(c); });
    }
    else
    {
        lattice = domain;
        boundary.build(lattice, spec);
    }
    grid.resize(lattice.nNodes);
    region = ActiveRegion();
    region.setDense(!options.sparseGrid);
}

void SystemState::sizePointScratch()
{
    const Index n = particles.size();
    for (auto& a : velocityGradient) a.resize(n);
    for (auto& a : displacement) a.resize(n);
}

void SystemState::pullPoints() const
{
    if (!deviceAhead) return;
    // The host's points are a copy of the device's: refreshing it changes
    // no state of the model
    resident->downloadPoints(const_cast<SystemState&>(*this).points());
    deviceAhead = false;
}

// Below parallelThreshold work items a loop runs serially: a parallel
// region costs microseconds on an idle machine but a scheduler time slice
// (milliseconds) when another process holds a core, and small loops gain
// nothing from two threads. With the serial back-end every loop runs on
// one thread.
bool SystemState::worthThreads(Index n) const
{
    return options.backend == Backend::openmp && n >= parallelThreshold;
}

void SystemState::stopIfNonFinite(Index firstBad, const char* what)
{
    // Every rank takes the same decision and names the same point: the
    // lowest id among the ranks' first bad points.
    const auto& P = particles;
    const std::int64_t none = std::numeric_limits<std::int64_t>::max();
    std::int64_t id = firstBad < P.size() ? P.id[firstBad] : none;
    std::int64_t material = firstBad < P.size() ? P.material[firstBad] : -1;
    if (subdomain)
    {
        const Communicator& c = subdomain->comm();
        id = c.min(id);
        if (id == none) return;
        if (firstBad >= P.size() || P.id[firstBad] != id) material = -1;
        material = c.max(material);
    }
    if (id == none) return;
    std::ostringstream os;
    os << "non-finite " << what << " at step " << stepCount + 1
       << " in material point id " << id;
    const bool ofMaterial = std::string(what) != "velocity";
    throw NonFiniteError(os.str(), stepCount + 1, id, ofMaterial ? int(material) : -1);
}

// Among the points with J <= 0 or a volume not positive (host and device
// steps alike)
void SystemState::findFirstInverted()
{
    const Particles& P = particles;
    std::int64_t first = std::numeric_limits<std::int64_t>::max();
    Index at = -1;
    for (Index p = 0; p < P.size(); ++p)
    {
        if (!(P.J(p) <= 0 || P.volume[p] <= 0) || P.id[p] >= first) continue;
        first = P.id[p];
        at = p;
    }
    if (at < 0) return;
    inverted.id = first;
    inverted.material = P.material[at];
    inverted.J = P.J(at);
    inverted.volume = P.volume[at];
}

std::vector<LawParams> SystemState::lawTable() const
{
    std::vector<LawParams> laws(materials.size());
    for (std::size_t m = 0; m < materials.size(); ++m) laws[m] = materials[m]->params();
    return laws;
}

std::vector<Real> SystemState::inverseDensities() const
{
    std::vector<Real> inv(materials.size());
    for (std::size_t m = 0; m < materials.size(); ++m) inv[m] = 1.0/materials[m]->rho0();
    return inv;
}

} // namespace mpm

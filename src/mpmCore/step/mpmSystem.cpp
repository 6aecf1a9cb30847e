#include "mpmSystem.hpp"
#include "../launchers/launchers.hpp"
#include "../phases/halo.hpp"
#include "../phases/migrate.hpp"
#include "../phases/timeStepLimit.hpp"
#include "../phases/walls.hpp"
#include <stdexcept>

namespace mpm {

Index& MpmSystem::parallelThreshold = SystemState::parallelThreshold;

void MpmSystem::setup
(
    const Lattice& lattice, const BoundarySpec& spec, const StepOptions& options,
    std::shared_ptr<const Subdomain> subdomain
)
{
    const std::string unavailable = backendUnavailableReason(options.backend);
    if (!unavailable.empty())
    {
        throw std::invalid_argument
        (
            std::string("backend ") + backendName(options.backend) + ": " + unavailable
        );
    }
    SystemState& s = s_;
    s.domain = lattice;
    s.domain.finalise();
    s.options = options;
    s.subdomain = std::move(subdomain);
    s.buildNodes(spec);
    s.plan = makeStepPlan(s.options);
    s.p2gRows = P2gRowChoice(s.options.p2gRowLoop);
    s.removedCount.assign(spec.conditions.size(), 0);
    s.removedMass.assign(spec.conditions.size(), 0.0);
    s.clamped = 0;
    s.contained = 0;
    s.levelSet = LevelSetWalls();
    // Gravity along unsolved directions has nothing to act on.
    for (int a = 0; a < 3; ++a) if (!s.lattice.solved[a]) s.options.gravity[a] = 0;
    // Available (checked above): the device mirror, sized by the first step
    if (s.options.backend != Backend::cuda) s.device.reset();
#ifdef MPM_HAVE_CUDA
    else if (!s.device) s.device = std::make_shared<DeviceStep>();
#endif
    // The resident step, where the case allows it (residentUnsupported)
    s.pullPoints();
    s.resident.reset();
    if (s.options.residentStandIn) s.resident = makeResidentStandIn();
#ifdef MPM_HAVE_CUDA
    else if (s.options.backend == Backend::cuda && s.options.deviceResident) s.resident = makeResidentCuda();
#endif
    s.residentConfigured = false;
    s.levelSetChanged = true;
    s.hostAhead = true;
    s.lastResident = false;
}

void MpmSystem::changeSubdomain(std::shared_ptr<const Subdomain> subdomain)
{
    SystemState& s = s_;
    s.pullPoints();
    const BoundarySpec spec = s.boundary.spec();
    s.subdomain = std::move(subdomain);
    s.buildNodes(spec);
    s.levelSet.relocate(s.lattice);
    s.levelSetChanged = true;
    if (!s.coupling.K.empty()) s.coupling.resize(s.lattice.nNodes);
    s.coverage.clear();
    s.coveredStencil.clear();
    for (auto& a : s.sample) a.clear();
    // The device mirrors are sized by the next step
#ifdef MPM_HAVE_CUDA
    if (s.device) s.device = std::make_shared<DeviceStep>();
#endif
    s.residentConfigured = false;
    s.hostAhead = true;
}

// The resident step where it runs this case, else the host's points are
// brought up to date and the cuda back-end's host-assisted step or the
// CPU back-ends' host step runs
void MpmSystem::step(Real dt)
{
    s_.lastResident = s_.resident && mpm::residentUnsupported(s_).empty();
    if (s_.lastResident) stepResident(s_, dt);
    else
    {
        s_.pullPoints();
        if (s_.device) stepHostAssisted(s_, dt);
        else stepOnHost(s_, dt);
    }
    ++s_.stepCount;
}

Index MpmSystem::countOutside() const
{
    s_.pullPoints();
    const Lattice& D = s_.domain;
    const Particles& P = s_.particles;
    Index count = 0;
    for (Index p = 0; p < P.size(); ++p)
    {
        for (int a = 0; a < 3; ++a)
        {
            if (!D.solved[a]) continue;
            const Real x = P.x[a][p];
            if (x < D.origin[a] || x > D.origin[a] + D.length(a)) { ++count; break; }
        }
    }
    return count;
}

// The forwards to the phases and launchers
Index MpmSystem::migrate() { return mpm::migrate(s_); }
void MpmSystem::setLevelSetWalls(std::vector<LevelSetWall> walls, const std::array<Real, 3>& unsolved)
{
    mpm::setLevelSetWalls(s_, std::move(walls), unsolved);
}
void MpmSystem::moveLevelSetWalls
(
    const std::vector<std::array<Real, 3>>& displacement,
    const std::vector<std::array<Real, 3>>& velocity
)
{
    mpm::moveLevelSetWalls(s_, displacement, velocity);
}
Real MpmSystem::computeFrictionCap() const { return mpm::computeFrictionCap(s_); }
Real MpmSystem::largestWallFriction() const { return mpm::largestWallFriction(s_); }
Real MpmSystem::maxSignalSpeed() const { return mpm::maxSignalSpeed(s_); }
Real MpmSystem::stableDeltaT(Real courant) const { return mpm::stableDeltaT(s_, courant); }
void MpmSystem::mapToGrid(std::vector<Real>* grainVolume) { mpm::mapToGrid(s_, grainVolume); }
MpmSystem::GridSample MpmSystem::sampleGrid() { return mpm::sampleGrid(s_); }
void MpmSystem::materialGrainVolume(std::vector<std::vector<Real>>& out) { mpm::materialGrainVolume(s_, out); }
void MpmSystem::setCoverage(const std::vector<double>& coverage) { mpm::setCoverage(s_, coverage); }
void MpmSystem::spreadGrainVolume(std::vector<Real>& spread) const { mpm::spreadGrainVolume(s_, spread); }
void MpmSystem::sumToOwners(const std::vector<Real*>& arrays) { sumHalo(s_, arrays, Subdomain::HaloKind::exchange); }
void MpmSystem::copyToHalo(const std::vector<Real*>& arrays) const { copyHalo(s_, arrays, Subdomain::HaloKind::exchange); }
std::string MpmSystem::residentUnsupported() const { return mpm::residentUnsupported(s_); }

} // namespace mpm

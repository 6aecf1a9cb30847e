// The cuda back-end's host-assisted step (backend/deviceStep.hpp: the data
// flow and its cost): the point work on the device with the CPU's kernel
// bodies, the node work between the transfers the host's own phases.
#include "launchers.hpp"
#include "../phases/migrate.hpp"
#include "../phases/movePoints.hpp"
#include "../phases/nodalUpdate.hpp"
#include "../phases/scatter.hpp"
#include "../kernels/movePoint.hpp"
#include <algorithm>
#include <stdexcept>

namespace mpm {

#ifdef MPM_HAVE_CUDA
namespace {

// The stress update on the device; the inverted point of lowest id is
// found on the host after the points come back (moveOnDevice)
void stressOnDevice(SystemState& s, Real dt)
{
    const DeviceStep::StressResult r = s.device->stress(dt);
    s.stopIfNonFinite(r.firstBad, "stress or deformation");
    s.inverted = InvertedPoints{};
    s.inverted.count = r.inverted;
}

// The advance on the device, then the points come back; the few beyond a
// face are classified here as movePoints does (removed or held)
void moveOnDevice(SystemState& s, bool apic, Real dt)
{
    const Boundary& b = s.boundary;
    const bool periodic[3] = {b.periodic(0), b.periodic(1), b.periodic(2)};
    const bool frozen = s.options.freezePositions;
    const Index flagged = s.device->move(s.domain, periodic, frozen, s.moveFlags);
    const PointView P = s.points();
    s.device->downloadPoints(P, apic);
    if (s.inverted.count > 0) s.findFirstInverted();
    const Index n = P.n;
    Index firstBad = n, clamped = 0, leaving = 0;
    s.leavingThrough.assign(b.hasOpenFaces() || s.levelSet.hasOutlets() ? n : 0, -1);
    if (flagged == 0)
    {
        if (!frozen) removeLeaving(s, containPoints(s, dt));
        return;
    }
    for (Index p = 0; p < n; ++p)
    {
        const int flags = s.moveFlags[p];
        if (flags & moveBad) { firstBad = std::min(firstBad, p); continue; }
        if (frozen || !(flags & moveOutside)) continue;
        // The device left the unclamped new position
        const Real x[3] = {P.x[0][p], P.x[1][p], P.x[2][p]};
        if (leavesThroughFace(s, p, x, leaving, clamped)) continue;
        storePosition(s.domain, periodic, P, p, x);
    }
    s.stopIfNonFinite(firstBad, "velocity");
    s.clamped += clamped;
    if (!frozen) leaving += containPoints(s, dt);
    removeLeaving(s, leaving);
}

} // namespace

void stepHostAssisted(SystemState& s, Real dt)
{
    DeviceStep& dev = *s.device;
    s.sizePointScratch();
    updateMassTolerance(s);
    const bool withForce = s.plan.forceWithScatter;
    const bool apic = s.options.transfer == Transfer::apic;
    const bool grainVolume = s.options.constantGrainVolume;
    const ShapeKind shape = s.options.shape;
    const Lattice& L = s.lattice;
    const unsigned massMomentum = DeviceStep::gridMass | DeviceStep::gridVolume | DeviceStep::gridMomentum;
    const unsigned force = DeviceStep::gridForce;
    const std::vector<LawParams> laws = s.lawTable();
    const std::vector<Real> invRho0 = s.inverseDensities();
    const GridView host = gridView(s.grid);
    runPlan(s.plan, s.timers, [&](Phase phase)
    {
        switch (phase)
        {
            case Phase::scatter:
                binPoints(s);   // first: the points go up in block order
                dev.setMaterials(laws);
                dev.uploadPoints(s.points(), apic);
                dev.setActiveNodes(L.nNodes, s.region.nodes());
                dev.zeroGrid(massMomentum | force);
                dev.p2g(L, shape, true, withForce, apic, invRho0, grainVolume);
                dev.gridToHost(host, massMomentum | (withForce ? force : 0u));
                break;
            case Phase::nodalAfterScatter: nodalAfterScatter(s, dt, withForce); break;
            case Phase::gradientFromOld:
                dev.gridFromHost(host, DeviceStep::gridVelocityOld);
                dev.gradient(L, shape, true);
                break;
            case Phase::stress: stressOnDevice(s, dt); break;
            case Phase::scatterForce:
                // The internal force, added here to the gravity already there
                dev.zeroGrid(force);
                dev.p2g(L, shape, false, true, apic, invRho0, grainVolume);
                dev.gridToHost(host, force, true);
                break;
            case Phase::foldForce: foldScatteredForce(s); break;
            case Phase::nodalUpdate: nodalUpdate(s, dt); break;
            case Phase::gather:
                dev.gridFromHost(host, DeviceStep::gridVelocity | (apic ? 0u : unsigned(DeviceStep::gridVelocityOld)));
                dev.g2p(L, shape, apic, s.options.flipRatio, dt);
                dev.synchronise();
                break;
            case Phase::remapMomentum:
                dev.zeroGrid(DeviceStep::gridMomentum);
                dev.p2g(L, shape, false, false, apic, invRho0, grainVolume);
                dev.gridToHost(host, DeviceStep::gridMomentum);
                break;
            case Phase::nodalAfterRemap: nodalAfterRemap(s); break;
            case Phase::gradientFromNew:
                dev.gridFromHost(host, DeviceStep::gridVelocity);
                dev.gradient(L, shape, false);
                dev.synchronise();
                break;
            case Phase::move: moveOnDevice(s, apic, dt); break;
            case Phase::migrate: migrate(s); break;
        }
    }, s.recordPhases);
}

#else

void stepHostAssisted(SystemState&, Real)
{
    // MpmSystem::setup makes no device mirror without CUDA
    throw std::logic_error("the host-assisted cuda step: built without CUDA");
}

#endif // MPM_HAVE_CUDA

} // namespace mpm

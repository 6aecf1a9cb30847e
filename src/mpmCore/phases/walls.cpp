#include "walls.hpp"
#include "halo.hpp"
#include "../kernels/frictionWall.hpp"
#include "../kernels/levelSetWall.hpp"
#include <algorithm>
#include <limits>

namespace mpm {

void foldGhosts(SystemState& s, unsigned what)
{
    const bool mass = what & foldMass, momentum = what & foldMomentum, force = what & foldForce;
    auto& g = s.grid;
    if (mass)
    {
        foldScalar(s, g.mass.data());
        foldScalar(s, g.volume.data());
    }
    if (momentum) foldVector(s, g.momentum);
    if (force) foldVector(s, g.force);
}

void foldScalar(const SystemState& s, Real* a)
{
    // Serial and in a fixed order: an image may receive from several ghosts.
    const auto& ghosts = s.boundary.ghosts();
    for (const Index k : s.region.ghosts()) a[ghosts[k].image] += a[ghosts[k].ghost];
    // Ghosts then hold their image's values (for completeness).
    for (const Index k : s.region.ghosts()) a[ghosts[k].ghost] = a[ghosts[k].image];
}

void foldVector(const SystemState& s, std::array<StaggeredArray<Real>, 3>& a)
{
    const auto& ghosts = s.boundary.ghosts();
    for (const Index k : s.region.ghosts())
    {
        const auto& gh = ghosts[k];
        for (int d = 0; d < 3; ++d) a[d][gh.image] += s.ghostSign[k][d]*a[d][gh.ghost];
    }
}

void fillGhosts(const SystemState& s, std::array<StaggeredArray<Real>, 3>& v)
{
    const auto& ghosts = s.boundary.ghosts();
    for (const Index k : s.region.ghosts())
    {
        const auto& gh = ghosts[k];
        for (int d = 0; d < 3; ++d) v[d][gh.ghost] = s.ghostSign[k][d]*v[d][gh.image];
    }
    // Free nodes beyond an inlet carry the inlet velocity. Only those with
    // material: a node without is outside the active region, which must
    // stay zero (and no stencil with weight reads it).
    const auto& conditions = s.boundary.spec().conditions;
    for (const auto& in : s.boundary.inletNodes())
    {
        if (s.grid.mass[in.node] <= s.massTolerance) continue;
        for (int d = 0; d < 3; ++d) v[d][in.node] = conditions[in.condition].velocity[d];
    }
    copyHalo(s, {v[0].data(), v[1].data(), v[2].data()});
}

namespace {

// Friction walls in contact: a node that sticks (frictionSticks) has its
// wall's ghosts mirror it as a noSlip wall's do this step; wallStuck marks
// it so that applyFriction leaves it alone. Before the momentum fold.
void decideFrictionStick(SystemState& s, Real dt, bool withForce)
{
    if (!s.boundary.hasFriction()) return;
    const auto& ghosts = s.boundary.ghosts();
    const auto& active = s.region.ghosts();
    for (auto& a : s.wallStuck) a.assign(s.lattice.nNodes, 0.0);
    const Real cap = s.frictionCap;   // decideWallContact
    const GridView g = gridView(s.grid);
    const Real gravity[3] = {s.options.gravity[0], s.options.gravity[1], s.options.gravity[2]};
    for (const Index k : active)
    {
        const auto& gh = ghosts[k];
        const int a = gh.unilateralAxis;
        if (!(gh.mu > 0) || s.ghostSign[k][a] > 0) continue;   // no friction, or no contact
        if (!frictionSticks(g, gh.image, a, gh.outward, std::min(gh.mu, cap), dt, withForce, gravity)) continue;
        for (int d = 0; d < 3; ++d) if (d != a) s.ghostSign[k][d] = -1.0;
        s.wallStuck[a][gh.image] = 1.0;
    }
}

} // namespace

// With the wall's normal reflection left out, would the node's material
// move towards the wall over this step (momentum + dt (force + m g))? If
// so the mirror holds it (contact); if not, the normal component is
// extended evenly and the wall is invisible, so material can leave. Mass
// must already be folded.
void decideWallContact(SystemState& s, Real dt, bool withForce)
{
    const auto& ghosts = s.boundary.ghosts();
    const auto& active = s.region.ghosts();
    s.ghostSign.resize(ghosts.size());
    for (const Index k : active) s.ghostSign[k] = ghosts[k].sign;

    auto& trial = s.nodeScratch;
    for (auto& a : trial) a.resize(s.lattice.nNodes);
    const auto& g = s.grid;
    auto term = [&](int a, Index I) { return g.momentum[a][I] + (withForce ? dt*g.force[a][I] : 0.0); };
    for (const Index k : active)
    {
        const auto& gh = ghosts[k];
        if (gh.unilateralAxis < 0) continue;
        const int a = gh.unilateralAxis;
        // The force includes gravity when given; otherwise add it here.
        trial[a][gh.image] = term(a, gh.image) + (withForce ? 0.0 : dt*g.mass[gh.image]*s.options.gravity[a]);
    }
    for (const Index k : active)
    {
        const auto& gh = ghosts[k];
        if (gh.unilateralAxis >= 0) trial[gh.unilateralAxis][gh.image] += term(gh.unilateralAxis, gh.ghost);
    }
    for (const Index k : active)
    {
        const auto& gh = ghosts[k];
        if (gh.unilateralAxis < 0) continue;
        const bool contact = trial[gh.unilateralAxis][gh.image]*gh.outward >= 0;
        if (!contact) s.ghostSign[k][gh.unilateralAxis] = 1.0;
    }
    // The friction walls' cap for this step, box and level-set walls alike
    if (largestWallFriction(s) > 0) s.frictionCap = computeFrictionCap(s);
    decideFrictionStick(s, dt, withForce);
}

void applyFriction(SystemState& s, std::array<StaggeredArray<Real>, 3>& v, Real dt)
{
    // Coulomb contact of friction walls (kernels/frictionWall.hpp), per
    // image node and wall. The wall pushes in two ways: by the mirror fold
    // of its contact ghosts, and on the first node layer by removing a
    // normal velocity still approaching the wall. The fold does most of the
    // work, so a bound taken from the second alone gave a fraction of mu
    // (tests/unit/frictionWallTest.cpp). The ghosts still hold their own
    // momentum and force after the fold. Nodes that stick this step
    // (decideFrictionStick) are the noSlip wall's and are left alone.
    const auto& ghosts = s.boundary.ghosts();
    const GridView g = gridView(s.grid);
    auto& J = s.wallImpulse;
    const auto& stuck = s.wallStuck;
    for (auto& a : J) a.resize(s.lattice.nNodes, 0.0);   // zero between calls
    Real* const Jp[3] = {J[0].data(), J[1].data(), J[2].data()};
    Real* const vp[3] = {v[0].data(), v[1].data(), v[2].data()};
    for (const Index k : s.region.ghosts())
    {
        const auto& gh = ghosts[k];
        const int a = gh.unilateralAxis;
        // no friction, no contact, or stuck (the noSlip mirror did the work)
        if (gh.mu <= 0 || s.ghostSign[k][a] > 0 || stuck[a][gh.image] > 0) continue;
        J[a][gh.image] += frictionGhostImpulse(g, gh.ghost, a, gh.outward, dt);
    }
    const Real tol = s.massTolerance;
    const Real cap = s.frictionCap;   // this step's (decideFrictionStick)
    for (const auto& fn : s.boundary.frictionNodes())
    {
        if (stuck[fn.axis][fn.node] > 0) continue;
        frictionFirstLayer(Jp, g.mass, vp, tol, fn.node, fn.axis, fn.outward, std::min(fn.mu, cap));
    }
    for (const Index k : s.region.ghosts())
    {
        const auto& gh = ghosts[k];
        if (gh.mu > 0) frictionSlide(Jp, g.mass, vp, tol, gh.image, gh.unilateralAxis, std::min(gh.mu, cap));
    }
}

Real largestWallFriction(const SystemState& s)
{
    Real most = 0;
    for (const auto& wc : s.boundary.spec().conditions)
    {
        if (wc.type == WallType::friction) most = std::max(most, wc.frictionCoefficient);
    }
    for (const auto& w : s.levelSet.walls())
    {
        if (w.condition.type == WallType::friction) most = std::max(most, w.condition.frictionCoefficient);
    }
    return most;
}

// A friction wall holds the material at most as hard as the material's own
// friction (ConstitutiveLaw::shearStrengthRatio, the largest of the
// materials that have points, on any rank): the wall's traction acts on
// the first node layers, and the material between them and the wall
// yields at its own friction first. A rougher wall is then that wall: a
// granular layer on a rough incline flows at the rate its own friction
// allows, not the wall's (issue 29).
Real computeFrictionCap(const SystemState& s)
{
    const auto& P = s.particles;
    std::vector<std::int64_t> present(s.materials.size(), 0);
    for (Index p = 0; p < P.size(); ++p) present[P.material[p]] = 1;
    if (s.subdomain && !present.empty())
    {
        s.subdomain->comm().allReduce(present.data(), int(present.size()), ReduceOp::max);
    }
    Real cap = 0;
    bool any = false;
    for (std::size_t m = 0; m < s.materials.size(); ++m)
    {
        if (!present[m]) continue;
        cap = std::max(cap, s.materials[m]->shearStrengthRatio());
        any = true;
    }
    return any ? cap : std::numeric_limits<Real>::infinity();
}

void setLevelSetWalls(SystemState& s, std::vector<LevelSetWall> walls, const std::array<Real, 3>& unsolved)
{
    // The B-splines reach every node within 1.5 (QBS) or 2 (CBS) cells of
    // a point, so a point resting on a wall always weighs on a node inside
    // it. A linear hat reaches one cell: a point just outside a wall whose
    // nearest inside node is almost a cell deep gives it almost no weight,
    // the wall then holds the material only by containment, and friction
    // is lost (a block decelerated at 0.77 mu g on a floor 0.94 h above a
    // node layer). Linear hats therefore also hold the nodes within half a
    // cell outside the wall: an effective wall up to h/2 thicker.
    const Real contact = s.options.shape == ShapeKind::linearHat ? 0.5*s.lattice.h : 0.0;
    s.levelSet.build(s.lattice, std::move(walls), unsolved, contact, &s.domain);
    s.contained = 0;
    s.levelSetChanged = true;
}

void moveLevelSetWalls
(
    SystemState& s,
    const std::vector<std::array<Real, 3>>& displacement,
    const std::vector<std::array<Real, 3>>& velocity
)
{
    s.levelSet.move(s.lattice, displacement, velocity);
    s.levelSetChanged = true;
}

void applyLevelSetWalls(SystemState& s, std::array<StaggeredArray<Real>, 3>& v)
{
    const LevelSetView ls = s.levelSet.view();
    if (!ls) return;
    Real* const vp[3] = {v[0].data(), v[1].data(), v[2].data()};
    const Real* m = s.grid.mass.data();
    const Real tol = s.massTolerance;
    const Real cap = s.frictionCap;   // this step's (decideWallContact)
    s.forEachActiveNode([&](Index I) { levelSetWallNode(ls, m, vp, tol, I, cap); });
}

} // namespace mpm

// MpmSystem's box walls and level-set walls on the grid: the ghost folds
// and fills with the contact decision of unilateral walls, Coulomb
// friction, the level-set node condition (kernels/frictionWall.hpp,
// kernels/levelSetWall.hpp hold the per-node bodies the resident device
// step shares).
#include "mpmSystemLoops.hpp"
#include "../kernels/frictionWall.hpp"
#include "../kernels/levelSetWall.hpp"
#include "../kernels/views.hpp"
#include <algorithm>
#include <limits>

namespace mpm {

void MpmSystem::foldGhosts(unsigned what)
{
    const bool mass = what & foldMass, momentum = what & foldMomentum, force = what & foldForce;
    auto& g = grid_;
    if (mass)
    {
        foldScalar(g.mass);
        foldScalar(g.volume);
    }
    if (momentum) foldVector(g.momentum);
    if (force) foldVector(g.force);
}

void MpmSystem::foldScalar(std::vector<Real>& a) const
{
    // Serial and in a fixed order: an image may receive from several ghosts.
    const auto& ghosts = boundary_.ghosts();
    for (const Index k : region_.ghosts()) a[ghosts[k].image] += a[ghosts[k].ghost];
    // Ghosts then hold their image's values (for completeness).
    for (const Index k : region_.ghosts()) a[ghosts[k].ghost] = a[ghosts[k].image];
}

// Contact of unilateral (slip, friction) walls, per image node: with the
// wall's normal reflection left out, would the node's material move towards
// the wall over this step (momentum + dt (force + m g))? If so the mirror
// holds it (contact); if not, the normal component is extended evenly and the
// wall is invisible, so material can leave. Mass must already be folded.
void MpmSystem::decideWallContact(Real dt, bool withForce)
{
    const auto& ghosts = boundary_.ghosts();
    const auto& active = region_.ghosts();
    ghostSign_.resize(ghosts.size());
    for (const Index k : active) ghostSign_[k] = ghosts[k].sign;

    auto& trial = nodeScratch_;
    for (auto& a : trial) a.resize(lattice_.nNodes);
    const auto& g = grid_;
    auto term = [&](int a, Index I) { return g.momentum[a][I] + (withForce ? dt*g.force[a][I] : 0.0); };
    for (const Index k : active)
    {
        const auto& gh = ghosts[k];
        if (gh.unilateralAxis < 0) continue;
        const int a = gh.unilateralAxis;
        // The force includes gravity when given; otherwise add it here.
        trial[a][gh.image] = term(a, gh.image) + (withForce ? 0.0 : dt*g.mass[gh.image]*options_.gravity[a]);
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
        if (!contact) ghostSign_[k][gh.unilateralAxis] = 1.0;
    }
    // The friction walls' cap for this step, box and level-set walls alike
    if (largestWallFriction() > 0) frictionCap_ = computeFrictionCap();
    decideFrictionStick(dt, withForce);
}

Real MpmSystem::largestWallFriction() const
{
    Real most = 0;
    for (const auto& wc : boundary_.spec().conditions)
    {
        if (wc.type == WallType::friction) most = std::max(most, wc.frictionCoefficient);
    }
    for (const auto& w : levelSet_.walls())
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
Real MpmSystem::computeFrictionCap() const
{
    const auto& P = particles_;
    std::vector<std::int64_t> present(materials_.size(), 0);
    for (Index p = 0; p < P.size(); ++p) present[P.material[p]] = 1;
    if (subdomain_ && !present.empty())
    {
        subdomain_->comm().allReduce(present.data(), int(present.size()), ReduceOp::max);
    }
    Real cap = 0;
    bool any = false;
    for (std::size_t m = 0; m < materials_.size(); ++m)
    {
        if (!present[m]) continue;
        cap = std::max(cap, materials_[m]->shearStrengthRatio());
        any = true;
    }
    return any ? cap : std::numeric_limits<Real>::infinity();
}

// Friction walls in contact: a node that sticks (frictionSticks) has its
// wall's ghosts mirror it as a noSlip wall's do this step; wallStuck_ marks
// it so that applyFriction leaves it alone. Before the momentum fold.
void MpmSystem::decideFrictionStick(Real dt, bool withForce)
{
    if (!boundary_.hasFriction()) return;
    const auto& ghosts = boundary_.ghosts();
    const auto& active = region_.ghosts();
    for (auto& a : wallStuck_) a.assign(lattice_.nNodes, 0.0);
    const Real cap = frictionCap_;   // decideWallContact
    const GridView g = gridView(grid_);
    const Real gravity[3] = {options_.gravity[0], options_.gravity[1], options_.gravity[2]};
    for (const Index k : active)
    {
        const auto& gh = ghosts[k];
        const int a = gh.unilateralAxis;
        if (!(gh.mu > 0) || ghostSign_[k][a] > 0) continue;   // no friction, or no contact
        if (!frictionSticks(g, gh.image, a, gh.outward, std::min(gh.mu, cap), dt, withForce, gravity)) continue;
        for (int d = 0; d < 3; ++d) if (d != a) ghostSign_[k][d] = -1.0;
        wallStuck_[a][gh.image] = 1.0;
    }
}

void MpmSystem::foldVector(std::array<std::vector<Real>, 3>& a) const
{
    const auto& ghosts = boundary_.ghosts();
    for (const Index k : region_.ghosts())
    {
        const auto& gh = ghosts[k];
        for (int d = 0; d < 3; ++d) a[d][gh.image] += ghostSign_[k][d]*a[d][gh.ghost];
    }
}

void MpmSystem::fillGhosts(std::array<std::vector<Real>, 3>& v) const
{
    const auto& ghosts = boundary_.ghosts();
    for (const Index k : region_.ghosts())
    {
        const auto& gh = ghosts[k];
        for (int d = 0; d < 3; ++d) v[d][gh.ghost] = ghostSign_[k][d]*v[d][gh.image];
    }
    // Free nodes beyond an inlet carry the inlet velocity. Only those with
    // material: a node without is outside the active region, which must
    // stay zero (and no stencil with weight reads it).
    const auto& conditions = boundary_.spec().conditions;
    for (const auto& in : boundary_.inletNodes())
    {
        if (grid_.mass[in.node] <= massTolerance_) continue;
        for (int d = 0; d < 3; ++d) v[d][in.node] = conditions[in.condition].velocity[d];
    }
    copyHalo({v[0].data(), v[1].data(), v[2].data()});
}

void MpmSystem::applyFriction(std::array<std::vector<Real>, 3>& v, Real dt)
{
    // Coulomb contact of friction walls (kernels/frictionWall.hpp), per
    // image node and wall. The wall pushes in two ways: by the mirror fold
    // of its contact ghosts, and on the first node layer by removing a
    // normal velocity still approaching the wall. The fold does most of the
    // work, so a bound taken from the second alone gave a fraction of mu
    // (tests/unit/frictionWallTest.cpp). The ghosts still hold their own
    // momentum and force after the fold. Nodes that stick this step
    // (decideFrictionStick) are the noSlip wall's and are left alone.
    const auto& ghosts = boundary_.ghosts();
    const GridView g = gridView(grid_);
    auto& J = wallImpulse_;
    for (auto& a : J) a.resize(lattice_.nNodes, 0.0);   // zero between calls
    Real* const Jp[3] = {J[0].data(), J[1].data(), J[2].data()};
    Real* const vp[3] = {v[0].data(), v[1].data(), v[2].data()};
    for (const Index k : region_.ghosts())
    {
        const auto& gh = ghosts[k];
        const int a = gh.unilateralAxis;
        // no friction, no contact, or stuck (the noSlip mirror did the work)
        if (gh.mu <= 0 || ghostSign_[k][a] > 0 || wallStuck_[a][gh.image] > 0) continue;
        J[a][gh.image] += frictionGhostImpulse(g, gh.ghost, a, gh.outward, dt);
    }
    const Real tol = massTolerance_;
    const Real cap = frictionCap_;   // this step's (decideFrictionStick)
    for (const auto& fn : boundary_.frictionNodes())
    {
        if (wallStuck_[fn.axis][fn.node] > 0) continue;
        frictionFirstLayer(Jp, g.mass, vp, tol, fn.node, fn.axis, fn.outward, std::min(fn.mu, cap));
    }
    for (const Index k : region_.ghosts())
    {
        const auto& gh = ghosts[k];
        if (gh.mu > 0) frictionSlide(Jp, g.mass, vp, tol, gh.image, gh.unilateralAxis, std::min(gh.mu, cap));
    }
}

void MpmSystem::setLevelSetWalls(std::vector<LevelSetWall> walls, const std::array<Real, 3>& unsolved)
{
    // The B-splines reach every node within 1.5 (QBS) or 2 (CBS) cells of
    // a point, so a point resting on a wall always weighs on a node inside
    // it. A linear hat reaches one cell: a point just outside a wall whose
    // nearest inside node is almost a cell deep gives it almost no weight,
    // the wall then holds the material only by containment, and friction
    // is lost (a block decelerated at 0.77 mu g on a floor 0.94 h above a
    // node layer). Linear hats therefore also hold the nodes within half a
    // cell outside the wall: an effective wall up to h/2 thicker.
    const Real contact = options_.shape == ShapeKind::linearHat ? 0.5*lattice_.h : 0.0;
    levelSet_.build(lattice_, std::move(walls), unsolved, contact, &domain_);
    contained_ = 0;
    levelSetChanged_ = true;
}

void MpmSystem::moveLevelSetWalls
(
    const std::vector<std::array<Real, 3>>& displacement,
    const std::vector<std::array<Real, 3>>& velocity
)
{
    levelSet_.move(lattice_, displacement, velocity);
    levelSetChanged_ = true;
}

void MpmSystem::applyLevelSetWalls(std::array<std::vector<Real>, 3>& v)
{
    const LevelSetView ls = levelSet_.view();
    if (!ls) return;
    Real* const vp[3] = {v[0].data(), v[1].data(), v[2].data()};
    const Real* m = grid_.mass.data();
    const Real tol = massTolerance_;
    const Real cap = frictionCap_;   // this step's (decideWallContact)
    forEachActiveNode([&](Index I) { levelSetWallNode(ls, m, vp, tol, I, cap); });
}

} // namespace mpm

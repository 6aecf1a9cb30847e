#include "levelSet.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mpm {

namespace {

using Vec = std::array<Real, 3>;

Real dot(const Real* a, const Real* b) { return a[0]*b[0] + a[1]*b[1] + a[2]*b[2]; }

Vec unit(const Vec& v, const char* what)
{
    const Real m = std::sqrt(dot(v.data(), v.data()));
    if (!(m > 0)) throw std::invalid_argument(std::string(what) + " must not be zero");
    return {v[0]/m, v[1]/m, v[2]/m};
}

std::string str(const Vec& v)
{
    std::ostringstream os;
    os << '(' << v[0] << ' ' << v[1] << ' ' << v[2] << ')';
    return os.str();
}

// Unit vector of d, or `fallback` where d vanishes (x on a centre or axis)
void direction(const Real d[3], const Real* fallback, Real n[3])
{
    const Real m = std::sqrt(dot(d, d));
    for (int a = 0; a < 3; ++a) n[a] = m > 0 ? d[a]/m : fallback[a];
}

} // namespace

HalfSpaceShape::HalfSpaceShape(const Vec& point, const Vec& normal)
:
    p_(point), n_(unit(normal, "plane normal"))
{}

Real HalfSpaceShape::distance(const Real x[3], Real normal[3], Real) const
{
    for (int a = 0; a < 3; ++a) normal[a] = n_[a];
    const Real d[3] = {x[0] - p_[0], x[1] - p_[1], x[2] - p_[2]};
    return dot(d, n_.data());
}

std::string HalfSpaceShape::describe() const
{
    return "plane through " + str(p_) + ", material towards " + str(n_);
}

SphereShape::SphereShape(const Vec& centre, Real radius)
:
    c_(centre), r_(radius)
{
    if (!(radius > 0)) throw std::invalid_argument("sphere radius must be positive");
}

Real SphereShape::distance(const Real x[3], Real normal[3], Real) const
{
    const Real d[3] = {x[0] - c_[0], x[1] - c_[1], x[2] - c_[2]};
    static const Real up[3] = {0, 0, 1};
    direction(d, up, normal);
    return std::sqrt(dot(d, d)) - r_;
}

std::string SphereShape::describe() const
{
    std::ostringstream os;
    os << "sphere, centre " << str(c_) << ", radius " << r_;
    return os.str();
}

CylinderShape::CylinderShape(const Vec& p0, const Vec& p1, Real radius)
:
    p0_(p0), r_(radius)
{
    const Vec d{p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    length_ = std::sqrt(dot(d.data(), d.data()));
    axis_ = unit(d, "cylinder axis (point2 - point1)");
    if (!(radius > 0)) throw std::invalid_argument("cylinder radius must be positive");
}

// Distance to a finite solid cylinder: the radial and axial excesses
// combine as for a box (inside: the smaller of the two depths).
Real CylinderShape::distance(const Real x[3], Real normal[3], Real) const
{
    const Real d[3] = {x[0] - p0_[0], x[1] - p0_[1], x[2] - p0_[2]};
    const Real s = dot(d, axis_.data());                 // along the axis
    Real radial[3];
    for (int a = 0; a < 3; ++a) radial[a] = d[a] - s*axis_[a];
    const Real rho = std::sqrt(dot(radial, radial));
    // Any direction normal to the axis where x lies on it
    Real any[3] = {axis_[1], -axis_[0], 0};
    if (dot(any, any) < 1e-12) { any[0] = 0; any[1] = axis_[2]; any[2] = -axis_[1]; }
    direction(any, any, any);
    Real er[3];
    direction(radial, any, er);
    const Real dr = rho - r_;                            // > 0 outside the mantle
    const Real ds = std::max(-s, s - length_);           // > 0 beyond an end
    const Real sign = s < 0.5*length_ ? -1 : 1;          // the nearer end's side
    if (dr <= 0 && ds <= 0)
    {
        // Inside: leave through the nearer of the mantle and the ends
        if (dr >= ds) { for (int a = 0; a < 3; ++a) normal[a] = er[a]; return dr; }
        for (int a = 0; a < 3; ++a) normal[a] = sign*axis_[a];
        return ds;
    }
    const Real pr = std::max(dr, Real(0)), ps = std::max(ds, Real(0));
    Real v[3];
    for (int a = 0; a < 3; ++a) v[a] = pr*er[a] + ps*sign*axis_[a];
    direction(v, er, normal);
    return std::sqrt(pr*pr + ps*ps);
}

std::string CylinderShape::describe() const
{
    std::ostringstream os;
    const Vec p1{p0_[0] + length_*axis_[0], p0_[1] + length_*axis_[1], p0_[2] + length_*axis_[2]};
    os << "cylinder from " << str(p0_) << " to " << str(p1) << ", radius " << r_;
    return os.str();
}

BoxShape::BoxShape(const Vec& min, const Vec& max)
:
    lo_(min), hi_(max)
{
    for (int a = 0; a < 3; ++a)
    {
        if (!(max[a] > min[a])) throw std::invalid_argument("box max must exceed min in every direction");
    }
}

Real BoxShape::distance(const Real x[3], Real normal[3], Real) const
{
    Real q[3], depth = -std::numeric_limits<Real>::max();
    int deepAxis = 0;
    Real deepSign = 1;
    for (int a = 0; a < 3; ++a)
    {
        const Real below = lo_[a] - x[a], above = x[a] - hi_[a];
        q[a] = below > 0 ? -below : (above > 0 ? above : 0);
        const Real e = std::max(below, above);           // < 0 inside along a
        if (e > depth) { depth = e; deepAxis = a; deepSign = above > below ? 1 : -1; }
    }
    if (depth <= 0)
    {
        for (int a = 0; a < 3; ++a) normal[a] = a == deepAxis ? deepSign : 0;
        return depth;
    }
    const Real fallback[3] = {0, 0, 1};
    direction(q, fallback, normal);
    return std::sqrt(dot(q, q));
}

std::string BoxShape::describe() const
{
    return "box from " + str(lo_) + " to " + str(hi_);
}

void LevelSetWalls::build
(
    const Lattice& L, std::vector<LevelSetWall> walls, const Vec& unsolved, Real contact,
    const Lattice* domain
)
{
    const Lattice& D = domain ? *domain : L;
    for (int a = 0; a < 3; ++a)
    {
        domainLo_[a] = D.origin[a];
        domainHi_[a] = D.origin[a] + D.nCells[a]*D.h;
    }
    walls_ = std::move(walls);
    contact_ = contact;
    type_.clear();
    mu_.clear();
    hasOutlets_ = false;
    for (const auto& w : walls_)
    {
        const WallType t = w.condition.type;
        if (!w.shape)
        {
            throw std::invalid_argument("level-set wall " + w.name + " has no shape");
        }
        if (t == WallType::periodic)
        {
            throw std::invalid_argument
            (
                "level-set wall " + w.name + ": type " + wallTypeName(t)
              + " is not a wall condition (valid: noSlip slip friction outlet inlet)"
            );
        }
        if (isOpen(t) && w.specCondition < 0)
        {
            throw std::invalid_argument("level-set " + std::string(wallTypeName(t)) + " " + w.name + " has no boundary condition index");
        }
        type_.push_back(int(t));
        mu_.push_back(t == WallType::friction ? w.condition.frictionCoefficient : 0.0);
        hasOutlets_ = hasOutlets_ || isOpen(t);
    }
    nInside_ = 0;
    if (walls_.empty())
    {
        phi_.clear();
        for (auto& n : normal_) n.clear();
        wall_.clear();
        return;
    }
    // Nodes further than a few cells from every wall need only the sign:
    // the widest stencil (CBS) reaches two cells, a point's planes one more.
    band_ = 4*L.h;
    // A noSlip wall stops the nodes within one cell outside it moving away
    // from it (kernels/levelSetWall.hpp says why)
    normalHold_ = L.h;
    unsolved_ = unsolved;
    for (auto& a : velocity_) a.assign(walls_.size(), 0.0);
    setInletVelocities(L);
    displacement_.assign(walls_.size(), Vec{0, 0, 0});
    computeNodes(L);
}

void LevelSetWalls::setInletVelocities(const Lattice& L)
{
    // An inlet does not move: its velocity is the entering material's, the
    // value its nodes get (kernels/levelSetWall.hpp)
    for (std::size_t w = 0; w < walls_.size(); ++w)
    {
        if (walls_[w].condition.type != WallType::inlet) continue;
        for (int a = 0; a < 3; ++a) velocity_[a][w] = L.solved[a] ? walls_[w].condition.velocity[a] : 0;
    }
}

void LevelSetWalls::move(const Lattice& L, const std::vector<Vec>& displacement, const std::vector<Vec>& velocity)
{
    if (displacement.size() != walls_.size() || velocity.size() != walls_.size())
    {
        throw std::invalid_argument("level-set walls: one displacement and velocity per wall");
    }
    displacement_ = displacement;
    for (std::size_t w = 0; w < walls_.size(); ++w)
    {
        for (int a = 0; a < 3; ++a) velocity_[a][w] = L.solved[a] ? velocity[w][a] : 0;
    }
    setInletVelocities(L);
    computeNodes(L);
}

void LevelSetWalls::computeNodes(const Lattice& L)
{
    const Vec& unsolved = unsolved_;
    nInside_ = 0;
    const Index n = L.nNodes;
    phi_.assign(n, 0);
    for (auto& a : normal_) a.assign(n, 0);
    wall_.assign(n, 0);
    // Serial: a shape may wrap a library that is not thread-safe (STL)
    for (Index I = 0; I < n; ++I)
    {
        const int idx[3] = {int(I % L.nodes[0]), int((I/L.nodes[0]) % L.nodes[1]), int(I/L.stride[2])};
        Real x[3];
        bool beyondBox = false;
        for (int a = 0; a < 3; ++a)
        {
            x[a] = L.solved[a] ? L.origin[a] + (idx[a] - L.padOf(a) + 0.5)*L.h : unsolved[a];
            beyondBox = beyondBox || (L.solved[a] && (x[a] < domainLo_[a] || x[a] > domainHi_[a]));
        }
        // The ghost layers beyond the domain lattice's box belong to the
        // box's own conditions (mirrored walls, open or periodic faces),
        // which set them after the level-set condition. As level-set nodes
        // they would lie outside the mesh, hence inside its patches' wall
        // (negative), with the plane of whatever level-set patch is
        // nearest: beside a box face kept as a mirrored wall, that plane
        // pushed the points next to the face up to a band's width along
        // it (a bed under a pier on a snappyHexMesh). Outside every wall.
        if (beyondBox)
        {
            phi_[I] = band_;
            for (int a = 0; a < 3; ++a) normal_[a][I] = 0;
            wall_[I] = 0;
            continue;
        }
        Real bestN[3] = {0, 0, 0};
        int bestW = 0;
        const Real best = nearest(x, band_, bestN, bestW);
        // Unsolved axes carry no motion: the normal lies in the solved plane
        Real m2 = 0;
        for (int a = 0; a < 3; ++a) { if (!L.solved[a]) bestN[a] = 0; m2 += bestN[a]*bestN[a]; }
        const Real m = std::sqrt(m2);
        for (int a = 0; a < 3; ++a) normal_[a][I] = m > 0 ? bestN[a]/m : 0;
        phi_[I] = best;
        wall_[I] = bestW;
        nInside_ += best < 0;
    }
}

LevelSetView LevelSetWalls::view() const
{
    LevelSetView v;
    if (walls_.empty()) return v;
    v.phi = phi_.data();
    for (int a = 0; a < 3; ++a) v.normal[a] = normal_[a].data();
    v.wall = wall_.data();
    v.type = type_.data();
    v.mu = mu_.data();
    v.band = band_;
    v.contact = contact_;
    v.normalHold = normalHold_;
    for (int a = 0; a < 3; ++a) v.velocity[a] = velocity_[a].data();
    return v;
}

Real LevelSetWalls::nearest(const Real x[3], Real band, Real normal[3], int& wall) const
{
    // Per group: the part nearest to x (smallest |d|); over the groups:
    // the smallest d
    Real best = std::numeric_limits<Real>::max();
    wall = -1;
    for (std::size_t w = 0; w < walls_.size(); ++w)
    {
        const void* g = walls_[w].shape->group();
        bool first = true;
        for (std::size_t v = 0; v < w && first; ++v) first = walls_[v].shape->group() != g;
        if (!first) continue;
        Real gd = 0, gn[3] = {0, 0, 0};
        int gw = -1;
        for (std::size_t v = w; v < walls_.size(); ++v)
        {
            if (walls_[v].shape->group() != g) continue;
            Real nrm[3];
            // A moving wall: its shape taken back by its displacement
            const Vec& dv = displacement_.empty() ? Vec{0, 0, 0} : displacement_[v];
            const Real xs[3] = {x[0] - dv[0], x[1] - dv[1], x[2] - dv[2]};
            const Real d = walls_[v].shape->distance(xs, nrm, band);
            if (gw < 0 || std::abs(d) < std::abs(gd))
            {
                gd = d; gw = int(v);
                for (int a = 0; a < 3; ++a) gn[a] = nrm[a];
            }
        }
        if (gd < best)
        {
            best = gd; wall = gw;
            for (int a = 0; a < 3; ++a) normal[a] = gn[a];
        }
    }
    return best;
}

Real LevelSetWalls::distance(const Real x[3], int* wall) const
{
    Real n[3];
    int w = -1;
    // Any distance: a band far beyond any domain, whose square is finite
    const Real d = walls_.empty() ? std::numeric_limits<Real>::max() : nearest(x, 1e100, n, w);
    if (wall) *wall = w;
    return d;
}

} // namespace mpm

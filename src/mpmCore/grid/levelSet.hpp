// Walls of any shape, as a level set on the lattice nodes.
//
// Each wall is a shape (a plane, a sphere, a cylinder, a box, or an STL
// surface from the OpenFOAM layer) that gives the signed distance of a
// position to its surface: positive on the material's side, negative inside
// the wall. At setup every node of the lattice stores the distance to the
// nearest wall, that wall's unit normal (pointing into the material's side)
// and which wall it is: a node's closest-point plane. The step then needs no
// geometry, only these node arrays, so the same kernel bodies run on every
// back-end (kernels/levelSetWall.hpp):
//   * the node condition: a node inside a wall (phi < 0; linear hats:
//     phi < h/2, below) that carries
//     material gets the wall's condition on its updated velocity (noSlip:
//     zero; slip and friction: unilateral, only while the node approaches
//     the wall; friction: Coulomb, the tangential speed reduced by mu times
//     the normal speed removed);
//   * containment: a point that ends a step inside a wall is put back on
//     its surface along the normal, its approaching normal velocity removed;
//     inside an outlet (a mesh's outlet patch off the box's sides) it
//     leaves the domain instead.
//     A point is tested against the closest-point planes of the nodes
//     around it, so a convex wall is never entered (its tangent planes all
//     hold it outside). Counted, per rank.
// Level-set walls are independent of the box's mirrored walls
// (grid/boundary.hpp) and act together with them. docs/geometry.md.
#pragma once
#include "../common/hostDevice.hpp"
#include "boundary.hpp"
#include "lattice.hpp"
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace mpm {

// A wall surface: the signed distance from x, positive on the material's
// side, and the unit normal of the nearest surface point pointing into the
// material's side. Beyond `band` from the surface a shape may return any
// distance of at least band in magnitude, with the right sign, and any unit
// normal (only nodes near a wall need their plane).
class WallShape
{
public:
    virtual ~WallShape() = default;
    virtual Real distance(const Real x[3], Real normal[3], Real band) const = 0;
    // One line for the log
    virtual std::string describe() const = 0;
    // Walls of one group are parts of one surface that share its sign (a
    // mesh's wall patches): the nearest part gives the distance. Separate
    // groups (obstacles) are solids: the smallest distance wins (inside
    // any, the deepest). Each shape is its own group unless it says so.
    virtual const void* group() const { return this; }
};

// A plane: the material lies on the side its normal points to.
class HalfSpaceShape : public WallShape
{
public:
    HalfSpaceShape(const std::array<Real, 3>& point, const std::array<Real, 3>& normal);
    Real distance(const Real x[3], Real normal[3], Real band) const override;
    std::string describe() const override;
private:
    std::array<Real, 3> p_, n_;
};

// A solid ball; the material is outside it.
class SphereShape : public WallShape
{
public:
    SphereShape(const std::array<Real, 3>& centre, Real radius);
    Real distance(const Real x[3], Real normal[3], Real band) const override;
    std::string describe() const override;
private:
    std::array<Real, 3> c_;
    Real r_;
};

// A solid cylinder of radius r between the end centres p0 and p1 (flat
// ends); the material is outside it.
class CylinderShape : public WallShape
{
public:
    CylinderShape(const std::array<Real, 3>& p0, const std::array<Real, 3>& p1, Real radius);
    Real distance(const Real x[3], Real normal[3], Real band) const override;
    std::string describe() const override;
private:
    std::array<Real, 3> p0_, axis_;
    Real length_, r_;
};

// A solid axis-aligned box [min, max]; the material is outside it.
class BoxShape : public WallShape
{
public:
    BoxShape(const std::array<Real, 3>& min, const std::array<Real, 3>& max);
    Real distance(const Real x[3], Real normal[3], Real band) const override;
    std::string describe() const override;
private:
    std::array<Real, 3> lo_, hi_;
};

struct LevelSetWall
{
    std::string name;
    std::shared_ptr<const WallShape> shape;
    // noSlip, slip or friction (with its frictionCoefficient), outlet: no
    // node condition, and a point that crosses it leaves the domain, or
    // inlet (a mesh's inlet patch off the box's sides): its nodes with
    // material get its velocity, and a point that crosses it outwards
    // leaves as at an outlet (the points entering are added by the
    // OpenFOAM layer, openBoundaries)
    WallCondition condition;
    // An open wall's condition index in the BoundarySpec: the removed
    // count and mass are booked there (MpmSystem::removedCount), as for an
    // open patch on a side of the box
    int specCondition = -1;
};

// The node arrays the kernels read (raw pointers: copyable to a device).
struct LevelSetView
{
    const Real* phi = nullptr;          // signed distance at each node
    const Real* normal[3] = {};         // into the material's side
    const int* wall = nullptr;          // the nearest wall's index
    const int* type = nullptr;          // per wall: WallType as int
    const Real* mu = nullptr;           // per wall: Coulomb coefficient
    Real band = 0;                      // beyond it phi is only a bound
    Real contact = 0;                   // nodes with phi below it are held
    Real normalHold = 0;                // noSlip: nodes with phi below it do not move away from the wall
    const Real* velocity[3] = {};       // per wall: its velocity (moving; an inlet's: the entering material's)
    MPM_HOST_DEVICE explicit operator bool() const { return phi != nullptr; }
};

class LevelSetWalls
{
public:
    // The node planes of every node of L (ghost layers included).
    // unsolved: the coordinate given to the shapes along unsolved axes (a
    // 2D case's mid-plane). Throws std::invalid_argument for a wall whose
    // condition is periodic, for an outlet or inlet without its
    // specCondition, or without a shape.
    // contact: nodes with phi below it get the wall condition (0: the
    // nodes inside the walls; see MpmSystem::setLevelSetWalls).
    // domain: the whole (undecomposed) lattice, whose box's ghost layers
    // are no level-set nodes (computeNodes says why); by default L.
    void build
    (
        const Lattice& L, std::vector<LevelSetWall> walls, const std::array<Real, 3>& unsolved,
        Real contact = 0, const Lattice* domain = nullptr
    );

    // The node planes again on another lattice of the same domain (a
    // decomposed run's new box after a rebalance), the walls where they
    // are now
    void relocate(const Lattice& L) { if (!walls_.empty()) computeNodes(L); }

    bool empty() const { return walls_.empty(); }
    // Whether any wall is open (points may leave through it)
    bool hasOutlets() const { return hasOutlets_; }
    const std::vector<LevelSetWall>& walls() const { return walls_; }
    // Empty view (false) without walls
    LevelSetView view() const;

    // Moving walls (translations): each wall's displacement from where its
    // shape puts it, and its velocity over the coming step; the node
    // planes are computed again there (every node, every wall: a step's
    // cost of O(nodes x walls), paid only by cases with moving walls)
    void move
    (
        const Lattice& L, const std::vector<std::array<Real, 3>>& displacement,
        const std::vector<std::array<Real, 3>>& velocity
    );

    // The exact signed distance to the nearest wall at x (min over the
    // shapes), for checks of seeded points; wall: which one (or -1)
    Real distance(const Real x[3], int* wall = nullptr) const;

    // The signed distance at x and the nearest wall's normal and index,
    // combining the walls by groups (WallShape::group)
    Real nearest(const Real x[3], Real band, Real normal[3], int& wall) const;

    // Nodes inside walls (phi < 0) of the lattice, for the log
    Index nodesInside() const { return nInside_; }

private:
    std::vector<LevelSetWall> walls_;
    std::vector<Real> phi_;
    std::array<std::vector<Real>, 3> normal_;
    std::vector<int> wall_;
    std::vector<int> type_;
    std::vector<Real> mu_;
    Real band_ = 0;
    Real contact_ = 0;
    Real normalHold_ = 0;
    Index nInside_ = 0;
    bool hasOutlets_ = false;
    std::array<Real, 3> unsolved_{0, 0, 0};
    std::array<Real, 3> domainLo_{0, 0, 0}, domainHi_{0, 0, 0};   // the domain lattice's box
    std::vector<std::array<Real, 3>> displacement_;
    std::array<std::vector<Real>, 3> velocity_;
    void computeNodes(const Lattice& L);
    // velocity_ of the inlets: their entering material's
    void setInletVelocities(const Lattice& L);
};

} // namespace mpm

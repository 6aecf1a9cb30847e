// Wall and periodic conditions on the lattice, by mirrored ghost nodes.
//
// Nodes sit at cell centres, so a wall lies half a spacing outside the first
// node layer. Each ghost node is the mirror image of a real node across the
// wall (or its periodic partner). The step
//   1. scatters to real and ghost nodes alike,
//   2. folds every ghost back onto its image: mass and volume add, momentum
//      and force add with the reflection sign (the contribution of a mirror
//      particle), then
//   3. after the nodal update, fills the ghosts from their images again.
// The result is the velocity field's odd (no-slip) or normal-odd (slip)
// extension, so the wall condition holds exactly on the wall plane for every
// B-spline order without modifying the splines. Coulomb friction adds a
// contact correction on the first node layer. slip and friction walls are
// unilateral: material moving away from the wall sees no mirror in the
// normal direction (contact is decided per node and step), so bodies can
// leave a wall; noSlip walls hold the material (sticky). See
// docs/gridDesign.md.
//
// Open faces (outlet, inlet) have no mirror: the ghost layers beyond them
// are free nodes, updated like real ones, so the lattice continues through
// the face and the material there feels no wall (zero traction). A point
// that crosses an open face leaves the domain (MpmSystem removes it and
// counts it). Beyond an inlet face the free nodes carrying material get the
// inlet velocity (a Dirichlet band the stencils read). docs/openBoundaries.md.
#pragma once
#include "lattice.hpp"
#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace mpm {

enum class WallType { noSlip = 0, slip = 1, friction = 2, periodic = 3, outlet = 4, inlet = 5 };

// Open faces: material passes through them (no mirror ghost)
inline bool isOpen(WallType t) { return t == WallType::outlet || t == WallType::inlet; }

const char* wallTypeName(WallType t);
bool parseWallType(const std::string& name, WallType& t);
const char* validWallTypeNames();

struct WallCondition
{
    WallType type = WallType::noSlip;
    Real frictionCoefficient = 0;   // Coulomb mu, for WallType::friction
    std::array<Real, 3> velocity{0, 0, 0};   // for WallType::inlet
    // An outlet whose nodes are free but whose points are held as at a
    // wall (exitCondition, phases/movePoints.hpp): the lattice faces
    // beyond a mesh that is not a box ("beyondMesh",
    // src/mpmFoam/boundary/wallConditions.C).
    // Only a point that went through a level-set wall, or through the
    // corner where it meets a mirrored box wall, reaches such a face; held
    // inside the box, the level-set containment then puts it back out of
    // the wall (or books it on a level-set outlet). Let out there, a point
    // sliding into the toe of a level-set slope on a mirrored floor left
    // the domain (tutorials/multiphase/granularSlideWave,
    // tests/cases/levelSetBoxCorner.sh).
    bool holdsPoints = false;
};

// Which condition each boundary face has. Sides are x-, x+, y-, y+, z-, z+.
// Faces of a side are indexed by the real cell indices of the two other
// axes (lower axis fastest). An empty vector means every face of that side
// uses condition 0 of `conditions`.
struct BoundarySpec
{
    std::vector<WallCondition> conditions{WallCondition{}};
    std::array<std::vector<int>, 6> faceCondition;

    int conditionAt(const Lattice& L, int side, int i, int j, int k) const;

    // The condition of the face a position beyond `side` crosses: the
    // other coordinates taken to their real cell (clamped into the box).
    int conditionAtPosition(const Lattice& L, int side, const Real x[3]) const;
};

// Precomputed ghost-to-image map and first-layer friction nodes.
class Boundary
{
public:
    // unilateralAxis >= 0 marks the ghost of a single slip/friction wall:
    // its normal reflection applies only while material moves towards the
    // wall (contact), so material can leave the wall. outward is the
    // direction from the image into the wall along that axis. mu: the
    // Coulomb coefficient of a friction wall's unilateral ghost (else 0):
    // the normal impulse its fold delivers to the image bounds the image's
    // friction.
    struct Ghost
    {
        Index ghost;
        Index image;
        std::array<Real, 3> sign;
        int unilateralAxis = -1;
        Real outward = 0;
        Real mu = 0;
    };
    struct FrictionNode { Index node; int axis; Real outward; Real mu; };
    // A free node beyond an inlet face and its inlet's condition index
    struct InletNode { Index node; int condition; };

    void build(const Lattice& L, const BoundarySpec& spec);

    // A decomposed rank: `local` is its box lattice, whose real node 0 is
    // the global real node `offset`. Wall ghosts are listed only where this
    // rank folds them (their image cell is owned: ownsCell(global cell
    // index)), friction nodes only on owned cells, and no periodic copies.
    // The node indices are the box lattice's.
    void build
    (
        const Lattice& global, const BoundarySpec& spec, const Lattice& local,
        const std::array<int, 3>& offset, const std::function<bool(Index)>& ownsCell
    );

    // Periodic axes of a spec (both sides of an axis must agree).
    static std::array<bool, 3> periodicAxes(const Lattice& L, const BoundarySpec& spec);

    // Wall (mirror) ghosts: folded onto their images with reflection signs.
    const std::vector<Ghost>& ghosts() const { return ghosts_; }

    // Serial runs: ghosts across a periodic direction, as (copy, canonical
    // node) pairs; the canonical node has its periodic coordinates wrapped
    // and may itself be a wall ghost (a corner). They are the serial halo:
    // summed into the canonical node right after P2G, before any wall
    // decision sees the node, and copied back before G2P. Decomposed runs
    // leave them to the Subdomain's halo, which does the same across ranks.
    const std::vector<std::pair<Index, Index>>& periodicCopies() const { return periodicCopies_; }
    const std::vector<FrictionNode>& frictionNodes() const { return friction_; }
    // Free nodes beyond inlet faces (every box node, owned or not: setting
    // the inlet velocity is the same on every rank)
    const std::vector<InletNode>& inletNodes() const { return inlet_; }
    // Free nodes beyond open faces with their mirror image (a real node),
    // listed where the image cell is owned: the fluid coupling's fields
    // continue through an open face from the image (zero gradient).
    const std::vector<std::pair<Index, Index>>& freeNodes() const { return free_; }
    // The specification it was built from (open faces, inlet velocities)
    const BoundarySpec& spec() const { return spec_; }
    // Whether any face is open (outlet or inlet)
    bool hasOpenFaces() const { return hasOpen_; }
    bool hasFriction() const { return hasFriction_; }

    // Whether the side is periodic (for wrapping positions).
    bool periodic(int axis) const { return periodic_[axis]; }

private:
    std::vector<Ghost> ghosts_;
    std::vector<std::pair<Index, Index>> periodicCopies_;
    std::vector<FrictionNode> friction_;
    std::vector<InletNode> inlet_;
    std::vector<std::pair<Index, Index>> free_;
    std::array<bool, 3> periodic_{false, false, false};
    BoundarySpec spec_;
    bool hasOpen_ = false;
    bool hasFriction_ = false;
};

} // namespace mpm

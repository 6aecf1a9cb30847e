// The walls on the grid: box walls through their ghost nodes (the folds
// and fills, the contact decision of unilateral walls, Coulomb friction)
// and level-set walls through their node condition (kernels/frictionWall.hpp,
// kernels/levelSetWall.hpp: the bodies per node that the resident device
// step shares). Containment of the points is the move's (movePoints.hpp).
#pragma once
#include "../step/systemState.hpp"

namespace mpm {

// Adds each ghost's chosen arrays (FoldWhat, halo.hpp) into its image, in
// a fixed order (an image may receive from several ghosts); the vectors
// with this step's reflection signs
void foldGhosts(SystemState& s, unsigned what);
void foldScalar(const SystemState& s, Real* a);
void foldVector(const SystemState& s, std::array<StaggeredArray<Real>, 3>& a);
// The images' velocity reflected into their ghosts, the inlet velocity on
// the free nodes beyond an inlet, the halo copied
void fillGhosts(const SystemState& s, std::array<StaggeredArray<Real>, 3>& v);

// Contact of unilateral (slip, friction) walls, per image node, from the
// folded mass: sets the ghosts' signs, the friction cap and the friction
// walls' sticking nodes for this step
void decideWallContact(SystemState& s, Real dt, bool withForce);
// Coulomb friction of friction walls on the updated velocity, bounded by
// the normal impulse of the wall's fold (momentum + dt force of its
// contact ghosts) and contact at each node
void applyFriction(SystemState& s, std::array<StaggeredArray<Real>, 3>& v, Real dt);

// The largest friction coefficient a friction wall applies: the largest
// shear strength ratio of the materials that have points, on any rank
Real computeFrictionCap(const SystemState& s);
// The largest coefficient of the friction walls, box and level-set walls
// alike; 0 without friction walls
Real largestWallFriction(const SystemState& s);

// Level-set walls (grid/levelSet.hpp): built on the state's lattice,
// moved (translations, before a step), and their node condition on an
// updated velocity
void setLevelSetWalls(SystemState& s, std::vector<LevelSetWall> walls, const std::array<Real, 3>& unsolved);
void moveLevelSetWalls
(
    SystemState& s,
    const std::vector<std::array<Real, 3>>& displacement,
    const std::vector<std::array<Real, 3>>& velocity
);
void applyLevelSetWalls(SystemState& s, std::array<StaggeredArray<Real>, 3>& v);

} // namespace mpm

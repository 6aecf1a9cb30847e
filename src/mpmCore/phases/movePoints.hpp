// The move phase: every point advanced by the displacement the G2P stored,
// the non-finite stop, and what a boundary does to a point that crossed
// it: an open face (outlet or inlet) removes it, a box wall holds it just
// inside (counted: clamping can never hide a loss), a level-set wall puts
// it back on its surface, a level-set outlet removes it.
#pragma once
#include "../step/systemState.hpp"

namespace mpm {

// Throws NonFiniteError (step/nonFiniteError.hpp) on a non-finite velocity
void movePoints(SystemState& s, Real dt);

// The parts the host-assisted and resident device steps share, whose move
// runs on the device:
// A point whose new position x lies beyond a face: marked in
// leavingThrough as leaving through an open face (true, leaving counted),
// or counted as clamped at a wall (false; the caller then stores it just
// inside)
bool leavesThroughFace(SystemState& s, Index p, const Real x[3], Index& leaving, Index& clamped);
// The open condition through which a point beyond a face at x leaves, or
// -1 when walls hold it (beyondWall: it lies past one)
int exitCondition(const SystemState& s, const Real x[3], bool& beyondWall);
// Puts points inside a level-set wall back on its surface (moving walls
// where they are at the end of the step dt); marks those beyond a
// level-set outlet in leavingThrough (sized by the caller) and returns
// their number
Index containPoints(SystemState& s, Real dt);
// Removes the `leaving` points marked in leavingThrough, counted per condition
void removeLeaving(SystemState& s, Index leaving);

} // namespace mpm

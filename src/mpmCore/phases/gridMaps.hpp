// Maps of the points to the grid outside the step, for output and for the
// fluid coupling's exchange (the OpenFOAM layer): the grid's mass, volume
// and velocity at the current positions, the grain volume per material,
// and the grain volume spread over a mesh that covers part of the lattice.
#pragma once
#include "../step/systemState.hpp"

namespace mpm {

// Maps mass, volume and momentum to the grid at the current positions and
// sets grid.velocity. With grainVolume, also a copy of the grid volume
// right after the P2G: this rank's points only, before any halo sum or
// ghost fold (for spreadGrainVolume).
void mapToGrid(SystemState& s, std::vector<Real>* grainVolume = nullptr);

// The grid's mass, volume and velocity where a mesh samples them, after
// mapToGrid or a step: serial, the grid itself; decomposed, a copy whose
// every node of the exchange halo holds its owner's values (a mesh cell
// overlapping a lattice cell another rank owns: meshLattice's own lattice;
// Subdomain::HaloKind). A copy, not the grid: the grid's nodes outside the
// active region must stay zero.
struct GridSample
{
    const Real* mass;
    const Real* volume;
    std::array<const Real*, 3> velocity;
};
GridSample sampleGrid(SystemState& s);

// Grain volume (mass/rho0) of each material's points, spread to the nodes
// with the shape functions and folded from the ghosts like the grid
// volume: out[material][node]. The sum over materials is grid.volume after
// mapToGrid with constant grain volume. For coupling models that differ
// per material (drag); one extra P2G. Decomposed: the owners' values on
// every copy of the exchange halo.
void materialGrainVolume(SystemState& s, std::vector<std::vector<Real>>& out);

// The grain volume (mass/rho0) of the points spread to the nodes with the
// shape functions, each point's weights renormalised over its stencil's
// coverage (per padded node, the share of its lattice cell inside the
// mesh, 0..1): sum_I spread[I] coverage[I] is the points' grain volume
// exactly, so a mesh that covers only part of the lattice receives all of
// it (meshLattice's own lattice, fluidCoupling). No ghost fold: ghosts lie
// outside the mesh (coverage 0). The coverage does not change: set once.
// At every exchange, mapToGrid(&spread) and then spreadGrainVolume(spread),
// with the points unmoved between: a point whose stencil lies on fully
// covered nodes (|coverage - 1| <= fullCoverage) keeps its P2G grain
// volume; only the others pay for a second stencil.
constexpr double fullCoverage = 1e-12;
void setCoverage(SystemState& s, const std::vector<double>& coverage);
void spreadGrainVolume(const SystemState& s, std::vector<Real>& spread);

} // namespace mpm

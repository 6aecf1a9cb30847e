// The halo of the node arrays: the copies of a node that other ranks
// (decomposed runs: the Subdomain's halo) or the periodic axes (serial
// runs: the boundary's periodic copies) hold. After a P2G every copy is
// summed into its owner, before the ghost folds and the contact decision;
// after a velocity is set the owners' values are sent back to the copies,
// before a G2P.
#pragma once
#include "../step/systemState.hpp"

namespace mpm {

// Which grid arrays a halo sum or ghost fold covers (bit set)
enum FoldWhat : unsigned { foldMass = 1, foldMomentum = 2, foldForce = 4 };

// The grid's chosen arrays (mass: mass and volume)
void sumHalo(SystemState& s, unsigned what);
// Any node arrays on the state's lattice
void sumHalo(const SystemState& s, const std::vector<Real*>& arrays,
             Subdomain::HaloKind kind = Subdomain::HaloKind::step);
void copyHalo(const SystemState& s, const std::vector<Real*>& arrays,
              Subdomain::HaloKind kind = Subdomain::HaloKind::step);

} // namespace mpm

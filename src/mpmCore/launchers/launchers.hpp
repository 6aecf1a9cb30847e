// The launchers of the step: each runs the step plan's phases
// (step/stepPlan.hpp) in order on one back-end, so that the step is one
// call per back-end and the order is written once, in the plan:
//
//   stepOnHost          serial and openmp: every phase a function of
//                       phases/*.hpp on the host
//   stepHostAssisted    cuda: the point work on the device, the node work
//                       the host's phases, the active nodes copied between
//                       (backend/deviceStep.hpp)
//   stepResident        cuda resident (or its host stand-in): every phase on
//                       the device, the host told a few counters
//                       (backend/residentStep.hpp)
//
// MpmSystem::step picks one; all take the whole state and leave it as the
// host step would, up to the order of P2G's sums on the device.
#pragma once
#include "../step/systemState.hpp"
#include <string>

namespace mpm {

void stepOnHost(SystemState& s, Real dt);
void stepHostAssisted(SystemState& s, Real dt);
void stepResident(SystemState& s, Real dt);

// Why the resident step does not run this case ("" when it does, or when
// the back-end has none: cuda or the stand-in only)
std::string residentUnsupported(const SystemState& s);

} // namespace mpm

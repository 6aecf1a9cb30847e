// The migrate phase of decomposed runs: every point whose cell another
// rank owns is sent to that rank with all its fields. The step's last
// phase; also called after reading or seeding points.
#pragma once
#include "../step/systemState.hpp"

namespace mpm {

// Returns the number of points sent (0 in serial runs). Throws
// std::runtime_error (not NonFiniteError) if a point moved beyond this
// rank's halo in one step.
Index migrate(SystemState& s);

} // namespace mpm

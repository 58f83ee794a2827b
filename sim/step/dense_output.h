// Dense output: the state at a time inside an accepted step, from the step's two ends. With error
// control the steps no longer stop at every output time (which cost a traversal up to twice its
// steps: a step the controller wanted at 15 ms became two of 10 ms to land on a 20 ms frame), so
// the run writes the frames that fall inside a step from this interpolant instead. It is the cubic
// Hermite through both ends' positions and velocities, exact for cubic motion: its error, O(h^4)
// in position, is below BDF2's own O(h^3) local error. The run checks that the interpolated frame
// keeps every barrier's gap open and otherwise lands a step on the output time as before
// (sim/run/run.cpp).
#pragma once

#include "sim/step/state.h"

namespace vascsim {

// The state at time t, start.t <= t <= end.t, of the step from `start` to `end` (same size):
// positions and velocities only; its history fields are left empty.
State interpolate_in_step(const State& start, const State& end, double t);

}  // namespace vascsim

// The local truncation error of a converged step, estimated without another solve: the step's
// solution y_{n+1} = (x, v) is compared with an explicit polynomial predictor through the
// previous points (quadratic through y_n, y_{n-1}, y_{n-2} for BDF2, linear through y_n, y_{n-1}
// for backward Euler). Both err by a multiple of the same derivative (y''' for BDF2, y'' for
// backward Euler), so the difference, scaled by the ratio of the two error constants (Milne's
// device; for variable steps derived in docs/solver.md, "Step size"), estimates the step's own
// error. It shrinks as h^3 for BDF2 and h^2 for backward Euler. The run loop accepts a step whose
// weighted error is at most 1 and chooses the next step from it (step_size_controller.h).
#pragma once

#include <vector>

#include "sim/scene/scene.h"
#include "sim/step/state.h"

namespace vascsim {

struct LocalErrorWeights {
  double rtol = 0.0;           // -
  double atol_position = 0.0;  // m
  double atol_velocity = 0.0;  // m/s
  double length = 1.0;         // m, the positions' scale for rtol (the rod's length)
  // m/s, the velocities' scale for rtol, at least: the run passes the largest node speed so far,
  // so that a rod momentarily at rest (an oscillation's turning point) is not held to
  // rtol times zero.
  double speed = 0.0;
};

struct LocalError {
  double position = 0.0;  // the largest |error_i| / (atol_position + rtol * length), positions
  double velocity = 0.0;  // the same for velocities, scale the largest of weights.speed and the node speeds
  bool estimated() const { return position >= 0.0; }
};

// The step's estimated local error relative to the tolerance, over the degrees of freedom not in
// `fixed` (prescribed ones are not integrated): <= 1 means within tolerance.
// `before` is the state the step started from (with its history), `after` the converged step
// of `order` (step_order of the stepper). Both are negative when the history is too short for
// the order's predictor (the first steps): no estimate.
LocalError local_error(const State& before, const State& after, int order, const std::vector<char>& fixed,
                   const LocalErrorWeights& weights);

}  // namespace vascsim

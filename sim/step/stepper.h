// The implicit time stepper: advances a State by one step of backward Euler or BDF2, solving the
// nonlinear step with Newton (sim/step/newton.h). The state changes only when Newton converged;
// on failure it retries with dt/2 (unless SolverSpec::adaptive is kOff) and otherwise returns a
// report with the reason and the state untouched. It never touches files. Whether a converged
// step is accurate enough is the caller's question (sim/step/local_error.h, the run loop).
//
// Schemes, for M a = F(x, v) written as a first-order system (x' = v, M v' = F):
//   backward Euler: x1 = x0 + h v1,                     M (v1 - v0) = h F(x1, v1)
//   BDF2 (variable step, w = h/h_prev):
//     x1 = a1 x0 - a2 x_prev + beta h v1,  M (v1 - a1 v0 + a2 v_prev) = beta h F(x1, v1)
//     a1 = (1+w)^2/(1+2w), a2 = w^2/(1+2w), beta = (1+w)/(1+2w)   (4/3, 1/3, 2/3 at w = 1)
// Both are x1 = x_hat + beta h v1 and M (v1 - v_hat) = beta h F; backward Euler is a1 = beta = 1,
// a2 = 0. BDF2 starts with one backward Euler step and falls back to it when the step ratio
// exceeds 2 (its zero-stability limit is 1 + sqrt 2).
#pragma once

#include <string>

#include "sim/step/controls.h"
#include "sim/step/model.h"
#include "sim/step/newton.h"
#include "sim/step/state.h"

namespace vascsim {

struct StepReport {
  bool ok = false;
  double dt = 0.0;             // s, the step actually taken (< requested after a retry)
  int iterations = 0;          // Newton iterations of the accepted attempt
  int total_iterations = 0;    // including rejected attempts
  int rejected = 0;            // attempts that failed and were retried with dt/2
  double residual = 0.0;       // relative residual at the accepted solution
  bool round_off_stop = false; // converged because the update fell below round-off
  // solver.adaptive "off" only (elsewhere such a step is retried shorter): the step kept is not
  // the motion but a root it jumped to, being too long for what happens in it: it ends at a
  // saddle of its incremental potential (the Newton matrix has negative pivots), or an edge
  // turned by more than 0.5 rad in it.
  bool unresolved = false;
  std::string failure;         // when !ok: what went wrong, at what time and dt
};

// Marks the held degrees of freedom in ws.fixed (constraints of the model, the controls' targets)
// and their positions at time t in ws.target.
void set_targets(const Model& model, const Controls& controls, double t, Workspace& ws);

// BDF2 steps no more than this many times longer than the previous one (zero-stability needs
// less than 1 + sqrt 2); a longer step is taken with backward Euler.
inline constexpr double kMaxBdf2StepRatio = 2.0;

// The order of the scheme a step of h from `state` uses: 2 for BDF2 with a previous step at most
// kMaxBdf2StepRatio times shorter, else 1 (backward Euler, also BDF2's first step).
int step_order(Scheme scheme, const State& state, double h);

// Under error control, how far from the exact solve a step may stop: Newton also ends when its
// next correction is within h * position_rate in every position and within velocity in the
// implied velocities (v = (x - x_hat) / (beta h)). Zeros: the residual test alone.
struct NewtonStopTolerance {
  double position_rate = 0.0;  // m/s
  double velocity = 0.0;       // m/s
};

// Where Newton starts instead of the predictor, for an attempt of exactly `dt` seconds: the paper
// contact solves each step again with new wall forces, and its last solution is a far better
// start than the predictor (on the tests' 42 paper traversals 2.9x fewer Newton iterations).
struct NewtonWarmStart {
  Eigen::VectorXd x;  // (2N), m
  double dt = 0.0;    // s
};

// One step of at most `dt` seconds from state.t, with `controls` held over the step; `warm`, if
// given, starts Newton for an attempt of its dt.
StepReport step(const Model& model, State& state, Workspace& ws, const Controls& controls, double dt,
                const NewtonStopTolerance& stop = {}, const NewtonWarmStart* warm = nullptr);

// As step(), but one attempt with exactly `dt` and no retry (used by tests and benchmarks).
StepReport step_once(const Model& model, State& state, Workspace& ws, const Controls& controls, double dt,
                     const NewtonStopTolerance& stop = {});

}  // namespace vascsim

#include "sim/step/statics.h"

#include <cstdio>

#include "sim/step/banded_ldlt.h"
#include "sim/step/stepper.h"

namespace vascsim {

StaticReport solve_static(const Model& model, State& state, Workspace& ws, const Controls& controls) {
  StaticReport report;
  set_targets(model, controls, state.t, ws);
  Eigen::VectorXd x = state.x;
  for (std::size_t d = 0; d < ws.fixed.size(); ++d)
    if (ws.fixed[d]) x[static_cast<Eigen::Index>(d)] = ws.target[static_cast<Eigen::Index>(d)];

  const int max_rejections = 4 * (model.solver.max_halvings + 1);
  double lambda = 0.0;
  double increment = 1.0 / std::max(1, model.solver.load_steps);
  const double min_increment = increment / std::ldexp(1.0, model.solver.max_halvings);
  NewtonProblem p;
  p.t = state.t;
  p.c = 0.0;
  p.controls = &controls;
  p.start = &state;
  while (lambda < 1.0) {
    const double next = std::min(1.0, lambda + increment);
    p.load_scale = next;
    ws.x = x;
    const NewtonOutcome out = newton_solve(model, p, ws);
    report.iterations += out.iterations;
    if (out.converged) {
      x = ws.x;
      lambda = next;
      ++report.increments;
      if (out.iterations <= 4) increment *= 1.5;
      continue;
    }
    ++report.rejected;
    increment *= 0.5;
    if (increment < min_increment || report.rejected > max_rejections) {
      char buf[120];
      std::snprintf(buf, sizeof buf, "static solve stopped at load factor %.4g of 1: ", lambda);
      report.failure = buf + out.failure;
      break;
    }
  }
  report.load_scale = lambda;
  report.ok = lambda >= 1.0;
  if (report.ok) {
    p.load_scale = 1.0;
    assemble(model, p, x, ws, true);
    report.negative_pivots = banded_block_ldlt_factor(ws.jacobian).negative_pivots;
  }
  state.x = x;
  state.v.setZero();
  state.h_prev = 0.0;
  state.h_prev2 = 0.0;
  return report;
}

}  // namespace vascsim

#include "sim/step/stepper.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace vascsim {

void set_targets(const Model& model, const Controls& controls, double t, Workspace& ws) {
  std::fill(ws.fixed.begin(), ws.fixed.end(), 0);
  for (const auto& c : model.constraints) {
    ws.target.segment<2>(2 * c.node) = c.position(t);
    ws.fixed[2 * c.node] = c.hold_x;
    ws.fixed[2 * c.node + 1] = c.hold_y;
  }
  for (const auto& g : controls.targets) {
    const int node = resolve_node(g.node, model.nodes());
    if (node < 0) continue;
    ws.target.segment<2>(2 * node) = g.position + g.velocity * (t - controls.time);
    ws.fixed[2 * node] = ws.fixed[2 * node + 1] = 1;
  }
}

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// rad: the most any edge of the rod may turn in one step. The shipped scenes at the fast preset
// turn an edge by at most 0.36 rad between two frames (coil_chamber, 33 ms apart), so this
// limits only motion no preset resolves.
constexpr double kMaxEdgeTurn = 0.5;

struct EdgeTurn {
  bool over = false;
  int edge = -1;       // the first edge over the limit
  double angle = 0.0;  // rad, its turn
};

// The first edge that turns by more than kMaxEdgeTurn from `before` to `after` (2N positions,
// m). By the cosine, one square root per edge and no arctangent: this runs at every step.
EdgeTurn first_edge_turned_too_far(const Eigen::VectorXd& before, const Eigen::VectorXd& after) {
  static const double cos_limit = std::cos(kMaxEdgeTurn);
  EdgeTurn out;
  const Eigen::Index n = before.size() / 2;
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    const Eigen::Vector2d a = before.segment<2>(2 * i + 2) - before.segment<2>(2 * i);
    const Eigen::Vector2d b = after.segment<2>(2 * i + 2) - after.segment<2>(2 * i);
    const double dot = a.dot(b);
    if (dot >= cos_limit * std::sqrt(a.squaredNorm() * b.squaredNorm())) continue;
    out.over = true;
    out.edge = static_cast<int>(i);
    out.angle = std::abs(std::atan2(a.x() * b.y() - a.y() * b.x(), dot));
    return out;
  }
  return out;
}

bool attempt(const Model& model, State& state, Workspace& ws, const Controls& controls, double h, const NewtonStopTolerance& stop,
             const NewtonWarmStart* warm, StepReport& report) {
  // Scheme coefficients (see stepper.h).
  double a1 = 1.0, a2 = 0.0, beta = 1.0;
  if (step_order(model.solver.scheme, state, h) == 2) {
    const double w = h / state.h_prev;
    a1 = (1.0 + w) * (1.0 + w) / (1.0 + 2.0 * w);
    a2 = w * w / (1.0 + 2.0 * w);
    beta = (1.0 + w) / (1.0 + 2.0 * w);
  }
  if (a2 != 0.0) {
    ws.x_hat = a1 * state.x - a2 * state.x_prev;
    ws.v_hat = a1 * state.v - a2 * state.v_prev;
  } else {
    ws.x_hat = state.x;
    ws.v_hat = state.v;
  }
  const double t1 = state.t + h;
  set_targets(model, controls, t1, ws);
  // Predictor: constant acceleration, the last two velocities' difference quotient (constant
  // velocity on the first step), shortened where a module needs it (a contact barrier must start
  // Newton from a configuration with every gap open). It is exact for the motion BDF2 integrates
  // exactly (a quadratic in time); on the maze traversals it saves about a third of the Newton
  // iterations over constant velocity (docs/solver.md, "Predictor").
  // Not under the paper's contact: its wall forces are explicit, raised between re-solves of a
  // step (run.cpp), so the last velocity difference carries their jumps, and from that start
  // Newton reached other solutions often enough that 2 of the 21 mazes of
  // tests/navigation_test.cpp lost their goal. Constant velocity there, as before.
  ws.dx = h * state.v;
  const bool paper_walls = model.scene.contact.mode == ContactMode::kPaper && model.scene.has_environment;
  if (state.h_prev > 0.0 && !paper_walls)
    ws.dx += (0.5 * h * h / state.h_prev) * (state.v - state.v_prev);
  for (std::size_t d = 0; d < ws.fixed.size(); ++d)
    if (ws.fixed[d]) ws.dx[static_cast<Eigen::Index>(d)] = ws.target[static_cast<Eigen::Index>(d)] - state.x[static_cast<Eigen::Index>(d)];
  double alpha = 1.0;
  if (!model.forces.empty()) {
    const ForceContext ctx = ForceContext::at(state, controls);
    for (std::size_t k = 0; k < model.forces.size(); ++k)
      alpha = std::min(alpha, model.forces[k]->max_step_fraction(module_context(ctx, ws, k), ws.dx));
  }
  if (warm && warm->dt == h && warm->x.size() == ws.x.size())
    ws.x = warm->x;
  else
    ws.x = state.x + alpha * ws.dx;
  for (std::size_t d = 0; d < ws.fixed.size(); ++d)
    if (ws.fixed[d]) ws.x[static_cast<Eigen::Index>(d)] = ws.target[static_cast<Eigen::Index>(d)];

  NewtonProblem p;
  p.t = t1;
  p.c = 1.0 / (beta * h);
  p.controls = &controls;
  p.start = &state;
  // A zero tolerance leaves its quantity out of the test (as local_error leaves it uncontrolled).
  const double by_position = stop.position_rate > 0.0 ? h * stop.position_rate : kInfinity;
  const double by_velocity = stop.velocity > 0.0 ? beta * h * stop.velocity : kInfinity;
  p.correction_tol = std::min(by_position, by_velocity) < kInfinity ? std::min(by_position, by_velocity) : 0.0;
  const NewtonOutcome out = newton_solve(model, p, ws);
  report.total_iterations += out.iterations;
  if (!out.converged) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "at t = %.9g s with dt = %.3g s: ", state.t, h);
    report.failure = buf + out.failure;
    return false;
  }
  // Two signs that the answer is not the motion but a root the step jumped to, because the step
  // is too long for what happens in it. A fixed-dt run keeps such a step and says so; otherwise
  // it is retried shorter, below any floor of error control (whose steps are kept over their
  // tolerance, not across a jump).
  // 1. A saddle of the step's incremental potential (inertia plus energy): the positions are a
  //    minimum only where the Newton matrix is positive definite, and a shorter step's larger
  //    inertia term m / (beta h)^2 makes it so. A rod against a strong field went round the
  //    wrong way within the fast preset's first 10 ms.
  // 2. An edge turned by more than kMaxEdgeTurn: the rod whipped round within the step, and the
  //    balanced preset's 1 ms steps coiled that rod 1.5 turns the wrong way, each a minimum.
  char why[200] = "";
  if (out.negative_pivots > 0) {
    std::snprintf(why, sizeof why, "the step ends at a saddle of its incremental potential (%d negative pivots)",
                  out.negative_pivots);
  } else if (const EdgeTurn turn = first_edge_turned_too_far(state.x, ws.x); turn.over) {
    std::snprintf(why, sizeof why, "edge %d turned by %.3g rad in the step, more than %.2g rad (the motion is not resolved)",
                  turn.edge, turn.angle, kMaxEdgeTurn);
  }
  report.unresolved = why[0] != '\0';
  if (report.unresolved && model.solver.adaptive != StepControl::kOff) {
    char buf[320];
    std::snprintf(buf, sizeof buf, "at t = %.9g s with dt = %.3g s: %s", state.t, h, why);
    report.failure = buf;
    return false;
  }
  report.iterations = out.iterations;
  report.residual = out.residual / std::max(out.scale, 1e-300);
  report.round_off_stop = out.round_off_stop;
  report.dt = h;
  // Commit.
  state.x_prev2.swap(state.x_prev);
  state.v_prev2.swap(state.v_prev);
  state.h_prev2 = state.h_prev;
  state.x_prev.swap(state.x);
  state.v_prev.swap(state.v);
  state.x = ws.x;
  state.v = ws.v;
  state.h_prev = h;
  state.t = t1;
  return true;
}

}  // namespace

int step_order(Scheme scheme, const State& state, double h) {
  return scheme == Scheme::kBdf2 && state.h_prev > 0.0 && h <= kMaxBdf2StepRatio * state.h_prev ? 2 : 1;
}

StepReport step_once(const Model& model, State& state, Workspace& ws, const Controls& controls, double dt,
                     const NewtonStopTolerance& stop) {
  StepReport report;
  report.ok = attempt(model, state, ws, controls, dt, stop, nullptr, report);
  return report;
}

StepReport step(const Model& model, State& state, Workspace& ws, const Controls& controls, double dt,
                const NewtonStopTolerance& stop, const NewtonWarmStart* warm) {
  StepReport report;
  const int retries = model.solver.adaptive == StepControl::kOff ? 0 : model.solver.max_halvings;
  // Under error control no step is shorter than solver.dt_min, a halving included (one took steps
  // of 2.5e-4 s with dt_min 1e-3 s).
  const double shortest = model.solver.adaptive == StepControl::kError ? model.solver.dt_min * (1 - 1e-12) : 0.0;
  double h = dt;
  int k = 0;
  for (;; ++k, h *= 0.5) {
    if (attempt(model, state, ws, controls, h, stop, warm, report)) {
      report.ok = true;
      return report;
    }
    if (k == retries || 0.5 * h < shortest) break;
    ++report.rejected;
  }
  if (k > 0 || retries > 0) {
    report.failure += " (after " + std::to_string(k) + " retries with halved dt";
    if (k < retries) {
      char text[96];
      std::snprintf(text, sizeof text, "; another would be shorter than solver.dt_min = %.3g s", model.solver.dt_min);
      report.failure += text;
    }
    report.failure += ")";
  }
  return report;
}

}  // namespace vascsim

#include "sim/step/statics.h"

#include <cstdio>
#include <optional>

#include "sim/step/banded_ldlt.h"
#include "sim/step/stability_margin.h"
#include "sim/step/stable_branch.h"
#include "sim/step/stepper.h"

namespace vascsim {

namespace {

// Negative pivots of the Newton matrix at x (-1 where its factorisation fails).
int negative_pivots_at(const Model& model, const NewtonProblem& p, const Eigen::VectorXd& x, Workspace& ws) {
  assemble(model, p, x, ws, true);
  const LdltResult f = banded_block_ldlt_factor(ws.jacobian);
  return f.ok ? f.negative_pivots : -1;
}

}  // namespace

StaticReport solve_static(const Model& model, State& state, Workspace& ws, const Controls& controls,
                          const std::function<std::string()>& stop_reason) {
  StaticReport report;
  set_targets(model, controls, state.t, ws);
  Eigen::VectorXd x = state.x;
  for (std::size_t d = 0; d < ws.fixed.size(); ++d)
    if (ws.fixed[d]) x[static_cast<Eigen::Index>(d)] = ws.target[static_cast<Eigen::Index>(d)];
  const Eigen::VectorXd unloaded = x;  // the reference that signs the way off a saddle

  const int max_rejections = 4 * (model.solver.max_halvings + 1);
  double lambda = 0.0;
  double increment = 1.0 / std::max(1, model.solver.load_steps);
  const double min_increment = increment / std::ldexp(1.0, model.solver.max_halvings);
  NewtonProblem p;
  p.t = state.t;
  p.c = 0.0;
  p.controls = &controls;
  p.start = &state;
  // Negative pivots at the last accepted equilibrium (-1: not known, e.g. a singular matrix).
  p.load_scale = 0.0;
  int pivots = model.solver.stable_branch ? negative_pivots_at(model, p, x, ws) : -1;
  // The last increment cut for leaving the stable branch, kept to fall back on.
  struct Jump {
    double load = 0.0, increment = 0.0;
    Eigen::VectorXd x;
  };
  std::optional<Jump> jump;
  while (lambda < 1.0) {
    if (stop_reason) {
      if (std::string who = stop_reason(); !who.empty()) {
        char buf[120];
        std::snprintf(buf, sizeof buf, " at load factor %.4g of 1", lambda);
        report.failure = "stopped by " + who + buf;
        report.stopped_by = std::move(who);
        break;
      }
    }
    const double next = std::min(1.0, lambda + increment);
    p.load_scale = next;
    ws.x = x;
    const NewtonOutcome out = newton_solve(model, p, ws);
    report.iterations += out.iterations;
    if (out.converged) {
      if (pivots == 0) {
        // At the converged point: Newton's own count (out.negative_pivots) is of the matrix at
        // the iterate before, and near a turn of the branch the sign of a pivot can differ.
        const int reached = negative_pivots_at(model, p, ws.x, ws);
        if (reached > 0 && increment > min_increment && report.stability_cuts < max_rejections) {
          // Newton crossed from a stable equilibrium to an unstable one: from a shape far from
          // the new one, at an indefinite matrix, it climbs to the nearest root, not down the
          // branch the load was following (a rod near anti-parallel to a strong field reached
          // the saddle, and the search down from there the far, clockwise coil). A smaller
          // increment stays on the branch.
          ++report.stability_cuts;
          jump = Jump{next, increment, ws.x};
          increment = std::max(min_increment, 0.5 * increment);
          continue;
        }
        // Stable; or unstable even within the smallest increment: the branch ends or bifurcates
        // here (a column at its buckling load), the path goes on along the unstable root, and
        // the solve leaves it at full load, below.
        pivots = reached;
      }
      x = ws.x;
      lambda = next;
      ++report.increments;
      if (out.iterations <= 4) increment *= 1.5;
      continue;
    }
    ++report.rejected;
    increment *= 0.5;
    if ((increment < min_increment || report.rejected > max_rejections) && jump && jump->load > lambda) {
      // The smaller increments could not follow the branch where it turns (Newton failed on
      // them): take the jump they were to avoid, as load stepping without the check would, and
      // say so; the equilibrium reached may be on another branch than slower loading reaches.
      // An imperfect column far past buckling (30 P_cr, 1e-2 P_cr aside) failed without this.
      x = jump->x;
      lambda = jump->load;
      increment = jump->increment;
      jump.reset();
      pivots = -1;  // off the branch: no more cuts; an unstable end is left below
      ++report.increments;
      if (report.branch_jumps++ == 0) report.first_jump_load = lambda;
      continue;
    }
    if (increment < min_increment || report.rejected > max_rejections) {
      char buf[120];
      std::snprintf(buf, sizeof buf, "static solve stopped at load factor %.4g of 1: ", lambda);
      report.failure = buf + out.failure;
      std::snprintf(buf, sizeof buf, " (the smallest increment is %.3g of the load", min_increment);
      report.failure += buf;
      if (report.stability_cuts > 0)
        report.failure += "; " + std::to_string(report.stability_cuts) +
                          " increments were cut for leaving the stable branch, which turns sharply here";
      report.failure += ": more solver.load_steps or solver.max_halvings make smaller ones)";
      break;
    }
  }
  report.load_scale = lambda;
  report.ok = lambda >= 1.0;
  if (report.ok) {
    p.load_scale = 1.0;
    // The Newton matrix at x, kept as assembled (for the stability margin) and factored in ws.
    BandedMatrix stiffness;
    const auto factor_at = [&](const Eigen::VectorXd& at) {
      assemble(model, p, at, ws, true);
      stiffness = ws.jacobian;
      return banded_block_ldlt_factor(ws.jacobian);
    };
    LdltResult factor = factor_at(x);
    report.negative_pivots = factor.negative_pivots;
    if (report.negative_pivots > 0 && model.solver.stable_branch) {
      // Newton found a saddle of the energy (a column kept straight past buckling): leave it.
      report.unstable_pivots = std::max(report.unstable_pivots, report.negative_pivots);
      ws.x = x;
      const BranchOutcome b = descend_to_stable(model, p, ws, unloaded);
      report.iterations += b.iterations;
      if (b.ok) {
        x = ws.x;
        report.left_unstable = true;
        report.negative_pivots = 0;
      } else {
        report.branch_failure = b.failure;
      }
      factor = factor_at(x);  // the branch search used ws's matrix
    }
    // The pivots' count is only as good as the sign of the eigenvalue nearest zero.
    if (factor.ok) {
      const StabilityMargin margin = stability_margin(stiffness, ws.jacobian, ws.fixed);
      report.smallest_eigenvalue = margin.eigenvalue;
      report.eigenvalue_round_off = margin.round_off;
      report.stability_undecided = !margin.decided();
    } else {
      report.stability_undecided = true;
    }
  }
  state.x = x;
  state.v.setZero();
  state.h_prev = 0.0;
  state.h_prev2 = 0.0;
  return report;
}

}  // namespace vascsim

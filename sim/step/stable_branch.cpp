#include "sim/step/stable_branch.h"

#include <cmath>
#include <cstdio>

#include "sim/step/banded_ldlt.h"

namespace vascsim {

namespace {

// The first step off the saddle, as a fraction of the rod length (largest node displacement).
// Small, so that the descent decides the shape; each flipped-pivot step about doubles the
// excursion along the negative mode (the residual there is lambda y, the step |lambda|^-1 of it),
// so reaching O(L) from 1e-3 L costs about ten steps.
constexpr double kNudge = 1e-3;
// The descent's iteration cap (flipped-pivot steps), in multiples of max_iterations: a buckled
// column travels far from the saddle, with backtracking where the linearised steps stretch the rod.
constexpr int kIterationFactor = 20;

double free_dot(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const std::vector<char>& fixed) {
  double s = 0.0;
  for (Eigen::Index i = 0; i < a.size(); ++i)
    if (!fixed[static_cast<std::size_t>(i)]) s += a[i] * b[i];
  return s;
}

double free_inf(const Eigen::VectorXd& a, const std::vector<char>& fixed) {
  double m = 0.0;
  for (Eigen::Index i = 0; i < a.size(); ++i)
    if (!fixed[static_cast<std::size_t>(i)]) m = std::max(m, std::abs(a[i]));
  return m;
}

BranchOutcome fail(Workspace& ws, const Eigen::VectorXd& unstable, BranchOutcome out, const std::string& why) {
  ws.x = unstable;
  out.ok = false;
  out.failure = why;
  return out;
}

}  // namespace

BranchOutcome descend_to_stable(const Model& model, const NewtonProblem& p, Workspace& ws,
                                const Eigen::VectorXd& reference) {
  const SolverSpec& s = model.solver;
  const double length = std::max(model.rod.length, 1e-300);
  const Eigen::VectorXd unstable = ws.x;
  BranchOutcome out;

  assemble(model, p, ws.x, ws, true);
  if (!banded_block_ldlt_factor(ws.jacobian).ok) return fail(ws, unstable, out, "singular Newton matrix at the unstable equilibrium");
  Eigen::VectorXd y = banded_block_ldlt_negative_direction(ws.jacobian);
  for (std::size_t d = 0; d < ws.fixed.size(); ++d)
    if (ws.fixed[d]) y[static_cast<Eigen::Index>(d)] = 0.0;
  const double y_inf = free_inf(y, ws.fixed);
  if (!(y_inf > 0.0) || !std::isfinite(y_inf)) return fail(ws, unstable, out, "no direction of negative curvature");
  if (free_dot(y, unstable - reference, ws.fixed) > 0.0) y = -y;
  ws.x += (kNudge * length / y_inf) * y;

  Eigen::VectorXd r0(ws.x.size());
  double scale = assemble(model, p, ws.x, ws, true);
  const int cap = kIterationFactor * s.max_iterations;
  for (;;) {
    const double rinf = free_inf(ws.residual, ws.fixed);
    if (!std::isfinite(rinf)) return fail(ws, unstable, out, "the residual is not finite");
    const LdltResult f = banded_block_ldlt_factor(ws.jacobian);
    if (!f.ok) return fail(ws, unstable, out, "singular Newton matrix on the way down");
    const bool stable = f.negative_pivots == 0;
    if (stable && (rinf <= s.rel_tol * scale || rinf <= s.abs_tol)) {
      out.ok = true;
      return out;
    }
    if (out.iterations >= cap) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "no stable equilibrium within %d iterations (relative residual %.3g, %d negative pivots)",
                    cap, rinf / std::max(scale, 1e-300), f.negative_pivots);
      return fail(ws, unstable, out, buf);
    }
    // Where the matrix is indefinite, flipping its negative pivots makes the step descend the
    // energy, away from the saddle along the negative modes; where it is definite this is the
    // Newton step. (No convergence test while indefinite: at the nudged saddle the residual is
    // small but the step is not.)
    if (!stable) banded_block_ldlt_absolute_pivots(ws.jacobian);
    ws.dx = -ws.residual;
    banded_block_ldlt_solve(ws.jacobian, ws.dx);
    ++out.iterations;
    const double slope = free_dot(ws.residual, ws.dx, ws.fixed);  // dE/dalpha at alpha = 0, < 0
    const double dx_inf = ws.dx.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(dx_inf)) return fail(ws, unstable, out, "the update is not finite");
    double alpha = 1.0;
    if (!model.forces.empty()) {
      ForceContext ctx;
      ctx.t = p.t;
      ctx.x = &ws.x;
      ctx.v = &ws.v;
      ctx.load_scale = p.load_scale;
      ctx.controls = p.controls;
      ctx.start = p.start;
      for (std::size_t k = 0; k < model.forces.size(); ++k)
        alpha = std::min(alpha, model.forces[k]->max_step_fraction(module_context(ctx, ws, k), ws.dx));
    }
    r0 = ws.residual;
    bool accepted = false;
    if (dx_inf > s.step_tol * length) {
      for (int k = 0; k < 30 && alpha > 0.0; ++k, alpha *= 0.5) {
        ws.x_trial = ws.x + alpha * ws.dx;
        const double trial_scale = assemble(model, p, ws.x_trial, ws, true);
        const double de = 0.5 * alpha * free_dot(r0 + ws.residual, ws.dx, ws.fixed);
        if (std::isfinite(de) && de <= 1e-4 * alpha * slope) {
          ws.x.swap(ws.x_trial);
          scale = trial_scale;
          accepted = true;
          break;
        }
      }
    }
    if (accepted) continue;
    if (!stable) return fail(ws, unstable, out, "the line search found no lower energy");
    // Definite, and no lower energy along the Newton step: the energy change is lost in
    // round-off this close to the minimum. Plain Newton (with its round-off stop) finishes; it
    // must not go back up to the saddle.
    assemble(model, p, ws.x, ws, true);
    const NewtonOutcome n = newton_solve(model, p, ws);
    out.iterations += n.iterations;
    if (!n.converged) return fail(ws, unstable, out, n.failure);
    assemble(model, p, ws.x, ws, true);
    const LdltResult g = banded_block_ldlt_factor(ws.jacobian);
    if (!g.ok || g.negative_pivots > 0) return fail(ws, unstable, out, "Newton went back to an unstable equilibrium");
    out.ok = true;
    return out;
  }
}

}  // namespace vascsim

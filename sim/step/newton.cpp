#include "sim/step/newton.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "sim/step/banded_ldlt.h"
#include "sim/step/sparse_solve.h"

namespace vascsim {

Workspace::Workspace(const Model& model) : jacobian(model.dofs()), elastic(model.rod) {
  const int n = model.dofs();
  for (Eigen::VectorXd* v : {&residual, &gradient, &force, &reaction, &x, &v, &dx, &x_trial, &x_hat, &v_hat, &target})
    v->setZero(n);
  fixed.assign(static_cast<std::size_t>(n), 0);
  for (const auto& f : model.forces) caches.push_back(f->make_cache());
}

namespace {

double norm_inf_free(const Eigen::VectorXd& r, const std::vector<char>& fixed) {
  double m = 0.0;
  for (Eigen::Index i = 0; i < r.size(); ++i)
    if (!fixed[static_cast<std::size_t>(i)]) m = std::max(m, std::abs(r[i]));
  return m;
}

// The force modules' view of a Newton iterate x with implied velocities v.
ForceContext context_of(const NewtonProblem& p, const Eigen::VectorXd& x, const Eigen::VectorXd& v) {
  ForceContext ctx;
  ctx.t = p.t;
  ctx.x = &x;
  ctx.v = &v;
  ctx.dv_dx = p.c;
  ctx.load_scale = p.load_scale;
  ctx.controls = p.controls;
  ctx.start = p.start;
  return ctx;
}

std::string format(const char* fmt, double a, double b = 0.0) {
  char buf[200];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}

}  // namespace

namespace {

NewtonOutcome& round_off_stop(const Model& model, const NewtonProblem& p, Workspace& ws, NewtonOutcome& out) {
  out.scale = assemble(model, p, ws.x, ws, true);
  out.residual = norm_inf_free(ws.residual, ws.fixed);
  out.round_off_stop = true;
  out.converged = std::isfinite(out.residual);
  if (!out.converged) out.failure = "the residual is not finite (the rod blew up)";
  return out;
}

// The residual's round-off in a static solve: rounding the positions alone (|x| eps) changes the
// forces by up to |K| |x| eps, and the bending stiffness EI/dl^3 in K grows like N^3. Without
// inertia to bound the softest mode, that noise, not the tolerance, limits a fine mesh: the
// paper's rod at 10001 nodes under a tip load sits at 1e-2 of the load there early in the ramp,
// where no step along the (round-off-dominated) Newton direction lowers it. A Newton update that
// cannot lower a residual below this level has reached the point floating point allows.
double residual_round_off(const BandedMatrix& k, const Eigen::VectorXd& x) {
  double diagonal = 0.0;
  for (int i = 0; i < k.size(); ++i) diagonal = std::max(diagonal, std::abs(k.lower(i, i)));
  // A row of a semi-definite band sums to at most (2 * 5 + 1) times its largest diagonal entry
  // (|K_ij| <= sqrt(K_ii K_jj)); an indefinite one near a buckling load is close to that.
  const double row_sum = (2 * BandedMatrix::kHalfBandwidth + 1) * diagonal;
  return row_sum * x.lpNorm<Eigen::Infinity>() * std::numeric_limits<double>::epsilon();
}

// Error control's stop (NewtonProblem::correction_tol), CVODE's test: the next correction,
// estimated with the factorisation of the last iterate's Jacobian (no new assembly), is within
// the tolerance; it is then applied, as CVODE does, since stopping short of it leaves an error
// of the same sign at every step (the iterates approach from the predictor's side), which adds
// up over a run: on maze_body_drag at the fast preset, stopping there without it took the body
// deviation from 0.17 to 0.53 mm, with it the deviation stays 0.17 mm (docs/solver.md).
// Not if the correction would move a node too close to a wall: then Newton goes on as before.
bool correction_converges(const Model& model, const NewtonProblem& p, Workspace& ws) {
  ws.dx = -ws.residual;
  banded_block_ldlt_solve(ws.jacobian, ws.dx);
  if (!(norm_inf_free(ws.dx, ws.fixed) <= p.correction_tol)) return false;
  const ForceContext ctx = context_of(p, ws.x, ws.v);
  for (std::size_t k = 0; k < model.forces.size(); ++k)
    if (model.forces[k]->max_step_fraction(module_context(ctx, ws, k), ws.dx) < 1.0) return false;
  ws.x += ws.dx;
  if (p.c > 0.0) ws.v.noalias() = (ws.x - ws.x_hat) * p.c;
  return true;
}

}  // namespace

double assemble(const Model& model, const NewtonProblem& p, const Eigen::VectorXd& x, Workspace& ws, bool jacobian) {
  const int n = model.nodes();
  BandedMatrix* jac = jacobian ? &ws.jacobian : nullptr;
  if (jac) {
    jac->set_zero();
    ws.off_band.clear();
  }
  if (p.c > 0.0) {
    ws.v.noalias() = (x - ws.x_hat) * p.c;
  } else {
    ws.v.setZero();
  }
  assemble_elastic(model.rod, x, ws.elastic, ws.gradient, jac);

  ws.force.setZero();
  if (!model.forces.empty()) {
    ForceContext ctx = context_of(p, x, ws.v);
    ctx.off_band = jac ? &ws.off_band : nullptr;
    for (std::size_t k = 0; k < model.forces.size(); ++k) model.forces[k]->add(module_context(ctx, ws, k), ws.force, jac);
  }

  double inertia_max = 0.0, grad_max = 0.0, force_max = 0.0;
  const double c2 = p.c * p.c;
  for (int i = 0; i < n; ++i) {
    const double m = model.rod.mass[i];
    for (int d = 2 * i; d < 2 * i + 2; ++d) {
      double inertia = 0.0;
      if (p.c > 0.0) {
        inertia = m * (ws.v[d] - ws.v_hat[d]) * p.c;
        if (jac) jac->add_diagonal(d, m * c2);
      }
      if (ws.fixed[static_cast<std::size_t>(d)]) {
        ws.residual[d] = 0.0;
        ws.reaction[d] = inertia + ws.gradient[d] - ws.force[d];
        continue;
      }
      ws.reaction[d] = 0.0;
      ws.residual[d] = inertia + ws.gradient[d] - ws.force[d];
      inertia_max = std::max(inertia_max, std::abs(inertia));
      grad_max = std::max(grad_max, std::abs(ws.gradient[d]));
      force_max = std::max(force_max, std::abs(ws.force[d]));
    }
  }
  if (jac)
    for (int d = 0; d < 2 * n; ++d)
      if (ws.fixed[static_cast<std::size_t>(d)]) jac->fix(d);
  return inertia_max + grad_max + force_max;
}

NewtonOutcome newton_solve(const Model& model, const NewtonProblem& p, Workspace& ws) {
  const SolverSpec& s = model.solver;
  const double step_floor = s.step_tol * std::max(model.rod.length, 1e-300);
  NewtonOutcome out;
  double scale = assemble(model, p, ws.x, ws, true);
  double rnorm2 = ws.residual.squaredNorm();
  int free_steps = 2;
  // Trial points are assembled without the Jacobian: most steps converge at their first trial,
  // whose Jacobian would never be used. Only an iterate that goes on is assembled again with it
  // (the residual comes out the same, bit for bit).
  bool jacobian_at_x = true;
  bool factored_without_off_band = false;
  for (;;) {
    const double rinf = norm_inf_free(ws.residual, ws.fixed);
    out.residual = rinf;
    out.scale = scale;
    if (!std::isfinite(rnorm2) || !std::isfinite(scale)) {
      out.failure = "the residual is not finite (the rod blew up)";
      return out;
    }
    // A held node's force is outside the residual, so a node driven into a wall (a prescribed
    // boundary motion, a kinematic tip's offset) would converge with it non-finite, unseen.
    if (!ws.reaction.allFinite()) {
      Eigen::Index d = 0;
      while (std::isfinite(ws.reaction[d])) ++d;
      out.failure = format("the force holding node %.0f is not finite: a node the scene moves (boundary.prescribed, "
                           "control.advance, a kinematic tip) is inside a wall", static_cast<double>(d / 2));
      return out;
    }
    if (rinf <= s.rel_tol * scale || rinf <= s.abs_tol) {
      out.converged = true;
      return out;
    }
    if (p.correction_tol > 0.0 && out.iterations > 0 && factored_without_off_band && correction_converges(model, p, ws)) {
      out.converged = true;
      out.correction_stop = true;
      return out;
    }
    if (out.iterations >= s.max_iterations) {
      out.failure = format("no convergence in %.0f Newton iterations (relative residual %.3g)",
                           static_cast<double>(out.iterations), rinf / std::max(scale, 1e-300));
      return out;
    }
    if (!jacobian_at_x) {
      scale = assemble(model, p, ws.x, ws, true);
      jacobian_at_x = true;
    }
    const double noise = p.c > 0.0 ? 0.0 : residual_round_off(ws.jacobian, ws.x);
    ws.dx = -ws.residual;
    if (ws.off_band.empty()) {
      // The 2x2-block factorisation: the same answer as banded_ldlt_factor up to round-off and
      // about 1.4x faster (a shorter dependency chain, docs/solver.md).
      const LdltResult f = banded_block_ldlt_factor(ws.jacobian);
      if (!f.ok) {
        out.failure = format("singular Newton matrix at degree of freedom %.0f (node %.0f)", f.failed_row, f.failed_row / 2);
        return out;
      }
      banded_block_ldlt_solve(ws.jacobian, ws.dx);
      factored_without_off_band = true;
      out.negative_pivots = f.negative_pivots;
    } else {
      factored_without_off_band = false;
      if (!sparse_ldlt_solve(ws.jacobian, ws.off_band, ws.fixed, ws.dx, &out.negative_pivots)) {
        out.failure = "singular Newton matrix (with self-contact)";
        return out;
      }
    }
    ++out.iterations;
    const double dx_inf = ws.dx.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(dx_inf)) {
      out.failure = "the Newton update is not finite";
      return out;
    }
    if (dx_inf <= step_floor) {
      // The update is below round-off: x + dx is as good as it gets in floating point, and a line
      // search on a residual that is all round-off noise would only thrash.
      ws.x += ws.dx;
      return round_off_stop(model, p, ws, out);
    }
    // Backtracking on |r|^2: the Newton direction descends it whenever the Jacobian is exact.
    // Modules may cap the first trial (a barrier must never see a closed gap).
    double alpha = 1.0;
    if (!model.forces.empty()) {
      const ForceContext ctx = context_of(p, ws.x, ws.v);
      for (std::size_t k = 0; k < model.forces.size(); ++k)
        alpha = std::min(alpha, model.forces[k]->max_step_fraction(module_context(ctx, ws, k), ws.dx));
      if (!(alpha > 0.0)) {
        out.failure = "a force module allows no step along the Newton direction";
        return out;
      }
    }
    // A watchdog lets the first two full steps of a solve through even if the residual grows:
    // a Newton step that bends a slender rod first stretches it (the linearisation moves nodes
    // sideways, not round), raising the residual a thousandfold just before quadratic
    // convergence, and backtracking there would crawl.
    bool accepted = false;
    for (int k = 0; k < 12; ++k) {
      ws.x_trial = ws.x + alpha * ws.dx;
      const double trial_scale = assemble(model, p, ws.x_trial, ws, false);
      jacobian_at_x = false;
      const double trial2 = ws.residual.squaredNorm();
      const bool watchdog = k == 0 && free_steps > 0;
      if (std::isfinite(trial2) && (watchdog || trial2 <= (1.0 - 1e-4 * alpha) * rnorm2)) {
        if (trial2 > rnorm2) --free_steps;
        ws.x.swap(ws.x_trial);
        scale = trial_scale;
        rnorm2 = trial2;
        accepted = true;
        break;
      }
      alpha *= 0.5;
    }
    if (!accepted && (dx_inf <= 1e3 * step_floor || rinf <= noise)) {
      // No decrease along a tiny update: the residual is round-off noise (near equilibrium a
      // tight relative tolerance can sit below it). Take the point we have.
      return round_off_stop(model, p, ws, out);
    }
    if (!accepted) {
      out.failure = format("line search failed (relative residual %.3g, |dx| %.3g m)",
                           std::sqrt(rnorm2) / std::max(scale, 1e-300), dx_inf);
      return out;
    }
  }
}

}  // namespace vascsim

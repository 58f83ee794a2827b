// Assembly of the Newton system and the damped Newton-Raphson solve shared by the time stepper
// and the static solver. The unknowns are the node positions at the end of the step.
//
// Residual (N), for every free degree of freedom:
//   dynamic:  r(x) = M (v(x) - v_hat) c + grad E(x) - F(x, v(x)),   v(x) = (x - x_hat) c
//   static:   r(x) = grad E(x) - F(x, 0)   (c = 0)
// with E the elastic energy, F the force modules, c = 1/(beta h) from the time scheme. Its
// Jacobian is M c^2 + Hess E + sum of the modules' stiffness, symmetric and banded.
// Converged when |r|_inf <= rel_tol * scale, scale = |M (v - v_hat) c|_inf + |grad E|_inf +
// |F|_inf over the free degrees of freedom: relative to the forces in balance, so independent
// of units (the paper's sum |F| < tol is not). Beside it: |r|_inf <= abs_tol, or a Newton update
// below round-off (|dx|_inf <= step_tol * L), where a tight relative tolerance may be out of reach.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "sim/step/banded_matrix.h"
#include "sim/step/controls.h"
#include "sim/step/elastic_assembly.h"
#include "sim/step/model.h"
#include "sim/step/state.h"

namespace vascsim {

// Scratch memory for one Model, allocated once; no data in it survives a step that matters.
struct Workspace {
  explicit Workspace(const Model& model);
  BandedMatrix jacobian;     // (2N x 2N), N/m
  Eigen::VectorXd residual;  // (2N), N
  Eigen::VectorXd gradient;  // (2N), N, grad E
  Eigen::VectorXd force;     // (2N), N, sum of the modules' forces
  // (2N), N, at held degrees of freedom (fixed): the force the constraint exerts on the rod at
  // the last assembled iterate (inertia + grad E - module forces); 0 elsewhere.
  Eigen::VectorXd reaction;
  OffBandEntries off_band;   // the Newton matrix's entries beyond the band (self-contact)
  Eigen::VectorXd x, v, dx, x_trial, x_hat, v_hat, target;  // (2N)
  std::vector<char> fixed;   // (2N), 1 for a prescribed degree of freedom
  ElasticScratch elastic;
  std::vector<std::unique_ptr<ModuleCache>> caches;  // one per Model::forces entry (null: none)
  // Behind a pointer: module_context() hands modules a mutable entry from a const Workspace.
  std::unique_ptr<SharedCaches> shared = std::make_unique<SharedCaches>();
};

// `ctx` for force module k of `model`, with its cache in `ws`.
inline ForceContext module_context(ForceContext ctx, const Workspace& ws, std::size_t k) {
  ctx.cache = ws.caches[k].get();
  ctx.shared = ws.shared.get();
  return ctx;
}

// One nonlinear solve. x_hat, v_hat and target are read from the Workspace.
struct NewtonProblem {
  double t = 0.0;           // s, time at the solution
  double c = 0.0;           // 1/s, dv/dx; 0 for a static solve
  double load_scale = 1.0;  // applied-load factor
  const Controls* controls = nullptr;
  const State* start = nullptr;
  // m, error control only (0: off): also converged when the next Newton correction, estimated
  // with the last factorisation, is at most this in every free degree of freedom.
  double correction_tol = 0.0;
};

struct NewtonOutcome {
  bool converged = false;
  int iterations = 0;         // linear solves
  double residual = 0.0;      // N, |r|_inf at the end
  double scale = 0.0;         // N, force scale at the end
  bool round_off_stop = false;  // stopped because the update fell below round-off
  bool correction_stop = false;  // stopped by correction_tol
  // Negative pivots of the last factored Newton matrix, banded or with self-contact's off-band
  // entries (-1: none factored): above 0 the solution is a saddle, not a minimum, of the energy Newton
  // balances (the static energy, or a dynamic step's incremental potential).
  int negative_pivots = -1;
  std::string failure;        // why, when !converged
};

// Fills ws.residual (and ws.jacobian when `jacobian`) at positions x; returns the force scale.
double assemble(const Model& model, const NewtonProblem& problem, const Eigen::VectorXd& x, Workspace& ws,
                bool jacobian);
// Newton from the guess in ws.x (prescribed entries already at ws.target); the answer in ws.x,
// velocities in ws.v.
NewtonOutcome newton_solve(const Model& model, const NewtonProblem& problem, Workspace& ws);

}  // namespace vascsim

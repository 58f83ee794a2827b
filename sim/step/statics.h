// Static equilibrium by load stepping: the applied loads (ForceContext::load_scale) ramp from 0
// to 1 in increments, each solved by Newton from the previous equilibrium; a failed increment is
// halved and retried, a quick one lets the next grow. Velocity-dependent forces vanish (v = 0).
// Needs enough constraints to remove rigid motion (otherwise the Newton matrix is singular and
// the report says so). Validation and many user questions are static (issue 3).
#pragma once

#include <functional>
#include <string>

#include "sim/step/controls.h"
#include "sim/step/model.h"
#include "sim/step/newton.h"
#include "sim/step/state.h"

namespace vascsim {

struct StaticReport {
  bool ok = false;
  int increments = 0;        // accepted load increments
  int rejected = 0;          // failed increments (retried smaller)
  // Increments retried smaller because Newton went from a stable equilibrium to an unstable one
  // (with SolverSpec::stable_branch): it jumped off the branch the load was following.
  int stability_cuts = 0;
  // Where even the smallest increments failed to follow the branch, the solve took the jump
  // after all (as without the check): how often, and the load factor of the first. The
  // equilibrium may then lie on another branch than slower loading would reach.
  int branch_jumps = 0;
  double first_jump_load = 0.0;
  int iterations = 0;        // Newton iterations over all increments
  double load_scale = 0.0;   // reached
  // Negative pivots of the Newton matrix at the equilibrium returned: its count of negative
  // eigenvalues (Sylvester's law of inertia). Above 0 the equilibrium is unstable (a column
  // loaded past its buckling load stays straight, but a nudge would make it buckle).
  int negative_pivots = 0;
  // With SolverSpec::stable_branch, when the load path ended at an unstable equilibrium: its
  // negative pivots, and whether the solve left it for a stable one (sim/step/stable_branch.h).
  int unstable_pivots = 0;
  bool left_unstable = false;
  std::string branch_failure;  // why it could not, when unstable_pivots > 0 and !left_unstable
  // The eigenvalue of the Newton matrix nearest zero at the equilibrium returned (N/m, for a unit
  // vector) and its round-off; when it is within that, the count of negative pivots, and with it
  // the stability, is not decided (a very fine mesh: sim/step/stability_margin.h).
  double smallest_eigenvalue = 0.0;
  double eigenvalue_round_off = 0.0;
  bool stability_undecided = false;
  std::string failure;
  std::string stopped_by;  // who ended the solve before full load (stop_reason's answer), or empty
};

// Solves from state.x; on success state.x is the equilibrium, v = 0 and the BDF2 history reset.
// On failure state.x holds the last converged increment (load_scale in the report).
// With model.solver.stable_branch (the default) the load path keeps to the stable branch where it
// can: an increment that goes from a stable equilibrium to an unstable one is retried smaller
// (Newton jumped off the branch); where even the smallest one does (a bifurcation or the
// branch's end) the path goes on along the unstable root, and the unstable equilibrium at full
// load is left for a stable one; if that fails the unstable one is returned (report.ok,
// negative_pivots > 0). Where Newton fails on the smaller increments, the solve takes the cut
// one after all and counts it (report.branch_jumps).
// `stop_reason` (may be empty) is asked before each increment, as Run::run asks between steps: a
// non-empty answer ends the solve there, failed, with `stopped_by` set and state.x the last
// converged increment.
StaticReport solve_static(const Model& model, State& state, Workspace& ws, const Controls& controls,
                          const std::function<std::string()>& stop_reason = {});

}  // namespace vascsim

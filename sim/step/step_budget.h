// The floor under error control's steps, which bounds what a run can cost when its error estimate
// asks for ever shorter steps (an undamped rod rattling on a wall, docs/accuracy.md). Two parts:
// a hard floor (solver.dt_floor: no step is shorter) and a floor on the mean step
// (solver.dt_mean_min with solver.mean_burst): steps shorter than dt_mean_min are taken only while
// the run has credit for them. A step of h changes the credit by h / dt_mean_min - 1, capped at
// mean_burst steps, so gliding earns what an impact spends, and over any stretch of T seconds the
// run takes at most T / dt_mean_min + mean_burst steps; a brief event is still resolved to the
// tolerance. A step at the floor in force is kept whatever its error. Per-run state: it lives with
// the run, not the model.
#pragma once

#include <algorithm>

namespace vascsim {

class StepBudget {
 public:
  StepBudget(double dt_floor, double dt_mean_min, double mean_burst)
      : hard_(dt_floor), mean_(dt_mean_min), burst_(mean_burst), credit_(mean_burst) {}

  // s: the shortest step allowed now (0: none).
  double floor() const { return std::max(hard_, mean_ > 0.0 && credit_ < 1.0 ? mean_ : 0.0); }
  // Records an accepted step of h (s).
  void spend(double h) {
    if (mean_ > 0.0) credit_ = std::min(burst_, credit_ + h / mean_ - 1.0);
  }

 private:
  double hard_, mean_, burst_, credit_;  // s, s, steps, steps
};

}  // namespace vascsim

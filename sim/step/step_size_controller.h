// Chooses the next step size from the error of the last one, as stiff integrators do (Hairer &
// Wanner, Solving ODEs II, IV.8; Gustafsson's PI controller). The error is per unit step (the
// local error of sim/step/local_error.h divided by h, which shrinks as h^order), so after an
// accepted step h_new = h * safety * err^(-0.7/k) * err_prev^(0.4/k), k = order,
// which damps the step-size oscillation a plain err^(-1/k) rule shows on stiff problems; after a
// rejected one h_new = h * max(min_shrink, safety * err^(-1/k)), without growth on the next
// accepted step. Growth is capped at kMaxBdf2StepRatio (BDF2's zero-stability) and the step
// stays within [shortest, dt_max], where the run passes the shortest step allowed now (dt_min, or
// the floor of its StepBudget). One controller per run: it lives with the run's state.
#pragma once

namespace vascsim {

class StepSizeController {
 public:
  explicit StepSizeController(double dt_max) : dt_max_(dt_max) {}

  // The step after an accepted one of h with error per unit step err (<= 1), order 1 or 2, not
  // shorter than `shortest` (s).
  double accepted(double h, double err, int order, double shortest);
  // The retry after a rejected one of h with error err (> 1).
  double rejected(double h, double err, int order, double shortest);

  static constexpr double kSafety = 0.9;
  static constexpr double kMinShrink = 0.2;

 private:
  double clamp(double h, double shortest) const;

  double dt_max_;
  double err_prev_ = 1.0;
  bool after_rejection_ = false;
};

}  // namespace vascsim

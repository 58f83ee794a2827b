#include "sim/step/step_size_controller.h"

#include <algorithm>
#include <cmath>

#include "sim/step/stepper.h"

namespace vascsim {

double StepSizeController::clamp(double h, double shortest) const { return std::min(dt_max_, std::max(shortest, h)); }

double StepSizeController::accepted(double h, double err, int order, double shortest) {
  const double k = order;
  // An error of exactly 0 (a rod at rest) would ask for infinite growth; the cap takes over.
  const double e = std::max(err, 1e-10);
  double factor = kSafety * std::pow(e, -0.7 / k) * std::pow(err_prev_, 0.4 / k);
  factor = std::min(factor, kMaxBdf2StepRatio);
  if (after_rejection_) factor = std::min(factor, 1.0);
  factor = std::max(factor, kMinShrink);
  err_prev_ = std::max(e, 1e-4);
  after_rejection_ = false;
  return clamp(h * factor, shortest);
}

double StepSizeController::rejected(double h, double err, int order, double shortest) {
  const double k = order;
  after_rejection_ = true;
  return clamp(h * std::max(kMinShrink, std::min(0.9, kSafety * std::pow(err, -1.0 / k))), shortest);
}

}  // namespace vascsim

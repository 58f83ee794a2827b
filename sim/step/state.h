// State: everything about a run that changes with time (MuJoCo's mjData to the Model's mjModel).
// The stepper advances it; it commits a step only when Newton converged, so a State is always a
// converged point of the trajectory.
#pragma once

#include <Eigen/Core>

namespace vascsim {

struct State {
  double t = 0.0;      // s
  Eigen::VectorXd x;   // (2N), m, node positions interleaved x0 y0 x1 y1 ...
  Eigen::VectorXd v;   // (2N), m/s, node velocities, same layout
  // The previous step, for BDF2 (x_{n-1}, v_{n-1}, h_{n-1}); h_prev = 0 when there is none
  // (first step, after a static solve, or after an external edit of x or v).
  Eigen::VectorXd x_prev;  // (2N), m
  Eigen::VectorXd v_prev;  // (2N), m/s
  double h_prev = 0.0;     // s
  // The step before that, for the error estimate's predictor (sim/step/local_error.h); h_prev2 = 0
  // when there is none.
  Eigen::VectorXd x_prev2;  // (2N), m
  Eigen::VectorXd v_prev2;  // (2N), m/s
  double h_prev2 = 0.0;     // s

  int nodes() const { return static_cast<int>(x.size() / 2); }
  Eigen::Vector2d position(int node) const { return x.segment<2>(2 * node); }
  Eigen::Vector2d velocity(int node) const { return v.segment<2>(2 * node); }
};

}  // namespace vascsim

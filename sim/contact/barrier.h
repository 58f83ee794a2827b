// The contact barrier of Incremental Potential Contact (Li et al., ACM TOG 39(4), 2020), in a
// force-scaled form: for a gap g between rod surface and wall surface and an activation
// distance g_hat,
//   E(g) = kappa g_hat b(g / g_hat),  b(s) = -(s - 1)^2 ln s  for 0 < s < 1, and 0 beyond,
// so that kappa is a force (N): the push at half the activation distance is about 1.19 kappa.
// b is C2 at s = 1 and grows without bound as s -> 0, so a step that keeps g > 0 never lets a
// node cross a wall, however large the time step.
#pragma once

#include <cmath>

namespace vascsim {

struct BarrierValue {
  double energy = 0.0;  // J
  double first = 0.0;   // dE/dg, N (negative: pushes the gap open)
  double second = 0.0;  // d2E/dg2, N/m (positive)
};

inline BarrierValue contact_barrier(double gap, double g_hat, double kappa) {
  BarrierValue v;
  if (gap >= g_hat) return v;
  const double s = gap / g_hat;
  const double ln_s = std::log(s);
  // b = -(s-1)^2 ln s;  b' = -2 (s-1) ln s - (s-1)^2 / s;  b'' = -2 ln s - 4 (s-1) / s + (s-1)^2 / s^2
  const double t = s - 1.0;
  v.energy = kappa * g_hat * (-t * t * ln_s);
  v.first = kappa * (-2.0 * t * ln_s - t * t / s);
  v.second = kappa / g_hat * (-2.0 * ln_s - 4.0 * t / s + t * t / (s * s));
  return v;
}

}  // namespace vascsim

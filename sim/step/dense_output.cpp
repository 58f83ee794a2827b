#include "sim/step/dense_output.h"

namespace vascsim {

State interpolate_in_step(const State& start, const State& end, double t) {
  const double h = end.t - start.t;
  const double s = (t - start.t) / h;
  const double s2 = s * s, s3 = s2 * s;
  // Hermite basis on [0, 1] and its derivative (d/dt = d/ds / h).
  const double p0 = 2 * s3 - 3 * s2 + 1, m0 = s3 - 2 * s2 + s, p1 = -2 * s3 + 3 * s2, m1 = s3 - s2;
  const double dp0 = 6 * s2 - 6 * s, dm0 = 3 * s2 - 4 * s + 1, dp1 = -dp0, dm1 = 3 * s2 - 2 * s;
  State out;
  out.t = t;
  out.x = p0 * start.x + (m0 * h) * start.v + p1 * end.x + (m1 * h) * end.v;
  out.v = (dp0 / h) * start.x + dm0 * start.v + (dp1 / h) * end.x + dm1 * end.v;
  return out;
}

}  // namespace vascsim

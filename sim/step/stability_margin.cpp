#include "sim/step/stability_margin.h"

#include <cmath>

#include "sim/step/banded_ldlt.h"

namespace vascsim {

StabilityMargin stability_margin(const BandedMatrix& stiffness, const BandedMatrix& factor,
                                 const std::vector<char>& fixed) {
  const int n = stiffness.size();
  // A fixed start that is not orthogonal to a smooth soft mode: alternating-sign vectors would be,
  // to first order, for a rod whose softest modes bend it.
  Eigen::VectorXd y(n), ky(n);
  for (int d = 0; d < n; ++d) y[d] = fixed[static_cast<std::size_t>(d)] ? 0.0 : 1.0 + 0.5 * std::sin(0.7 * d);
  StabilityMargin margin;
  if (!(y.norm() > 0.0)) return margin;
  y.normalize();
  // 20 iterations: the softest mode of a rod is well separated from the next (a ratio of 6 or more
  // for a cantilever's first two), so the vector has converged long before; where it has not, the
  // residual stays large and the sign is called undecided, the safe side.
  for (int k = 0; k < 20; ++k) {
    banded_block_ldlt_solve(factor, y);
    for (int d = 0; d < n; ++d)
      if (fixed[static_cast<std::size_t>(d)]) y[d] = 0.0;
    const double norm = y.norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) return margin;
    y /= norm;
  }
  stiffness.multiply(y, ky);
  for (int d = 0; d < n; ++d)
    if (fixed[static_cast<std::size_t>(d)]) ky[d] = 0.0;
  margin.eigenvalue = y.dot(ky);
  margin.round_off = (ky - margin.eigenvalue * y).norm();
  return margin;
}

}  // namespace vascsim

#include "sim/step/banded_ldlt.h"

#include <cmath>

namespace vascsim {

// Row-oriented (Doolittle) LDL^T: for row i and j = i-5 .. i,
//   s = A(i,j) - sum_{k<j} L(i,k) D(k) L(j,k),  L(i,j) = s / D(j) (j < i),  D(i) = s (j = i),
// where k runs over the band of both rows. w_k = L(i,k) D(k) is kept to save a multiply.
LdltResult banded_ldlt_factor(BandedMatrix& a, double pivot_tol) {
  constexpr int W = BandedMatrix::kWidth;
  constexpr int K = BandedMatrix::kHalfBandwidth;
  const int n = a.size();
  double* band = a.data();
  LdltResult result;
  for (int i = 0; i < n; ++i) {
    double* row = band + static_cast<std::size_t>(i) * W;  // row[m] = A(i, i-m)
    const int j0 = i - K < 0 ? 0 : i - K;
    double w[W];  // w[m] = L(i, i-m) * D(i-m)
    for (int j = j0; j < i; ++j) {
      const double* rowj = band + static_cast<std::size_t>(j) * W;
      double s = row[i - j];
      for (int k = j0; k < j; ++k) s -= w[i - k] * rowj[j - k];
      const double d = rowj[0];
      w[i - j] = s;
      row[i - j] = s / d;
    }
    const double diag = row[0];
    double s = diag;
    for (int k = j0; k < i; ++k) s -= w[i - k] * row[i - k];
    if (!std::isfinite(s) || std::abs(s) <= pivot_tol * std::abs(diag) || s == 0.0) {
      result.failed_row = i;
      return result;
    }
    if (s < 0.0) ++result.negative_pivots;
    row[0] = s;
  }
  result.ok = true;
  return result;
}

void banded_ldlt_solve(const BandedMatrix& factor, Eigen::VectorXd& b) {
  constexpr int W = BandedMatrix::kWidth;
  constexpr int K = BandedMatrix::kHalfBandwidth;
  const int n = factor.size();
  const double* band = factor.data();
  // L y = b
  for (int i = 0; i < n; ++i) {
    const double* row = band + static_cast<std::size_t>(i) * W;
    double s = b[i];
    for (int m = 1; m <= K && i - m >= 0; ++m) s -= row[m] * b[i - m];
    b[i] = s;
  }
  // D z = y
  for (int i = 0; i < n; ++i) b[i] /= band[static_cast<std::size_t>(i) * W];
  // L^T x = z
  for (int i = n - 1; i >= 0; --i) {
    const double xi = b[i];
    const double* row = band + static_cast<std::size_t>(i) * W;
    for (int m = 1; m <= K && i - m >= 0; ++m) b[i - m] -= row[m] * xi;
  }
}

}  // namespace vascsim

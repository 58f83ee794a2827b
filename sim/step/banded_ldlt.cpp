#include "sim/step/banded_ldlt.h"

#include <cmath>

namespace vascsim {

// Row-oriented (Doolittle) LDL^T: for row i and j = i-5 .. i,
//   s = A(i,j) - sum_{k<j} L(i,k) D(k) L(j,k),  L(i,j) = s / D(j) (j < i),  D(i) = s (j = i),
// where k runs over the band of both rows. w_m = L(i,i-m) D(i-m) is kept to save a multiply,
// and the diagonal stores 1/D so that neither factor nor solve divides in the inner loops.
// Rows i >= 5 have the full band and take the unrolled path (constant loop bounds).
LdltResult banded_ldlt_factor(BandedMatrix& a, double pivot_tol) {
  constexpr int W = BandedMatrix::kWidth;
  constexpr int K = BandedMatrix::kHalfBandwidth;
  const int n = a.size();
  double* band = a.data();
  LdltResult result;
  for (int i = 0; i < n; ++i) {
    double* row = band + static_cast<std::size_t>(i) * W;  // row[m] = A(i, i-m)
    const int mmax = i < K ? i : K;                         // columns i-mmax .. i-1 are in the band
    double w[W] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double diag;
    if (mmax == K) {
      for (int m = K; m >= 1; --m) {
        const double* rowj = row - static_cast<std::ptrdiff_t>(m) * W;  // row i-m
        double s = row[m];
        for (int mk = K; mk > m; --mk) s -= w[mk] * rowj[mk - m];
        w[m] = s;
        row[m] = s * rowj[0];
      }
      diag = row[0];
      for (int m = 1; m <= K; ++m) diag -= w[m] * row[m];
    } else {
      for (int m = mmax; m >= 1; --m) {
        const double* rowj = row - static_cast<std::ptrdiff_t>(m) * W;
        double s = row[m];
        for (int mk = mmax; mk > m; --mk) s -= w[mk] * rowj[mk - m];
        w[m] = s;
        row[m] = s * rowj[0];
      }
      diag = row[0];
      for (int m = 1; m <= mmax; ++m) diag -= w[m] * row[m];
    }
    if (!std::isfinite(diag) || diag == 0.0 || std::abs(diag) <= pivot_tol * std::abs(row[0])) {
      result.failed_row = i;
      return result;
    }
    if (diag < 0.0) ++result.negative_pivots;
    row[0] = 1.0 / diag;
  }
  result.ok = true;
  return result;
}

void banded_ldlt_solve(const BandedMatrix& factor, Eigen::VectorXd& b) {
  constexpr int W = BandedMatrix::kWidth;
  constexpr int K = BandedMatrix::kHalfBandwidth;
  const int n = factor.size();
  const double* band = factor.data();
  // L y = b, then D z = y (the diagonal holds 1/D), in one pass
  for (int i = 0; i < n; ++i) {
    const double* row = band + static_cast<std::size_t>(i) * W;
    double s = b[i];
    for (int m = 1; m <= K && i - m >= 0; ++m) s -= row[m] * b[i - m];
    b[i] = s;
  }
  for (int i = 0; i < n; ++i) b[i] *= band[static_cast<std::size_t>(i) * W];
  // L^T x = z
  for (int i = n - 1; i >= 0; --i) {
    const double xi = b[i];
    const double* row = band + static_cast<std::size_t>(i) * W;
    for (int m = 1; m <= K && i - m >= 0; ++m) b[i - m] -= row[m] * xi;
  }
}

}  // namespace vascsim

#include "sim/step/banded_ldlt.h"

#include <algorithm>
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

namespace vascsim {

namespace {

// A 2x2 block as plain numbers: [a b; c d].
struct M2 {
  double a, b, c, d;
};
inline M2 mul(const M2& x, const M2& y) {
  return {x.a * y.a + x.b * y.c, x.a * y.b + x.b * y.d, x.c * y.a + x.d * y.c, x.c * y.b + x.d * y.d};
}
// x * y^T
inline M2 mul_t(const M2& x, const M2& y) {
  return {x.a * y.a + x.b * y.b, x.a * y.c + x.b * y.d, x.c * y.a + x.d * y.b, x.c * y.c + x.d * y.d};
}

// Band row r holds A(r, r-m) at row[m]. Block (i, j), j = i-1 or i-2, rows 2i, 2i+1.
inline M2 get_block(const double* band, int i, int j) {
  constexpr int W = BandedMatrix::kWidth;
  const double* r0 = band + static_cast<std::size_t>(2 * i) * W;
  const double* r1 = r0 + W;
  const int o = 2 * (i - j);  // offset of column 2j in row 2i
  return {r0[o], r0[o - 1], r1[o + 1], r1[o]};
}
inline void set_block(double* band, int i, int j, const M2& m) {
  constexpr int W = BandedMatrix::kWidth;
  double* r0 = band + static_cast<std::size_t>(2 * i) * W;
  double* r1 = r0 + W;
  const int o = 2 * (i - j);
  r0[o] = m.a;
  r0[o - 1] = m.b;
  r1[o + 1] = m.c;
  r1[o] = m.d;
}

}  // namespace

inline M2 get_diag(const double* band, int i) {
  constexpr int W = BandedMatrix::kWidth;
  const double* r0 = band + static_cast<std::size_t>(2 * i) * W;
  const double* r1 = r0 + W;
  return {r0[0], r1[1], r1[1], r1[0]};
}

// Block LDL^T, for block row i (W_k = L(i,k) D_k):
//   W2 = A(i,i-2),                   L2 = W2 D_{i-2}^-1
//   W1 = A(i,i-1) - W2 L(i-1,i-2)^T, L1 = W1 D_{i-1}^-1
//   D_i = A(i,i) - L2 W2^T - L1 W1^T
LdltResult banded_block_ldlt_factor(BandedMatrix& a, double pivot_tol) {
  constexpr int W = BandedMatrix::kWidth;
  LdltResult result;
  const int nodes = a.size() / 2;
  double* band = a.data();
  for (int i = 0; i < nodes; ++i) {
    M2 d = get_diag(band, i);
    const double scale = std::abs(d.a) + std::abs(d.d) + 2.0 * std::abs(d.b);
    if (i >= 2) {
      const M2 w2 = get_block(band, i, i - 2);
      const M2 l2 = mul(w2, get_diag(band, i - 2));
      const M2 lt = get_block(band, i - 1, i - 2);  // L(i-1, i-2), already factored
      M2 w1 = get_block(band, i, i - 1);
      const M2 c = mul_t(w2, lt);
      w1 = {w1.a - c.a, w1.b - c.b, w1.c - c.c, w1.d - c.d};
      const M2 l1 = mul(w1, get_diag(band, i - 1));
      const M2 e2 = mul_t(l2, w2), e1 = mul_t(l1, w1);
      d = {d.a - e2.a - e1.a, d.b - e2.b - e1.b, d.c - e2.c - e1.c, d.d - e2.d - e1.d};
      set_block(band, i, i - 2, l2);
      set_block(band, i, i - 1, l1);
    } else if (i == 1) {
      const M2 w1 = get_block(band, 1, 0);
      const M2 l1 = mul(w1, get_diag(band, 0));
      const M2 e1 = mul_t(l1, w1);
      d = {d.a - e1.a, d.b - e1.b, d.c - e1.c, d.d - e1.d};
      set_block(band, 1, 0, l1);
    }
    // The pivot vanishes when its smallest eigenvalue is at the round-off of the entries it was
    // computed from: |lambda_min| <= pivot_tol * scale, the scalar test's |d_i| <= pivot_tol |A(i,i)|
    // per eigenvalue. D is symmetric, so |lambda_max| <= |D|_inf <= sqrt 2 |lambda_max| and
    // |det| / |D|_inf is |lambda_min| to within a factor sqrt 2, without a square root.
    // Comparing det with scale^2 instead (as before issue 16) tested the product of the two
    // eigenvalues: at the tip of a bent, finely meshed cantilever both are O(EI/L^3) while scale is
    // O(EA/dl), and their product fell below 1e-13 scale^2 at a few hundred nodes.
    const double det = d.a * d.d - d.b * d.c;
    const double d_norm = std::max(std::abs(d.a) + std::abs(d.b), std::abs(d.c) + std::abs(d.d));
    if (!std::isfinite(det) || det == 0.0 || std::abs(det) <= pivot_tol * d_norm * scale) {
      result.failed_row = 2 * i + 1;
      return result;
    }
    if (det < 0.0) ++result.negative_pivots;
    else if (d.a + d.d < 0.0) result.negative_pivots += 2;
    const double inv = 1.0 / det;
    double* r0 = band + static_cast<std::size_t>(2 * i) * W;
    double* r1 = r0 + W;
    r0[0] = d.d * inv;
    r1[1] = -0.5 * (d.b + d.c) * inv;
    r1[0] = d.a * inv;
  }
  result.ok = true;
  return result;
}

namespace {

// L^T x = z in place, for a block factor.
void block_back_substitute(const BandedMatrix& factor, Eigen::VectorXd& b) {
  const int nodes = factor.size() / 2;
  const double* band = factor.data();
  for (int i = nodes - 1; i >= 0; --i) {
    double x0 = b[2 * i], x1 = b[2 * i + 1];
    if (i + 1 < nodes) {
      const M2 l = get_block(band, i + 1, i);
      x0 -= l.a * b[2 * i + 2] + l.c * b[2 * i + 3];
      x1 -= l.b * b[2 * i + 2] + l.d * b[2 * i + 3];
    }
    if (i + 2 < nodes) {
      const M2 l = get_block(band, i + 2, i);
      x0 -= l.a * b[2 * i + 4] + l.c * b[2 * i + 5];
      x1 -= l.b * b[2 * i + 4] + l.d * b[2 * i + 5];
    }
    b[2 * i] = x0;
    b[2 * i + 1] = x1;
  }
}

// Eigen-decomposition of a symmetric 2x2 [p q; q s]: eigenvalues lo <= hi, and the unit
// eigenvector of lo (that of hi is its perpendicular).
struct Eigen2 {
  double lo, hi;
  double vx, vy;
};
Eigen2 eigen2(double p, double q, double s) {
  const double mean = 0.5 * (p + s);
  const double radius = std::hypot(0.5 * (p - s), q);
  Eigen2 e{mean - radius, mean + radius, 1.0, 0.0};
  // (q, lo - p) and (lo - s, q) both solve the eigen-equation; the longer is the better conditioned.
  const double ax = q, ay = e.lo - p, bx = e.lo - s, by = q;
  const double na = std::hypot(ax, ay), nb = std::hypot(bx, by);
  if (na >= nb && na > 0.0) {
    e.vx = ax / na;
    e.vy = ay / na;
  } else if (nb > 0.0) {
    e.vx = bx / nb;
    e.vy = by / nb;
  } else if (p > s) {  // diagonal: lo is s
    e.vx = 0.0;
    e.vy = 1.0;
  }
  return e;
}

}  // namespace

void banded_block_ldlt_solve(const BandedMatrix& factor, Eigen::VectorXd& b) {
  const int nodes = factor.size() / 2;
  const double* band = factor.data();
  // L y = b
  for (int i = 1; i < nodes; ++i) {
    double y0 = b[2 * i], y1 = b[2 * i + 1];
    const M2 l1 = get_block(band, i, i - 1);
    y0 -= l1.a * b[2 * i - 2] + l1.b * b[2 * i - 1];
    y1 -= l1.c * b[2 * i - 2] + l1.d * b[2 * i - 1];
    if (i >= 2) {
      const M2 l2 = get_block(band, i, i - 2);
      y0 -= l2.a * b[2 * i - 4] + l2.b * b[2 * i - 3];
      y1 -= l2.c * b[2 * i - 4] + l2.d * b[2 * i - 3];
    }
    b[2 * i] = y0;
    b[2 * i + 1] = y1;
  }
  // D z = y
  for (int i = 0; i < nodes; ++i) {
    const M2 dinv = get_diag(band, i);
    const double y0 = b[2 * i], y1 = b[2 * i + 1];
    b[2 * i] = dinv.a * y0 + dinv.b * y1;
    b[2 * i + 1] = dinv.c * y0 + dinv.d * y1;
  }
  block_back_substitute(factor, b);
}

// With z zero but for the block pivot's eigenvector u of a negative eigenvalue, y = L^-T z gives
// y^T A y = z^T D z = lambda |u|^2 < 0. The stored D_i^-1 has the same eigenvectors as D_i and
// eigenvalues of the same signs.
Eigen::VectorXd banded_block_ldlt_negative_direction(const BandedMatrix& factor) {
  const int nodes = factor.size() / 2;
  const double* band = factor.data();
  Eigen::VectorXd y = Eigen::VectorXd::Zero(factor.size());
  for (int i = 0; i < nodes; ++i) {
    const M2 dinv = get_diag(band, i);
    const Eigen2 e = eigen2(dinv.a, dinv.b, dinv.d);
    if (e.lo < 0.0) {
      y[2 * i] = e.vx;
      y[2 * i + 1] = e.vy;
      block_back_substitute(factor, y);
      return y;
    }
  }
  return y;
}

void banded_block_ldlt_absolute_pivots(BandedMatrix& factor) {
  constexpr int W = BandedMatrix::kWidth;
  const int nodes = factor.size() / 2;
  double* band = factor.data();
  for (int i = 0; i < nodes; ++i) {
    const M2 dinv = get_diag(band, i);
    const Eigen2 e = eigen2(dinv.a, dinv.b, dinv.d);
    if (e.lo >= 0.0) continue;
    // |D^-1| = |lo| u u^T + |hi| w w^T, w the perpendicular of u.
    const double lo = std::abs(e.lo), hi = std::abs(e.hi);
    double* r0 = band + static_cast<std::size_t>(2 * i) * W;
    double* r1 = r0 + W;
    r0[0] = lo * e.vx * e.vx + hi * e.vy * e.vy;
    r1[1] = (lo - hi) * e.vx * e.vy;
    r1[0] = lo * e.vy * e.vy + hi * e.vx * e.vx;
  }
}

}  // namespace vascsim

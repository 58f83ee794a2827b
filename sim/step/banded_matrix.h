// BandedMatrix: a symmetric matrix with half-bandwidth 5 stored as its lower band, row by row.
// The planar DER couples node i with nodes i-1 and i+1 only (bending hinges span three nodes),
// so with interleaved x/y degrees of freedom every entry A(i, j) of the Newton matrix has
// |i - j| <= 5. Contact on nodes and on edges keeps within that band too. Row-major band storage
// keeps one row's entries in one cache line (6 doubles), which the factorisation walks in order.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace vascsim {

class BandedMatrix {
 public:
  static constexpr int kHalfBandwidth = 5;
  static constexpr int kWidth = kHalfBandwidth + 1;  // stored values per row

  BandedMatrix() = default;
  explicit BandedMatrix(int size) { resize(size); }
  void resize(int size) {
    size_ = size;
    band_.assign(static_cast<std::size_t>(size) * kWidth, 0.0);
  }
  void set_zero() { std::fill(band_.begin(), band_.end(), 0.0); }
  int size() const { return size_; }

  // A(i, j) for j <= i <= j + 5; (i, j) above the diagonal is its mirror (j, i).
  double& lower(int i, int j) { return band_[static_cast<std::size_t>(i) * kWidth + (i - j)]; }
  double lower(int i, int j) const { return band_[static_cast<std::size_t>(i) * kWidth + (i - j)]; }
  // Symmetric access; zero outside the band.
  double at(int i, int j) const {
    if (i < j) std::swap(i, j);
    return i - j > kHalfBandwidth ? 0.0 : lower(i, j);
  }
  // Adds a symmetric element block (dim x dim) whose rows/columns are the consecutive degrees of
  // freedom first .. first+dim-1; only its lower triangle is read.
  template <int Dim>
  void add_block(int first, const Eigen::Matrix<double, Dim, Dim>& block) {
    static_assert(Dim <= kWidth, "an element block must fit in the band");
    for (int r = 0; r < Dim; ++r) {
      double* row = &band_[static_cast<std::size_t>(first + r) * kWidth];
      for (int c = 0; c <= r; ++c) row[r - c] += block(r, c);
    }
  }
  void add_diagonal(int i, double value) { band_[static_cast<std::size_t>(i) * kWidth] += value; }
  // Replaces row and column i by those of the identity (a fixed degree of freedom).
  void fix(int i) {
    double* row = &band_[static_cast<std::size_t>(i) * kWidth];
    for (int k = 1; k < kWidth; ++k) row[k] = 0.0;
    for (int k = 1; k < kWidth && i + k < size_; ++k) band_[static_cast<std::size_t>(i + k) * kWidth + k] = 0.0;
    row[0] = 1.0;
  }
  // y = A x.
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  Eigen::MatrixXd to_dense() const;

  double* data() { return band_.data(); }
  const double* data() const { return band_.data(); }

 private:
  int size_ = 0;
  std::vector<double> band_;  // row i holds A(i, i), A(i, i-1), ..., A(i, i-5)
};

}  // namespace vascsim

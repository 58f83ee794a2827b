#include "sim/step/banded_matrix.h"

namespace vascsim {

void BandedMatrix::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  y.setZero(size_);
  for (int i = 0; i < size_; ++i) {
    y[i] += lower(i, i) * x[i];
    for (int k = 1; k < kWidth && i - k >= 0; ++k) {
      const double a = lower(i, i - k);
      y[i] += a * x[i - k];
      y[i - k] += a * x[i];
    }
  }
}

Eigen::MatrixXd BandedMatrix::to_dense() const {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(size_, size_);
  for (int i = 0; i < size_; ++i)
    for (int k = 0; k < kWidth && i - k >= 0; ++k) a(i, i - k) = a(i - k, i) = lower(i, i - k);
  return a;
}

}  // namespace vascsim

// One comparison for vectors and matrices in tests (Drake's CompareMatrices): passes when every
// entry of `actual` is within `tolerance` of `expected`, and otherwise prints the worst entry and
// both matrices, so a failure says where and by how much.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <sstream>

namespace vascsim::test {

inline ::testing::AssertionResult matrices_near(const Eigen::MatrixXd& actual, const Eigen::MatrixXd& expected,
                                                double tolerance) {
  if (actual.rows() != expected.rows() || actual.cols() != expected.cols())
    return ::testing::AssertionFailure() << "sizes differ: " << actual.rows() << "x" << actual.cols() << " vs "
                                         << expected.rows() << "x" << expected.cols();
  Eigen::Index r = 0, c = 0;
  const double worst = actual.size() ? (actual - expected).cwiseAbs().maxCoeff(&r, &c) : 0.0;
  if (worst <= tolerance) return ::testing::AssertionSuccess();
  std::ostringstream out;
  const Eigen::IOFormat compact(4, 0, " ", "\n", "  [", "]");
  out << "largest difference " << worst << " > " << tolerance << " at (" << r << ", " << c << "): " << actual(r, c)
      << " vs " << expected(r, c) << "\nactual:\n" << actual.format(compact) << "\nexpected:\n" << expected.format(compact);
  return ::testing::AssertionFailure() << out.str();
}

}  // namespace vascsim::test

// Point-segment distance and the contact barrier: analytic derivatives against central finite
// differences, symmetry, and the barrier's defining properties (IPC, Li et al. 2020).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "sim/contact/barrier.h"
#include "sim/contact/point_segment_distance.h"
#include "tests/compare_matrices.h"

namespace vascsim {
namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;

PointSegmentDistance eval(const Vec6& y) {
  return point_segment_distance(y.segment<2>(0), y.segment<2>(2), y.segment<2>(4));
}

void check_against_finite_differences(const Vec6& y) {
  const PointSegmentDistance at = eval(y);
  const double h = 1e-6;
  Vec6 fd_gradient;
  Eigen::Matrix<double, 6, 6> fd_hessian;
  for (int i = 0; i < 6; ++i) {
    Vec6 up = y, down = y;
    up[i] += h;
    down[i] -= h;
    const auto plus = eval(up), minus = eval(down);
    fd_gradient[i] = (plus.distance - minus.distance) / (2 * h);
    fd_hessian.col(i) = (plus.gradient - minus.gradient) / (2 * h);
  }
  EXPECT_TRUE(test::matrices_near(at.gradient, fd_gradient, 1e-7 * (1 + at.gradient.norm()))) << "at " << y.transpose();
  EXPECT_TRUE(test::matrices_near(at.hessian, fd_hessian, 1e-5 * (1 + at.hessian.norm()))) << "at " << y.transpose();
  EXPECT_TRUE(test::matrices_near(at.hessian, at.hessian.transpose(), 1e-12 * (1 + at.hessian.norm())));
}

TEST(PointSegmentDistance, KnownValuesInEachCase) {
  const Eigen::Vector2d a(0, 0), b(2, 0);
  EXPECT_DOUBLE_EQ(point_segment_distance({1, 0.5}, a, b).distance, 0.5);   // interior
  EXPECT_DOUBLE_EQ(point_segment_distance({1, 0.5}, a, b).parameter, 0.5);
  EXPECT_DOUBLE_EQ(point_segment_distance({-3, 4}, a, b).distance, 5.0);    // before a
  EXPECT_DOUBLE_EQ(point_segment_distance({5, -4}, a, b).distance, 5.0);    // beyond b
  EXPECT_DOUBLE_EQ(point_segment_distance({1, 1}, a, a).distance, std::sqrt(2.0));  // degenerate segment
}

TEST(PointSegmentDistance, DerivativesMatchFiniteDifferencesInAllCases) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int cases[3] = {0, 0, 0};
  for (int trial = 0; trial < 300; ++trial) {
    Vec6 y;
    for (int i = 0; i < 6; ++i) y[i] = u(rng);
    const auto d = eval(y);
    if (d.distance < 0.05) continue;  // finite differences need room to the segment
    // Stay away from the case boundaries, where the Hessian legitimately jumps.
    const Eigen::Vector2d e = y.segment<2>(4) - y.segment<2>(2);
    const double s = (y.segment<2>(0) - y.segment<2>(2)).dot(e) / e.squaredNorm();
    if (std::abs(s) < 0.02 || std::abs(s - 1) < 0.02) continue;
    ++cases[s <= 0 ? 0 : (s >= 1 ? 2 : 1)];
    check_against_finite_differences(y);
  }
  EXPECT_GT(cases[0], 20);
  EXPECT_GT(cases[1], 20);
  EXPECT_GT(cases[2], 20);
}

TEST(PointSegmentDistance, ValueAloneIsBitForBitTheDistance) {
  // Contact drops a pair on point_segment_distance_value before computing derivatives, so a pair
  // is kept or dropped exactly as the full evaluation would: the two must agree to the last bit,
  // in every case (near the case boundaries too, and for a degenerate segment).
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 3000; ++trial) {
    Vec6 y;
    for (int i = 0; i < 6; ++i) y[i] = u(rng);
    if (trial % 3 == 1) y.segment<2>(4) = y.segment<2>(2);  // a = b
    if (trial % 3 == 2) y[0] = y[2] + 1e-12 * u(rng);       // near the end a
    const Eigen::Vector2d p = y.segment<2>(0), a = y.segment<2>(2), b = y.segment<2>(4);
    const double full = point_segment_distance(p, a, b, false).distance;
    ASSERT_EQ(point_segment_distance_value(p, a, b), full) << "at " << y.transpose();
    ASSERT_EQ(point_segment_distance(p, a, b, true).distance, full);
  }
}

TEST(PointSegmentDistance, GradientIsContinuousAcrossCases) {
  // Crossing s = 0 (from the interior to the end a) must not jump the gradient (C1 distance).
  const Eigen::Vector2d a(0, 0), b(1, 0);
  const auto inside = point_segment_distance({1e-9, 0.3}, a, b);
  const auto outside = point_segment_distance({-1e-9, 0.3}, a, b);
  EXPECT_LT((inside.gradient - outside.gradient).norm(), 1e-7);
}

// Against the smallest of 2001 x 2001 sampled point pairs (an upper bound within the sampling's
// resolution), on random segments, crossing ones included.
TEST(SegmentSegmentDistance, MatchesSampledMinimumAndIsZeroWhenTheSegmentsCross) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int crossing = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Eigen::Vector2d p0(u(rng), u(rng)), p1(u(rng), u(rng)), a(u(rng), u(rng)), b(u(rng), u(rng));
    const double d = segment_segment_distance(p0, p1, a, b);
    double sampled = 1e9;
    for (int i = 0; i <= 2000; ++i) {
      const Eigen::Vector2d p = p0 + (i / 2000.0) * (p1 - p0);
      sampled = std::min(sampled, point_segment_distance_value(p, a, b));
    }
    EXPECT_LE(d, sampled + 1e-12) << "trial " << trial;
    EXPECT_GE(d, sampled - 2e-3) << "trial " << trial;  // the samples are 1e-3 apart at most
    EXPECT_GE(d, 0.0);
    if (sampled < 1e-3) crossing += d == 0.0;
  }
  EXPECT_GT(crossing, 5) << "too few crossing pairs to test that case";
  // Parallel segments side by side, and a move ending exactly on the segment.
  EXPECT_DOUBLE_EQ(segment_segment_distance({0, 1}, {2, 1}, {0.5, 0}, {1.5, 0}), 1.0);
  EXPECT_DOUBLE_EQ(segment_segment_distance({1, 1}, {1, 0}, {0, 0}, {2, 0}), 0.0);
}

// The hull of a unit square given in any order, and of a degenerate (collinear) set.
TEST(PointHullDistance, ZeroInsideAndTheNearestEdgeOutside) {
  const Eigen::Vector2d a(0, 0), b(1, 0), c(1, 1), d(0, 1);
  EXPECT_EQ(point_hull_distance({0.5, 0.5}, a, c, b, d), 0.0);
  EXPECT_EQ(point_hull_distance({0.0, 0.3}, b, d, a, c), 0.0);  // on the boundary
  EXPECT_DOUBLE_EQ(point_hull_distance({0.5, 1.5}, a, b, c, d), 0.5);
  EXPECT_DOUBLE_EQ(point_hull_distance({2.0, 2.0}, d, c, a, b), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(point_hull_distance({-3.0, 0.5}, a, c, d, b), 3.0);
  EXPECT_DOUBLE_EQ(point_hull_distance({0.5, 0.25}, a, b, {2, 0}, {3, 0}), 0.25);
}

TEST(ContactBarrier, ZeroBeyondActivationAndDerivativesMatch) {
  const double g_hat = 1e-3, kappa = 2.0;
  EXPECT_EQ(contact_barrier(g_hat, g_hat, kappa).energy, 0.0);
  EXPECT_EQ(contact_barrier(2 * g_hat, g_hat, kappa).first, 0.0);
  // C2 at the activation distance: value, slope and curvature all tend to 0.
  const auto near_hat = contact_barrier(g_hat * (1 - 1e-6), g_hat, kappa);
  EXPECT_LT(std::abs(near_hat.first), 1e-5 * kappa);
  EXPECT_LT(std::abs(near_hat.second), 1e-2 * kappa / g_hat);
  for (double s : {0.01, 0.1, 0.3, 0.5, 0.9}) {
    const double g = s * g_hat, h = 1e-9 * g_hat;
    const auto v = contact_barrier(g, g_hat, kappa);
    const auto up = contact_barrier(g + h, g_hat, kappa), down = contact_barrier(g - h, g_hat, kappa);
    EXPECT_NEAR(v.first, (up.energy - down.energy) / (2 * h), 1e-6 * std::abs(v.first) + 1e-9) << s;
    EXPECT_NEAR(v.second, (up.first - down.first) / (2 * h), 1e-5 * std::abs(v.second) + 1e-6) << s;
    EXPECT_LT(v.first, 0.0);   // pushes apart
    EXPECT_GT(v.second, 0.0);  // convex
  }
  // Force scale: about 1.19 kappa at half the activation distance (header comment).
  EXPECT_NEAR(-contact_barrier(0.5 * g_hat, g_hat, kappa).first / kappa, 1.1931, 1e-4);
}

}  // namespace
}  // namespace vascsim

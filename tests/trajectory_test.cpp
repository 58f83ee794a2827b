// Constant-speed traversal of a polyline with rounded corners (issue 2, item 5), against closed
// forms: the length of a rounded corner is the two legs shortened by the tangent length R tan(theta/2)
// plus the arc R theta; uniform circular motion has |a| = v^2 / R; straight lines have a = 0; and the
// position is the time integral of the velocity.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sim/env/trajectory.h"

namespace vascsim {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Which piece arc length s falls in, from the trajectory's own piece table.
const Trajectory::Piece& piece_at(const Trajectory& traj, double s) {
  const Trajectory::Piece* found = &traj.pieces().front();
  for (const auto& q : traj.pieces())
    if (q.s0 <= s) found = &q;
  return *found;
}

TEST(Trajectory, RoundedLCornerHasTheAnalyticLength) {
  // Legs of 0.6 m and 0.4 m, a 90-degree left turn, R = 0.05 m: (0.6 - R) + (0.4 - R) + pi R / 2.
  const double R = 0.05;
  const Trajectory traj({{0, 0}, {0.6, 0}, {0.6, 0.4}}, R, 0.05);
  EXPECT_NEAR(traj.length(), (0.6 - R) + (0.4 - R) + kPi * R / 2, 1e-14);
  EXPECT_NEAR(traj.duration(), traj.length() / 0.05, 1e-12);
  ASSERT_EQ(traj.pieces().size(), 3u);
  EXPECT_NEAR(traj.pieces()[1].radius, R, 1e-15);
  EXPECT_NEAR(traj.pieces()[1].turn, kPi / 2, 1e-15);
  // The arc's centre sits R inside the corner on both legs.
  EXPECT_LT((traj.pieces()[1].centre - Vec2(0.55, 0.05)).norm(), 1e-15);
  // A 135-degree right turn: tangent length R tan(67.5 deg), arc R * 3 pi / 4.
  const Trajectory sharp_turn({{0, 0}, {1, 0}, {1 - std::sqrt(0.5), -std::sqrt(0.5)}}, R, 1.0);
  EXPECT_NEAR(sharp_turn.length(), 2.0 - 2 * R * std::tan(3 * kPi / 8) + R * 3 * kPi / 4, 1e-13);
  EXPECT_LT(sharp_turn.pieces()[1].turn, 0.0);
}

TEST(Trajectory, SharpCornersWhenRadiusIsZero) {
  const Trajectory traj({{0, 0}, {0.6, 0}, {0.6, 0.4}}, 0.0, 0.1);
  EXPECT_NEAR(traj.length(), 1.0, 1e-15);
  EXPECT_EQ(traj.pieces().size(), 2u);
  EXPECT_LT((traj.position(6.0) - Vec2(0.6, 0.0)).norm(), 1e-14);
}

TEST(Trajectory, RadiusShrinksToWhatFits) {
  // A U-turn of two 90-degree corners 0.1 m apart: each may use half of the shared leg, so R = 0.05 m
  // although 1 m was asked; the first and last legs are long.
  const Trajectory u({{0, 0}, {1, 0}, {1, 0.1}, {0, 0.1}}, 1.0, 1.0);
  int arcs = 0;
  for (const auto& q : u.pieces())
    if (q.radius > 0) {
      ++arcs;
      EXPECT_NEAR(q.radius, 0.05, 1e-15);
    }
  EXPECT_EQ(arcs, 2);
  EXPECT_NEAR(u.length(), 0.95 + kPi * 0.05 + 0.95, 1e-14);
  // A single corner with a 0.3 m first leg and a 2 m second leg: R = 0.3 m (the whole first leg).
  const Trajectory one({{0, 0}, {0.3, 0}, {0.3, 2}}, 1.0, 1.0);
  EXPECT_NEAR(one.pieces()[0].radius, 0.3, 1e-15);
  EXPECT_NEAR(one.length(), kPi * 0.3 / 2 + 1.7, 1e-14);
}

// A zig-zag with 90-degree and 45-degree turns of both senses.
const Polyline kZigZag = {{0, 0}, {0.5, 0}, {0.5, 0.3}, {0.8, 0.6}, {1.4, 0.6}, {1.4, 0.2}, {1.0, 0.2}};

TEST(Trajectory, SpeedIsConstantAndAccelerationIsCentripetal) {
  const double v = 0.07, R = 0.12;
  const Trajectory traj(kZigZag, R, v);
  int on_arcs = 0, on_lines = 0;
  for (int k = 0; k <= 20000; ++k) {
    const double t = traj.duration() * k / 20000.0;
    const double s = v * t;
    ASSERT_NEAR(traj.velocity(t).norm(), v, 1e-14 * v) << "t " << t;
    const auto& q = piece_at(traj, s);
    const Vec2 a = traj.acceleration(t);
    if (q.radius > 0) {
      ++on_arcs;
      ASSERT_NEAR(a.norm(), v * v / q.radius, 1e-12 * v * v / q.radius) << "t " << t;
      // Towards the centre, perpendicular to the velocity.
      ASSERT_NEAR(a.normalized().dot((q.centre - traj.position(t)).normalized()), 1.0, 1e-12);
      ASSERT_NEAR(a.dot(traj.velocity(t)), 0.0, 1e-12 * v * v * v / q.radius);
    } else {
      ++on_lines;
      ASSERT_EQ(a.norm(), 0.0) << "t " << t;
    }
  }
  EXPECT_GT(on_arcs, 1000);
  EXPECT_GT(on_lines, 1000);
}

TEST(Trajectory, PositionIsTheIntegralOfVelocityAndIsC1) {
  const double v = 0.05;
  const Trajectory traj(kZigZag, 0.1, v);
  // Simpson's rule on the velocity, which is smooth within each piece and continuous across them
  // (C1 position), so the error is O(h^2) at the kinks of the acceleration at most.
  const int n = 100000;  // even
  const double h = traj.duration() / n;
  Vec2 integral = Vec2::Zero();
  for (int k = 0; k < n; k += 2) {
    const double t = k * h;
    integral += h / 3 * (traj.velocity(t) + 4 * traj.velocity(t + h) + traj.velocity(t + 2 * h));
    if (k % 5000 == 0) {
      ASSERT_LT((traj.position(0) + integral - traj.position(t + 2 * h)).norm(), 1e-7) << "t " << t + 2 * h;
    }
  }
  EXPECT_LT((traj.position(0) + integral - kZigZag.back()).norm(), 1e-7);
  // Continuity at every piece joint: position and velocity from both sides agree.
  for (std::size_t i = 1; i < traj.pieces().size(); ++i) {
    const double t = traj.pieces()[i].s0 / v, dt = 1e-9;
    EXPECT_LT((traj.position(t - dt) - traj.position(t + dt)).norm(), 3 * v * dt) << "joint " << i;
    EXPECT_LT((traj.velocity(t - dt) - traj.velocity(t + dt)).norm(), 1e-6 * v) << "joint " << i;
  }
}

TEST(Trajectory, EndsAreClampedAndPassThroughTheCorners) {
  const Trajectory traj(kZigZag, 0.1, 0.05);
  EXPECT_EQ(traj.position(-3.0), kZigZag.front());
  EXPECT_LT((traj.position(traj.duration() + 5) - kZigZag.back()).norm(), 1e-15);
  EXPECT_LT((traj.velocity(1e9) - Vec2(-0.05, 0)).norm(), 1e-15);
  // The rounded path leaves each corner inside: its distance to the corner is R (1/cos(theta/2) - 1)
  // for a turn of theta; at the first, 90-degree corner that is 0.1 (sqrt 2 - 1).
  double least = INFINITY;
  for (const Vec2& p : traj.sample(1e-7)) least = std::min(least, (p - kZigZag[1]).norm());
  EXPECT_NEAR(least, 0.1 * (std::sqrt(2.0) - 1), 1e-6);
}

TEST(Trajectory, SampleKeepsChordErrorBelowTheBound) {
  const Trajectory traj(kZigZag, 0.1, 0.05);
  for (const double e : {1e-3, 1e-5}) {
    const Polyline pts = traj.sample(e);
    for (std::size_t i = 1; i < pts.size(); ++i) {
      // A chord between two points of one arc is furthest from it at its midpoint: the sagitta.
      const Vec2 mid = 0.5 * (pts[i - 1] + pts[i]);
      const auto on_circle = [](const Vec2& p, const Trajectory::Piece& q) {
        return std::abs((p - q.centre).norm() - q.radius) < 1e-9 * q.radius;
      };
      for (const auto& q : traj.pieces())
        if (q.radius > 0 && on_circle(pts[i - 1], q) && on_circle(pts[i], q)) {
          ASSERT_LE(q.radius - (mid - q.centre).norm(), e * (1 + 1e-9));
        }
    }
    EXPECT_EQ(pts.front(), kZigZag.front());
    EXPECT_LT((pts.back() - kZigZag.back()).norm(), 1e-15);
  }
  EXPECT_GT(traj.sample(1e-5).size(), traj.sample(1e-3).size());
}

// With ramps the speed follows a trapezoid (closed forms): v t / T for t < T, the cruising speed,
// then v (duration - t) / T, so the reference starts and ends at rest; the path is unchanged and
// takes T longer; the acceleration is v / T along the path plus the centripetal part, bounded.
TEST(Trajectory, RampsStartAndStopAtRestWithBoundedAcceleration) {
  const double v = 0.05, R = 0.1, T = 2.0;
  const Trajectory cruise(kZigZag, R, v), traj(kZigZag, R, v, T);
  EXPECT_NEAR(traj.length(), cruise.length(), 1e-15);
  EXPECT_NEAR(traj.duration(), traj.length() / v + T, 1e-12);
  EXPECT_EQ(traj.velocity(0.0).norm(), 0.0);
  EXPECT_LT(traj.velocity(traj.duration()).norm(), 1e-15);
  EXPECT_LT(traj.velocity(traj.duration() + 10.0).norm(), 1e-15) << "stays at rest at the goal";
  // Half-way through the first ramp: s = v (T/2)^2 / (2 T) = v T / 8 along the first leg (+x).
  EXPECT_LT((traj.position(T / 2) - Vec2(v * T / 8, 0)).norm(), 1e-15);
  EXPECT_LT((traj.acceleration(T / 2) - Vec2(v / T, 0)).norm(), 1e-15);
  const int n = 200000;
  const double h = traj.duration() / n;
  Vec2 integral = Vec2::Zero();
  for (int k = 0; k < n; ++k) {
    const double t = k * h;
    const double expected_speed = std::min({v, v * t / T, v * (traj.duration() - t) / T});
    ASSERT_NEAR(traj.velocity(t).norm(), expected_speed, 1e-12) << "t " << t;
    ASSERT_LE(traj.acceleration(t).norm(), (v / T + v * v / R) * (1 + 1e-12)) << "t " << t;
    integral += 0.5 * h * (traj.velocity(t) + traj.velocity(t + h));
  }
  EXPECT_LT((traj.position(0) + integral - kZigZag.back()).norm(), 1e-7) << "position is the integral of velocity";
  // Acceleration is the derivative of velocity, ramps and arcs alike (points away from joints).
  for (const double t : {0.7, 1.3, 5.0, traj.duration() - 1.1}) {
    const double dt = 1e-6;
    const Vec2 derivative = (traj.velocity(t + dt) - traj.velocity(t - dt)) / (2 * dt);
    EXPECT_LT((derivative - traj.acceleration(t)).norm(), 1e-6) << "t " << t;
  }
}

TEST(Trajectory, ShortPathPeaksBelowTheCruisingSpeed) {
  // 1 cm with v = 0.05 m/s and T = 1 s: a = 0.05 m/s^2 never reaches v; the profile is a triangle
  // with peak sqrt(a L) at half of duration 2 sqrt(L / a).
  const double a = 0.05, L = 0.01;
  const Trajectory traj({{0, 0}, {L, 0}}, 0.05, 0.05, 1.0);
  EXPECT_NEAR(traj.duration(), 2 * std::sqrt(L / a), 1e-14);
  EXPECT_NEAR(traj.velocity(traj.duration() / 2).norm(), std::sqrt(a * L), 1e-14);
  EXPECT_LT((traj.position(traj.duration()) - Vec2(L, 0)).norm(), 1e-16);
  EXPECT_THROW(Trajectory({{0, 0}, {1, 0}}, 0.05, 1.0, -1.0), std::invalid_argument);
}

TEST(Trajectory, DegenerateInputs) {
  const Trajectory point({{0.3, 0.4}}, 0.05, 0.1);
  EXPECT_EQ(point.length(), 0.0);
  EXPECT_EQ(point.duration(), 0.0);
  EXPECT_EQ(point.position(1.0), Vec2(0.3, 0.4));
  EXPECT_EQ(point.velocity(1.0), Vec2::Zero());
  EXPECT_EQ(point.acceleration(0.0), Vec2::Zero());
  EXPECT_EQ(point.sample(1e-3).size(), 1u);
  // Duplicates and straight-through points are dropped: one line of 2 m.
  const Trajectory line({{0, 0}, {0, 0}, {1, 0}, {2, 0}, {2, 0}}, 0.05, 1.0);
  EXPECT_EQ(line.pieces().size(), 1u);
  EXPECT_NEAR(line.length(), 2.0, 1e-15);
  // A reversal stays sharp: the path goes out and back, velocity flips, nothing is NaN.
  const Trajectory back({{0, 0}, {1, 0}, {0.5, 0}}, 0.05, 1.0);
  EXPECT_NEAR(back.length(), 1.5, 1e-15);
  EXPECT_TRUE(back.position(1.2).allFinite());
  EXPECT_LT((back.velocity(1.2) - Vec2(-1, 0)).norm(), 1e-15);
  EXPECT_THROW(Trajectory({}, 0.05, 1.0), std::invalid_argument);
  EXPECT_THROW(Trajectory({{0, 0}, {1, 0}}, -1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(Trajectory({{0, 0}, {1, 0}}, 0.05, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace vascsim

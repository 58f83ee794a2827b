// Wall distance queries (issue 2, item 6): closed forms for one capsule (sides, round ends, inside,
// exactly on a line wall), corners with two walls, and the bucket grid against the brute-force loop
// on 10^5 random points per environment, inside walls too, for thick, line and arbitrary walls.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "sim/env/environment.h"
#include "sim/env/wall_distance.h"
#include "tests/env_test_support.h"

namespace vascsim {
namespace {

testing::AssertionResult same_hit(const WallHit& a, const WallHit& b) {
  if (a.wall == b.wall && a.distance == b.distance && a.closest == b.closest && a.normal == b.normal)
    return testing::AssertionSuccess();
  return testing::AssertionFailure() << "wall " << a.wall << " vs " << b.wall << ", distance " << a.distance << " vs "
                                     << b.distance << ", closest " << a.closest.transpose() << " vs "
                                     << b.closest.transpose() << ", normal " << a.normal.transpose() << " vs "
                                     << b.normal.transpose();
}

void expect_hit(const WallHit& h, double distance, const Vec2& closest, const Vec2& normal) {
  EXPECT_NEAR(h.distance, distance, 1e-15);
  EXPECT_LT((h.closest - closest).norm(), 1e-15) << h.closest.transpose();
  EXPECT_LT((h.normal - normal).norm(), 1e-15) << h.normal.transpose();
}

TEST(WallDistance, OneCapsuleClosedForms) {
  const WallSegment w{Vec2(0, 0), Vec2(1, 0), 0.2};  // radius 0.1 m
  expect_hit(wall_hit(w, 0, Vec2(0.5, 1.0)), 0.9, Vec2(0.5, 0.1), Vec2(0, 1));     // beside
  expect_hit(wall_hit(w, 0, Vec2(0.5, -0.3)), 0.2, Vec2(0.5, -0.1), Vec2(0, -1));  // other side
  expect_hit(wall_hit(w, 0, Vec2(2.0, 0.0)), 0.9, Vec2(1.1, 0.0), Vec2(1, 0));     // past the end, on the axis
  expect_hit(wall_hit(w, 0, Vec2(1.3, 0.4)), 0.4, Vec2(1.06, 0.08), Vec2(0.6, 0.8));  // round end cap
  expect_hit(wall_hit(w, 0, Vec2(0.5, 0.04)), -0.06, Vec2(0.5, 0.1), Vec2(0, 1));  // inside
  // On the centre line the direction is undefined: the left normal of a -> b, here +y.
  expect_hit(wall_hit(w, 0, Vec2(0.25, 0.0)), -0.1, Vec2(0.25, 0.1), Vec2(0, 1));
  expect_hit(wall_hit(w, 0, Vec2(1.0, 0.0)), -0.1, Vec2(1.0, 0.1), Vec2(0, 1));    // the end point itself
}

TEST(WallDistance, ZeroThicknessAndDegenerateWallsGiveNoNaN) {
  const WallSegment line{Vec2(0.2, 0.2), Vec2(0.2, 0.8), 0.0};
  const WallHit on = wall_hit(line, 3, Vec2(0.2, 0.5));  // exactly on a line wall
  EXPECT_EQ(on.distance, 0.0);
  EXPECT_EQ(on.wall, 3);
  expect_hit(on, 0.0, Vec2(0.2, 0.5), Vec2(-1, 0));
  expect_hit(wall_hit(line, 3, Vec2(0.2, 0.8)), 0.0, Vec2(0.2, 0.8), Vec2(-1, 0));  // on its end
  // An offset whose square underflows: treated as on the line, not divided by zero.
  const WallSegment y_axis{Vec2(0, 0), Vec2(0, 1), 0.0};
  expect_hit(wall_hit(y_axis, 0, Vec2(1e-170, 0.5)), 0.0, Vec2(0, 0.5), Vec2(-1, 0));
  const WallHit tiny = wall_hit(y_axis, 0, Vec2(1e-90, 0.5));  // small but representable: the true normal
  EXPECT_EQ(tiny.normal, Vec2(1, 0));
  const WallSegment dot{Vec2(0.5, 0.5), Vec2(0.5, 0.5), 0.1};  // zero length: a disc of radius 0.05 m
  expect_hit(wall_hit(dot, 0, Vec2(0.5, 0.5)), -0.05, Vec2(0.55, 0.5), Vec2(1, 0));
  expect_hit(wall_hit(dot, 0, Vec2(0.5, 0.2)), 0.25, Vec2(0.5, 0.45), Vec2(0, -1));
  const WallSegment point{Vec2(0.5, 0.5), Vec2(0.5, 0.5), 0.0};
  const WallHit p = wall_hit(point, 0, Vec2(0.5, 0.5));
  EXPECT_TRUE(p.normal.allFinite() && p.closest.allFinite() && std::isfinite(p.distance));
  // The field over line walls, queried on them, on their ends and at their crossing.
  const WallDistanceField field(test::paper_fig10_spec().walls, 0.05);
  std::vector<WallHit> hits;
  for (const Vec2& q : {Vec2(0.2, 0.5), Vec2(0.2, 0.8), Vec2(0.0, 0.0), Vec2(0.6, 0.4)}) {
    WallHit h;
    ASSERT_TRUE(field.nearest(q, 0.0, h));
    EXPECT_EQ(h.distance, 0.0);
    EXPECT_TRUE(h.normal.allFinite());
    EXPECT_NEAR(h.normal.norm(), 1.0, 1e-15);
  }
}

TEST(WallDistance, CornerReportsBothWalls) {
  // An L of two 0.1 m thick walls meeting at the origin; a point in the inner corner, 0.06 m from each
  // wall's centre line (0.01 m from each surface), touches both.
  const std::vector<WallSegment> walls = {{Vec2(0, 0), Vec2(1, 0), 0.1}, {Vec2(0, 0), Vec2(0, 1), 0.1}};
  const WallDistanceField field(walls, 0.02);
  std::vector<WallHit> hits;
  field.near(Vec2(0.06, 0.06), 0.02, hits);
  ASSERT_EQ(hits.size(), 2u);
  expect_hit(hits[0], 0.01, Vec2(0.06, 0.05), Vec2(0, 1));
  expect_hit(hits[1], 0.01, Vec2(0.05, 0.06), Vec2(1, 0));
  WallHit nearest;
  ASSERT_TRUE(field.nearest(Vec2(0.06, 0.06), 0.02, nearest));
  EXPECT_EQ(nearest.wall, 0);  // a tie goes to the lower index
  // Outside the convex corner both walls are equally near through their round ends.
  field.near(Vec2(-0.045, -0.045), 0.02, hits);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].distance, std::sqrt(2.0) * 0.045 - 0.05, 1e-15);
  EXPECT_LT((hits[1].normal - Vec2(-1, -1) / std::sqrt(2.0)).norm(), 1e-15);
  EXPECT_FALSE(field.nearest(Vec2(0.5, 0.5), 0.02, nearest));
  EXPECT_THROW(field.nearest(Vec2(0.5, 0.5), 0.03, nearest), std::invalid_argument);
}

// Random points over the walls' box grown by 0.3 m: nearest() must equal the brute force bit for bit
// whenever the brute-force distance is within the radius, and report nothing otherwise; near() must
// list exactly the walls within the radius. The three environments below share the 10^5 points
// issue 2 asks for (a sanitizer build runs the brute force ~40x slower, so not 10^5 each).
void compare_with_brute_force(const std::vector<WallSegment>& walls, double radius, std::uint64_t seed,
                              int points, bool walls_have_inside) {
  const WallDistanceField field(walls, radius);
  Vec2 lo = walls[0].a, hi = walls[0].a;
  for (const auto& w : walls) {
    lo = lo.cwiseMin(w.a.cwiseMin(w.b));
    hi = hi.cwiseMax(w.a.cwiseMax(w.b));
  }
  lo.array() -= 0.3;
  hi.array() += 0.3;
  std::mt19937_64 rng(seed);
  const auto uniform = [&](double a, double b) { return a + (b - a) * static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  int found = 0, inside = 0;
  std::vector<WallHit> hits, expected_hits;
  for (int k = 0; k < points; ++k) {
    const Vec2 p(uniform(lo.x(), hi.x()), uniform(lo.y(), hi.y()));
    // One pass over every wall gives both references: the nearest and the list within the radius.
    WallHit brute;
    expected_hits.clear();
    for (int i = 0; i < static_cast<int>(walls.size()); ++i) {
      const WallHit h = wall_hit(walls[static_cast<std::size_t>(i)], i, p);
      if (i == 0 || h.distance < brute.distance) brute = h;
      if (h.distance <= radius) expected_hits.push_back(h);
    }
    if (k % 16 == 0) {  // the library's own brute force is that same loop
      WallHit reference;
      ASSERT_TRUE(WallDistanceField::nearest_brute_force(walls, p, reference));
      ASSERT_TRUE(same_hit(reference, brute));
    }
    WallHit fast;
    const bool got = field.nearest(p, radius, fast);
    ASSERT_EQ(got, brute.distance <= radius) << "point " << p.transpose() << " brute distance " << brute.distance;
    if (got) {
      ASSERT_TRUE(same_hit(fast, brute)) << "point " << p.transpose();
      ++found;
    }
    if (brute.distance < 0) ++inside;
    // The geometry is self-consistent: p = closest + distance * normal, normal a unit vector.
    ASSERT_LT((brute.closest + brute.distance * brute.normal - p).norm(), 1e-12);
    ASSERT_NEAR(brute.normal.norm(), 1.0, 1e-12);
    field.near(p, radius, hits);
    ASSERT_EQ(hits.size(), expected_hits.size()) << "point " << p.transpose();
    for (std::size_t i = 0; i < hits.size(); ++i) ASSERT_TRUE(same_hit(hits[i], expected_hits[i]));
  }
  // The sample must exercise both outcomes and the inside of walls.
  EXPECT_GT(found, points / 10);
  EXPECT_LT(found, points);
  if (walls_have_inside) {
    EXPECT_GT(inside, points / 100);
  }
}

TEST(WallDistance, GridEqualsBruteForceOnThickMazeWalls) {
  compare_with_brute_force(build_environment(test::maze_spec(12, 12, 11, 0.1)).walls, 0.08, 1, 40000, true);
}

TEST(WallDistance, GridEqualsBruteForceOnLineMazeWalls) {
  // Line walls have no inside; points on them are measure-zero, so add some exactly on walls.
  const auto walls = build_environment(test::maze_spec(12, 12, 12, 0.2)).walls;
  compare_with_brute_force(walls, 0.08, 2, 30000, false);
  const WallDistanceField field(walls, 0.08);
  for (const auto& w : walls)
    for (const double t : {0.0, 0.25, 0.5, 1.0}) {
      const Vec2 p = w.a + t * (w.b - w.a);
      WallHit brute, fast;
      ASSERT_TRUE(WallDistanceField::nearest_brute_force(walls, p, brute));
      ASSERT_TRUE(field.nearest(p, 0.0, fast));
      ASSERT_TRUE(same_hit(fast, brute));
      EXPECT_EQ(fast.distance, 0.0);
    }
}

TEST(WallDistance, GridEqualsBruteForceOnRandomWalls) {
  // Any direction, length from zero (discs) to 0.8 m, thickness 0 to 0.2 m, over a 2 m square.
  std::mt19937_64 rng(99);
  const auto uniform = [&](double a, double b) { return a + (b - a) * static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::vector<WallSegment> walls;
  for (int i = 0; i < 100; ++i) {
    WallSegment w;
    w.a = Vec2(uniform(0, 2), uniform(0, 2));
    const double len = i % 10 == 0 ? 0.0 : uniform(0, 0.8), angle = uniform(0, 6.283185307179586);
    w.b = w.a + len * Vec2(std::cos(angle), std::sin(angle));
    w.thickness = i % 3 == 0 ? 0.0 : uniform(0, 0.2);
    walls.push_back(w);
  }
  compare_with_brute_force(walls, 0.05, 3, 30000, true);
}

TEST(WallDistance, FarAndNonFinitePointsFindNothing) {
  const auto walls = build_environment(test::maze_spec(5, 5, 1, 0.1)).walls;
  const WallDistanceField field(walls, 0.1);
  WallHit h;
  EXPECT_FALSE(field.nearest(Vec2(1e30, -1e30), 0.1, h));
  EXPECT_FALSE(field.nearest(Vec2(NAN, 0.5), 0.1, h));
  std::vector<WallHit> hits{WallHit{}};
  field.near(Vec2(INFINITY, 0.5), 0.1, hits);
  EXPECT_TRUE(hits.empty());
  const WallDistanceField empty({}, 0.1);
  EXPECT_FALSE(empty.nearest(Vec2(0, 0), 0.1, h));
  EXPECT_FALSE(WallDistanceField::nearest_brute_force({}, Vec2(0, 0), h));
}

}  // namespace
}  // namespace vascsim

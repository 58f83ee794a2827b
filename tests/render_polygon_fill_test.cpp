// The lumen triangulation against independent checks: the triangles' areas add up to the even-odd
// area from the shoelace formula, and at random points "inside some triangle" (exactly one, never
// two: the triangles do not overlap) agrees with an even-odd ray-crossing test of the rings. Shapes:
// an annulus, a comb (concave, many horizontal edges), a rotated comb, a polygon with two holes,
// rings that cross themselves or each other, and a 5000-vertex wavy annulus.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "render/polygon_fill.h"

namespace vascsim::render {
namespace {

constexpr double kPi = 3.14159265358979323846;

Polyline circle(Vec2 centre, double radius, int n, double phase = 0.1, bool clockwise = false) {
  Polyline p;
  for (int i = 0; i < n; ++i) {
    const double a = phase + (clockwise ? -1 : 1) * 2 * kPi * i / n;
    p.push_back(centre + radius * Vec2(std::cos(a), std::sin(a)));
  }
  return p;
}

// A base bar 0..10 x 0..1 with 10 teeth [k, k + 0.5] x [1, 3], counter-clockwise.
Polyline comb() {
  Polyline p = {{0, 0}, {10, 0}, {10, 1}};
  for (int k = 9; k >= 0; --k) {
    p.push_back({k + 0.5, 1});
    p.push_back({k + 0.5, 3});
    p.push_back({k + 0.0, 3});
    if (k > 0) p.push_back({k + 0.0, 1});
  }
  return p;
}

double shoelace(const Polyline& ring) {
  double a = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 &p = ring[i], &q = ring[(i + 1) % ring.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

double triangle_area(const Triangle& t) {
  return 0.5 * std::abs((t.b - t.a).x() * (t.c - t.a).y() - (t.b - t.a).y() * (t.c - t.a).x());
}

double total_area(const std::vector<Triangle>& ts) {
  double a = 0;
  for (const auto& t : ts) a += triangle_area(t);
  return a;
}

// Even-odd by counting the ring edges a ray to +x crosses.
bool inside_even_odd(const std::vector<Polyline>& rings, Vec2 p) {
  bool in = false;
  for (const auto& ring : rings)
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 &a = ring[i], &b = ring[(i + 1) % ring.size()];
      if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()))
        in = !in;
    }
  return in;
}

bool in_triangle(const Triangle& t, Vec2 p) {
  auto side = [](Vec2 a, Vec2 b, Vec2 q) { return (b - a).x() * (q - a).y() - (b - a).y() * (q - a).x(); };
  const double s0 = side(t.a, t.b, p), s1 = side(t.b, t.c, p), s2 = side(t.c, t.a, p);
  return (s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0);
}

// At `samples` random points of the rings' bounding box, the number of triangles holding the
// point is 1 inside (even-odd) and 0 outside.
void expect_tiles_interior(const std::vector<Polyline>& rings, const std::vector<Triangle>& ts, int samples = 20000) {
  Vec2 lo = Vec2::Constant(1e300), hi = Vec2::Constant(-1e300);
  for (const auto& r : rings)
    for (const auto& p : r) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y());
  int wrong = 0, inside = 0;
  for (int i = 0; i < samples; ++i) {
    const Vec2 p(ux(rng), uy(rng));
    int holders = 0;
    for (const auto& t : ts) holders += in_triangle(t, p) ? 1 : 0;
    const bool in = inside_even_odd(rings, p);
    inside += in ? 1 : 0;
    if (holders != (in ? 1 : 0) && ++wrong <= 5)
      ADD_FAILURE() << "at (" << p.x() << ", " << p.y() << "): " << holders << " triangles, even-odd says "
                    << (in ? "inside" : "outside");
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(inside, samples / 20) << "the sample hardly tested the interior";
}

std::size_t vertex_count(const std::vector<Polyline>& rings) {
  std::size_t n = 0;
  for (const auto& r : rings) n += r.size();
  return n;
}

TEST(PolygonFill, AnnulusAreaAndInterior) {
  const std::vector<Polyline> rings = {circle({0.3, -0.2}, 1.0, 96), circle({0.35, -0.2}, 0.5, 64, 0.37, true)};
  const auto ts = triangulate_even_odd(rings);
  const double area = std::abs(shoelace(rings[0])) - std::abs(shoelace(rings[1]));
  EXPECT_NEAR(total_area(ts), area, 1e-12 * area);
  expect_tiles_interior(rings, ts);
  EXPECT_LE(ts.size(), 4 * vertex_count(rings));
  std::printf("annulus, %zu + %zu vertices: %zu triangles\n", rings[0].size(), rings[1].size(), ts.size());
}

TEST(PolygonFill, CombAxisAlignedAndRotated) {
  const Polyline c = comb();
  ASSERT_NEAR(std::abs(shoelace(c)), 10 * 1 + 10 * 0.5 * 2, 1e-12);  // base + teeth
  for (const double angle : {0.0, 0.3}) {
    Polyline r;
    for (const Vec2& p : c) r.push_back({std::cos(angle) * p.x() - std::sin(angle) * p.y(),
                                         std::sin(angle) * p.x() + std::cos(angle) * p.y()});
    const auto ts = triangulate_even_odd({r});
    EXPECT_NEAR(total_area(ts), 20.0, 1e-11) << "angle " << angle;
    expect_tiles_interior({r}, ts);
    std::printf("comb at %.1f rad, %zu vertices: %zu triangles\n", angle, r.size(), ts.size());
  }
}

TEST(PolygonFill, TwoHoles) {
  const Polyline outer = {{0, 0}, {10, 0}, {10, 6}, {0, 6}};
  const Polyline round_hole = circle({3, 3}, 1.5, 40);
  const Polyline square_hole = {{6, 2}, {6, 4.5}, {8.5, 4.5}, {8.5, 2}};  // clockwise: orientation is irrelevant
  const std::vector<Polyline> rings = {outer, round_hole, square_hole};
  const auto ts = triangulate_even_odd(rings);
  const double area = std::abs(shoelace(outer)) - std::abs(shoelace(round_hole)) - std::abs(shoelace(square_hole));
  EXPECT_NEAR(total_area(ts), area, 1e-11);
  expect_tiles_interior(rings, ts);
  std::printf("rectangle with two holes, %zu vertices: %zu triangles\n", vertex_count(rings), ts.size());
}

TEST(PolygonFill, CrossingRingsFollowEvenOdd) {
  // Two overlapping squares: even-odd leaves their overlap out.
  const std::vector<Polyline> squares = {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{2, 1}, {6, 1.5}, {5.5, 5.5}, {1.5, 5}}};
  const auto ts = triangulate_even_odd(squares);
  expect_tiles_interior(squares, ts);
  // A pentagram: its centre pentagon is covered twice, so even-odd leaves it out.
  Polyline star;
  for (int i = 0; i < 5; ++i) star.push_back(Vec2(std::cos(0.2 + 4 * kPi * i / 5), std::sin(0.2 + 4 * kPi * i / 5)));
  const auto st = triangulate_even_odd({star});
  expect_tiles_interior({star}, st);
  EXPECT_TRUE(std::none_of(st.begin(), st.end(), [](const Triangle& t) { return in_triangle(t, Vec2(0.01, 0.02)); }));
}

TEST(PolygonFill, DegenerateInput) {
  EXPECT_TRUE(triangulate_even_odd({}).empty());
  EXPECT_TRUE(triangulate_even_odd({{{0, 0}, {1, 1}}}).empty());                  // too few points
  EXPECT_TRUE(triangulate_even_odd({{{0, 0}, {1, 1}, {2, 2}}}).empty());          // no area
  EXPECT_TRUE(triangulate_even_odd({{{0, 0}, {1, NAN}, {2, 0}, {1, 1}}}).empty());  // not finite
  // The first point repeated at the end, and collinear points, change nothing.
  const Polyline square = {{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 0}};
  const auto ts = triangulate_even_odd({square});
  EXPECT_NEAR(total_area(ts), 4.0, 1e-14);
  EXPECT_EQ(ts.size(), 2u);
  // A ring given twice cancels itself.
  EXPECT_TRUE(triangulate_even_odd({square, square}).empty());
}

TEST(PolygonFill, FiveThousandVertexNetworkSizedRing) {
  // A wavy annulus of 5000 vertices, the size of a large vessel network's outline.
  Polyline outer, inner;
  for (int i = 0; i < 3000; ++i) {
    const double a = 2 * kPi * i / 3000;
    outer.push_back((1.0 + 0.1 * std::sin(40 * a)) * Vec2(std::cos(a), std::sin(a)));
  }
  for (int i = 0; i < 2000; ++i) {
    const double a = 2 * kPi * i / 2000 + 0.001;
    inner.push_back((0.5 + 0.05 * std::sin(25 * a)) * Vec2(std::cos(a), std::sin(a)));
  }
  const std::vector<Polyline> rings = {outer, inner};
  const auto ts = triangulate_even_odd(rings);
  const double area = std::abs(shoelace(outer)) - std::abs(shoelace(inner));
  EXPECT_NEAR(total_area(ts), area, 1e-10 * area);
  expect_tiles_interior(rings, ts, 2000);
  EXPECT_LE(ts.size(), 4 * vertex_count(rings));
  std::printf("wavy annulus, %zu vertices: %zu triangles\n", vertex_count(rings), ts.size());
}

TEST(PolygonFill, AxisAlignedRectangleIsRecognised) {
  Box2 b;
  // As navigation logs a maze's bounds: counter-clockwise from the lower left corner.
  ASSERT_TRUE(axis_aligned_rectangle({{0, 0}, {2, 0}, {2, 1}, {0, 1}}, b));
  EXPECT_EQ(b.min, Vec2(0, 0));
  EXPECT_EQ(b.max, Vec2(2, 1));
  EXPECT_TRUE(axis_aligned_rectangle({{2, 1}, {2, 0}, {0, 0}, {0, 1}, {2, 1}}, b));  // clockwise, closed
  EXPECT_EQ(b.min, Vec2(0, 0));
  EXPECT_EQ(b.max, Vec2(2, 1));
  EXPECT_FALSE(axis_aligned_rectangle({{0, 0}, {2, 0}, {2, 1}}, b));
  EXPECT_FALSE(axis_aligned_rectangle({{0, 0}, {1, 1}, {0, 2}, {-1, 1}}, b));      // a rotated square
  EXPECT_FALSE(axis_aligned_rectangle({{0, 0}, {2, 0}, {2, 0}, {0, 0}}, b));       // no area
  EXPECT_FALSE(axis_aligned_rectangle({{0, 0}, {2, 0}, {0, 1}, {2, 1}}, b));       // a bow tie
  EXPECT_FALSE(axis_aligned_rectangle({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, b));  // an L
}

}  // namespace
}  // namespace vascsim::render

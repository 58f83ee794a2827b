// Vessel networks (issue 12): the lumen polygon against analytic areas and brute-force distance,
// its outline closed and simple, no wall across a junction's mouth, Murray's law in the shipped
// tree, and every shipped vessel scene traversed to its goal inside the lumen.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <nlohmann/json.hpp>

#include "sim/env/vessel_environment.h"
#include "sim/env/vessel_graph.h"
#include "sim/env/vessel_lumen.h"
#include "sim/env/wall_distance.h"
#include "sim/io/scene_reader.h"
#include "sim/log/channel_names.h"
#include "sim/run/compile.h"
#include "sim/run/navigation.h"
#include "sim/run/run.h"
#include "sim/scene/input_error.h"
#include "tests/sanitizer_budget.h"

namespace vascsim {
namespace {

constexpr double kPi = 3.14159265358979323846;

Scene shipped(const std::string& name) {
  return read_scene_file(std::string(VASCSIM_SOURCE_DIR) + "/scenes/" + name + ".json");
}

Environment environment_of(const std::string& name) {
  const Scene s = shipped(name);
  return build_vessel_environment(s.vessels, s.rod.length);
}

const char* const kGraphScenes[] = {"bifurcation", "aneurysm", "stenosis", "tortuous", "vessel_tree"};
const char* const kAllScenes[] = {"bifurcation", "aneurysm", "stenosis", "tortuous", "vessel_tree", "vessel_mask"};
const auto kSceneName = [](const auto& info) { return std::string(info.param); };

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Proper or touching intersection of segments ab and cd (an independent check, not Clipper's).
bool segments_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

TEST(VesselLumen, StraightTubeAndDiscAreasMatchTheFormulas) {
  const double r = 0.05, length = 0.8, chord = 1e-3 * r;
  // A tube piece is the hull of its end discs: area 2 r L + pi r^2 (less the facets' sliver).
  const auto tube = lumen_union({tapered_tube_ring(Vec2(0, 0), r, Vec2(length, 0), r, chord)}, 0.0, chord);
  ASSERT_EQ(tube.size(), 1u);
  EXPECT_NEAR(lumen_area(tube), 2 * r * length + kPi * r * r, 2.0 * chord * (2 * length + 2 * kPi * r));
  // Two overlapping discs: the lens-corrected union area.
  const double d = 0.06;
  const auto two = lumen_union({disc_ring(Vec2(0, 0), r, chord), disc_ring(Vec2(d, 0), r, chord)}, 0.0, chord);
  ASSERT_EQ(two.size(), 1u);
  const double lens = 2 * r * r * std::acos(d / (2 * r)) - 0.5 * d * std::sqrt(4 * r * r - d * d);
  EXPECT_NEAR(lumen_area(two), 2 * kPi * r * r - lens, 2.0 * chord * 4 * kPi * r);
  // A ring of tubes around a square leaves a hole: one counter-clockwise and one clockwise ring.
  std::vector<Polyline> square;
  const Vec2 c[4] = {Vec2(0, 0), Vec2(0.5, 0), Vec2(0.5, 0.5), Vec2(0, 0.5)};
  for (int k = 0; k < 4; ++k) square.push_back(tapered_tube_ring(c[k], r, c[(k + 1) % 4], r, chord));
  const auto loop = lumen_union(square, 0.0, chord);
  ASSERT_EQ(loop.size(), 2u);
  EXPECT_GT(lumen_area({loop[0]}) * lumen_area({loop[1]}), -1e300);
  EXPECT_LT(lumen_area({loop[0]}) * lumen_area({loop[1]}), 0.0) << "outer and hole have opposite orientation";
  EXPECT_TRUE(inside_lumen(loop, Vec2(0.25, 0.0)));
  EXPECT_FALSE(inside_lumen(loop, Vec2(0.25, 0.25)));
}

TEST(VesselLumen, RoundingMovesNoStraightWallAndBluntsTheCarina) {
  const double r = 0.05, chord = 1e-3 * r;
  // A V of two tubes: the closing fills the sharp inner corner and leaves the straight walls.
  const std::vector<Polyline> v = {tapered_tube_ring(Vec2(0, 0), r, Vec2(0.5, 0.3), r, chord),
                                   tapered_tube_ring(Vec2(0, 0), r, Vec2(0.5, -0.3), r, chord)};
  const auto sharp = lumen_union(v, 0.0, chord), round = lumen_union(v, 0.25 * r, chord);
  EXPECT_GT(lumen_area(round), lumen_area(sharp));
  WallHit a, b;
  // Mid-way along the upper tube, the wall is where it was.
  const Vec2 mid(0.25, 0.15);
  ASSERT_TRUE(WallDistanceField::nearest_brute_force(walls_along(sharp), mid, a));
  ASSERT_TRUE(WallDistanceField::nearest_brute_force(walls_along(round), mid, b));
  EXPECT_NEAR(a.distance, r, 2 * chord);
  EXPECT_NEAR(b.distance, r, 2 * chord);
}

TEST(VesselGraph, StenosisNarrowsToItsFractionSmoothly) {
  const Scene s = shipped("stenosis");
  const VesselGraph g = resolve_vessel_graph(s.vessels);
  const StenosisSpec& st = s.vessels.segments[0].stenoses[0];
  double narrowest = INFINITY, at = 0;
  for (const auto& v : g.segments[0].samples)
    if (v.radius < narrowest) narrowest = v.radius, at = v.s;
  EXPECT_NEAR(narrowest, st.fraction * 0.05, 1e-12);
  EXPECT_NEAR(at, st.at, 1e-9);
  EXPECT_DOUBLE_EQ(stenosis_factor({st}, st.at - 0.5 * st.length), 1.0);
  EXPECT_NEAR(stenosis_factor({st}, st.at + 0.25 * st.length), 0.5 * (1 + st.fraction), 1e-12);
}

// Murray (1926): the cube of a parent's radius is the sum of its daughters' cubes.
TEST(VesselGraph, ShippedTreeAndBifurcationObeyMurraysLaw) {
  for (const char* name : {"vessel_tree", "bifurcation"}) {
    const VesselGraph g = resolve_vessel_graph(shipped(name).vessels);
    int junctions = 0;
    for (std::size_t node = 0; node < g.names.size(); ++node) {
      double parent = 0, daughters = 0;
      int count = 0;
      for (const auto& seg : g.segments) {
        if (seg.to == static_cast<int>(node)) parent = std::pow(seg.samples.back().radius, 3);
        if (seg.from == static_cast<int>(node)) daughters += std::pow(seg.samples.front().radius, 3), ++count;
      }
      if (count < 2) continue;
      ++junctions;
      EXPECT_NEAR(daughters / parent, 1.0, 1e-4) << name << " at " << g.names[node];
    }
    EXPECT_EQ(junctions, std::string(name) == "vessel_tree" ? 7 : 1) << name;
  }
}

TEST(VesselGraph, ShortestRouteAndExplicitRoute) {
  Scene s = shipped("vessel_tree");
  const VesselGraph g = resolve_vessel_graph(s.vessels);
  const auto route = vessel_route(g, s.vessels);
  ASSERT_EQ(route.size(), 4u);  // inlet-g0, g0-g1a, g1a-g2ab, g2ab-g3aba
  EXPECT_EQ(g.names[static_cast<std::size_t>(g.segments[static_cast<std::size_t>(route.back().segment)].to)], "g3aba");
  s.vessels.route = {"inlet", "g0", "g1b"};
  EXPECT_THROW(vessel_route(g, s.vessels), InputError);  // does not end at the goal
  s.vessels.route = {"inlet", "g0", "g2ab", "g3aba"};
  try {
    vessel_route(g, s.vessels);
    FAIL() << "a route through a missing segment was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/vessels/route/2: no segment joins \"g0\" and \"g2ab\""), std::string::npos) << e.what();
  }
}

double largest_arc(const Trajectory& t) {
  double r = 0.0;
  for (const auto& piece : t.pieces()) r = std::max(r, piece.radius);
  return r;
}

// A vessel scene rounds each corner as far as its lumen allows; path.corner_radius, if given,
// caps that (and is kept in the canonical scene, which leaves it out when not given).
TEST(VesselPath, CornerRadiusCapsWhatTheLumenAllows) {
  Scene free = shipped("tortuous");
  EXPECT_EQ(nlohmann::json::parse(scene_to_json(free))["path"].count("corner_radius"), 0u);
  const double widest = largest_arc(*prepare_navigation(free)->trajectory);
  ASSERT_GT(widest, 0.0);
  Scene capped = shipped("tortuous");
  capped.path.corner_radius = 0.5 * widest;
  const std::unique_ptr<Navigation> nav = prepare_navigation(capped);
  EXPECT_NEAR(largest_arc(*nav->trajectory), 0.5 * widest, 1e-12 * widest);
  for (const auto& piece : nav->trajectory->pieces()) EXPECT_LE(piece.radius, 0.5 * widest * (1 + 1e-12));
  const Scene again = read_scene_text(scene_to_json(capped), "canonical.json");
  EXPECT_EQ(again.path.corner_radius, 0.5 * widest);
}

// The smallest distance from the reference path to a wall, relative to the narrowest radius of
// the route (negative: outside the lumen), over 4000 points along it.
double path_clearance(Scene scene) {
  const std::unique_ptr<Navigation> nav = prepare_navigation(scene);
  const Environment& env = nav->environment;
  const double narrowest = *std::min_element(env.centreline_radius.begin(), env.centreline_radius.end());
  double worst = INFINITY;
  for (int k = 0; k <= 4000; ++k) {
    const Vec2 p = nav->trajectory->position(nav->trajectory->duration() * k / 4000.0);
    WallHit hit;
    WallDistanceField::nearest_brute_force(env.walls, p, hit);
    worst = std::min(worst, (inside_lumen(env.lumen, p) ? 1.0 : -1.0) * std::abs(hit.distance) / narrowest);
  }
  return worst;
}

// A corner into a narrower branch is rounded by the branch's radius, not the parent's: sized by
// the parent's 50 mm, the arc entered a 10 mm side branch off-centre and crossed its wall (37 of
// 421 path points outside). Then the arc keeps within r (1 - cos(theta/2) / 2) of either leg:
// at 90 degrees at least 0.35 r from the wall.
TEST(VesselPath, RoundedCornersStayInsideANarrowerBranch) {
  for (const double branch : {0.01, 0.02, 0.005}) {
    const std::string text = R"({"vessels": {"nodes": {"inlet": [0.1, 0.5], "j": [0.5, 0.5], "end": [0.9, 0.5], "side": [0.5, 0.8]},
        "segments": [{"from": "inlet", "to": "j", "radius": 0.05}, {"from": "j", "to": "end", "radius": 0.05},
                     {"from": "j", "to": "side", "radius": )" + std::to_string(branch) + R"(}], "start": "inlet", "goal": "side"},
        "rod": {"outer_radius": 0.001, "inner_radius": 0.0005}})";
    EXPECT_GT(path_clearance(read_scene_text(text, "side_branch.json")), 0.3) << "branch radius " << branch;
  }
  for (const char* name : kGraphScenes) EXPECT_GT(path_clearance(shipped(name)), 0.3) << name;
}

// Facets follow the smallest radius, but never below 1 um: a 10 nm branch off the route made
// millions of vertices (30 s and 300 MB for 1e-8 m, minutes for less) before any check ran.
TEST(VesselLumen, AHairThinBranchDoesNotExplodeTheFacets) {
  Scene s = shipped("bifurcation");
  s.vessels.segments[1].radius = {1e-8, 1e-8};  // the branch the route does not take
  const Environment env = build_vessel_environment(s.vessels, s.rod.length);
  std::size_t vertices = 0;
  for (const auto& ring : env.lumen) vertices += ring.size();
  EXPECT_LT(vertices, 20000u);
  EXPECT_TRUE(inside_lumen(env.lumen, env.centreline[env.centreline.size() / 2]));
}

class ShippedNetwork : public ::testing::TestWithParam<const char*> {};

// The grid's query against every wall, at 10^5 random points over the bounds, inside and outside
// (2 10^4 under the sanitizers).
TEST_P(ShippedNetwork, DistanceQueryMatchesBruteForce) {
  const Environment env = environment_of(GetParam());
  const double radius = 0.05;
  const WallDistanceField field(env.walls, radius);
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> ux(env.bounds.min.x() - 0.05, env.bounds.max.x() + 0.05);
  std::uniform_real_distribution<double> uy(env.bounds.min.y() - 0.05, env.bounds.max.y() + 0.05);
  const int points = test::sweep_size(100000, 20000);
  int inside = 0, near = 0;
  for (int k = 0; k < points; ++k) {
    const Vec2 p(ux(rng), uy(rng));
    inside += inside_lumen(env.lumen, p);
    WallHit brute, grid;
    ASSERT_TRUE(WallDistanceField::nearest_brute_force(env.walls, p, brute));
    const bool found = field.nearest(p, radius, grid);
    ASSERT_EQ(found, brute.distance <= radius) << p.transpose();
    if (!found) continue;
    ++near;
    ASSERT_EQ(grid.distance, brute.distance) << p.transpose();
    ASSERT_EQ(grid.closest, brute.closest);
  }
  EXPECT_GT(inside, points / 20);
  EXPECT_GT(points - inside, points / 20);
  EXPECT_GT(near, points / 20);
}

TEST_P(ShippedNetwork, OutlineIsClosedAndSimple) {
  const Environment env = environment_of(GetParam());
  ASSERT_FALSE(env.lumen.empty());
  std::vector<WallSegment> edges = walls_along(env.lumen);
  // walls_along closes every ring: the edges' ends chain back to each ring's first point.
  std::size_t first = 0;
  for (const auto& ring : env.lumen) {
    ASSERT_GE(ring.size(), 3u);
    EXPECT_EQ(edges[first + ring.size() - 1].b, edges[first].a);
    first += ring.size();
  }
  EXPECT_GT(lumen_area(env.lumen), 0.0);
  // No two non-adjacent edges cross (quadratic: a few thousand edges).
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 2; j < edges.size(); ++j) {
      if (edges[i].a == edges[j].b || edges[i].b == edges[j].a) continue;
      ASSERT_FALSE(segments_meet(edges[i].a, edges[i].b, edges[j].a, edges[j].b)) << GetParam() << ": edges " << i << ", " << j;
    }
  // The whole reference centreline lies in the lumen, at least half its local radius from a wall.
  for (std::size_t k = 0; k < env.centreline.size(); ++k) {
    EXPECT_TRUE(inside_lumen(env.lumen, env.centreline[k]));
    WallHit hit;
    WallDistanceField::nearest_brute_force(env.walls, env.centreline[k], hit);
    EXPECT_GT(hit.distance, 0.5 * env.centreline_radius[k]) << GetParam() << " at " << env.centreline[k].transpose();
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedNetwork, ::testing::ValuesIn(kAllScenes), kSceneName);

// No wall across a branch's mouth: just past the parent's wall, a point on each daughter's
// centreline is as far from the wall as the daughter's radius.
TEST(VesselJunction, DaughterCentrelineKeepsItsRadiusAtTheMouth) {
  const Scene s = shipped("bifurcation");
  const Environment env = build_vessel_environment(s.vessels, s.rod.length);
  const VesselGraph g = resolve_vessel_graph(s.vessels);
  for (int k : {1, 2}) {
    const auto& seg = g.segments[static_cast<std::size_t>(k)];
    const Vec2 a = seg.samples.front().point, b = seg.samples.back().point;
    const double r = seg.samples.front().radius;
    // 1.5 parent radii along the daughter is past the parent tube's wall for both angles.
    const Vec2 p = a + 1.5 * 0.05 / std::sin(40 * kPi / 180) * (b - a).normalized();
    WallHit hit;
    ASSERT_TRUE(WallDistanceField::nearest_brute_force(env.walls, p, hit));
    EXPECT_NEAR(hit.distance, r, 2e-3 * r) << "daughter " << k;
  }
}

// As a user runs them: each reaches its goal with the tip within 2 mm RMS of its reference and
// never in a wall; in the aneurysm scene the tip never enters the sac.
class ShippedVesselScene : public ::testing::TestWithParam<const char*> {};

struct TipTrack : FrameSink {
  std::vector<Vec2> tips;
  std::size_t offset = 0, nodes = 0;
  void write(double, const std::vector<double>& values) override {
    tips.emplace_back(values[offset + 2 * nodes - 2], values[offset + 2 * nodes - 1]);
  }
};

TEST_P(ShippedVesselScene, ReachesItsGoalInsideTheLumen) {
  const Scene input = shipped(GetParam());
  vascsim::Run run(compile(input));
  TipTrack track;
  track.nodes = static_cast<std::size_t>(run.scene().rod.nodes);
  for (const auto& c : run.channels()) {
    if (c.name == channel::kPosition) break;
    track.offset += c.count;
  }
  run.run(track);
  const RunStatistics& st = run.statistics();
  ASSERT_FALSE(st.failed) << st.failure;
  EXPECT_TRUE(st.goal_reached);
  EXPECT_LT(st.tip_error_rms, 2e-3);
  EXPECT_LE(st.max_penetration, 0.0);
  const Environment& env = run.navigation()->environment;
  for (const Vec2& tip : track.tips) ASSERT_TRUE(inside_lumen(env.lumen, tip)) << tip.transpose();
  if (std::string(GetParam()) == "aneurysm") {
    const VesselGraph g = resolve_vessel_graph(input.vessels);
    ASSERT_EQ(g.sacs.size(), 1u);
    const auto& tube = g.segments[0].samples;
    int frames_in_sac = 0;
    for (const Vec2& tip : track.tips) {
      // In the sac: inside its disc and outside the tube (farther than the radius from the centreline).
      double to_centreline = INFINITY;
      for (std::size_t k = 1; k < tube.size(); ++k) {
        const Vec2 d = tube[k].point - tube[k - 1].point;
        const double t = std::clamp((tip - tube[k - 1].point).dot(d) / d.squaredNorm(), 0.0, 1.0);
        to_centreline = std::min(to_centreline, (tip - tube[k - 1].point - t * d).norm());
      }
      frames_in_sac += (tip - g.sacs[0].centre).norm() < g.sacs[0].radius && to_centreline > 0.05;
    }
    EXPECT_EQ(frames_in_sac, 0);
    EXPECT_GT(track.tips.size(), 1000u);
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedVesselScene, ::testing::ValuesIn(kAllScenes), kSceneName);

}  // namespace
}  // namespace vascsim

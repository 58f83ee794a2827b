// The reference path (issue 2, item 5): solver routes join start and goal through open cells, the
// paper's wall follower agrees with breadth-first search on perfect mazes, the rounded centreline
// keeps lumen_width/2 clear of every wall by the distance query, and the explicit-walls maze of the
// paper's Fig. 10 gives the route one reads off the figure.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "sim/env/centreline.h"
#include "sim/env/environment.h"
#include "sim/env/maze_solvers.h"
#include "sim/env/trajectory.h"
#include "sim/env/wall_distance.h"
#include "sim/scene/input_error.h"
#include "tests/env_test_support.h"

namespace vascsim {
namespace {

using test::maze_spec;

// 1000 seeds per size. The clearance sweep queries the distance field every 1/8 cell along the path,
// which on 60x60 (depth-first mazes give paths of ~1000 cells) costs ~10^4 queries per maze and ~0.1 s
// per maze under the sanitizers: there 60 seeds keep the suite fast while covering each pair of
// wall kind (seed % 2) and corner radius (seed % 3) ten times.
const test::MazeSize kSizes[] = {{1, 1, 1000}, {5, 5, 1000}, {1, 50, 1000}, {60, 60, 1000}};
constexpr int kClearanceSeeds60 = 60;

testing::AssertionResult is_route(const GridMaze& m, const std::vector<Cell>& cells) {
  if (cells.empty()) return testing::AssertionFailure() << "empty route";
  if (cells.front() != m.start) return testing::AssertionFailure() << "route does not begin at the start cell";
  if (cells.back() != m.goal) return testing::AssertionFailure() << "route does not end at the goal cell";
  std::vector<char> seen(m.open.size(), 0);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (!m.contains(cells[i])) return testing::AssertionFailure() << "cell " << i << " outside the grid";
    if (seen[static_cast<std::size_t>(m.index(cells[i]))]++) return testing::AssertionFailure() << "cell " << i << " repeats";
    if (i == 0) continue;
    const int dr = cells[i].row - cells[i - 1].row, dc = cells[i].col - cells[i - 1].col;
    const int side = dr == -1 && dc == 0 ? kNorth : dr == 1 && dc == 0 ? kSouth : dc == 1 && dr == 0 ? kEast : dc == -1 && dr == 0 ? kWest : 0;
    if (side == 0) return testing::AssertionFailure() << "cells " << i - 1 << " and " << i << " are not neighbours";
    if (!m.is_open(cells[i - 1], side)) return testing::AssertionFailure() << "step " << i << " goes through a wall";
  }
  return testing::AssertionSuccess();
}

// The smallest wall distance (m) the distance query reports along the trajectory, sampled every
// `step` of arc length plus every piece end and a few points per arc (sample()). +infinity if nothing
// is within `radius` anywhere; callers compare with a bound below radius.
double min_clearance(const Trajectory& traj, const WallDistanceField& field, double step, double radius) {
  double least = INFINITY;
  const auto probe = [&](const Vec2& p) {
    WallHit hit;
    if (field.nearest(p, radius, hit)) least = std::min(least, hit.distance);
  };
  const int n = static_cast<int>(std::ceil(traj.length() / step));
  for (int k = 0; k <= n; ++k) probe(traj.position(traj.duration() * k / std::max(n, 1)));
  for (const Vec2& p : traj.sample(0.05 * step)) probe(p);
  return least;
}

TEST(Path, SolversJoinStartAndGoalAndAgreeOnPerfectMazes) {
  for (const auto& size : kSizes)
    for (int seed = 0; seed < size.seeds; ++seed) {
      const GridMaze m = generate_maze(maze_spec(size.rows, size.cols, static_cast<std::uint64_t>(seed), 0.1));
      const std::vector<Cell> bfs = solve_breadth_first(m), follower = solve_wall_follower(m);
      ASSERT_TRUE(is_route(m, bfs)) << size.rows << "x" << size.cols << " seed " << seed;
      ASSERT_TRUE(is_route(m, follower)) << size.rows << "x" << size.cols << " seed " << seed;
      ASSERT_EQ(follower, bfs) << size.rows << "x" << size.cols << " seed " << seed;
    }
}

TEST(Path, CentrelineHasOnlyCornersAndRunsFromStartToGoal) {
  for (int seed = 0; seed < 200; ++seed) {
    const MazeSpec spec = maze_spec(5, 5, static_cast<std::uint64_t>(seed), 0.1);
    const Environment env = build_environment(spec);
    const Polyline line = reference_centreline(env, spec, PathSpec{});
    ASSERT_GE(line.size(), 2u);
    EXPECT_EQ(line.front(), env.start);
    EXPECT_EQ(line.back(), env.goal);
    for (std::size_t i = 1; i < line.size(); ++i) {
      const Vec2 u = line[i] - line[i - 1];
      ASSERT_TRUE(std::abs(u.x()) < 1e-12 || std::abs(u.y()) < 1e-12) << "legs are axis-aligned";
      if (i + 1 < line.size()) {
        const Vec2 w = line[i + 1] - line[i];
        ASSERT_GT(std::abs(u.x() * w.y() - u.y() * w.x()), 1e-6) << "point " << i << " is not a corner";
      }
    }
  }
  // A one-cell maze: start and goal coincide, one point.
  const MazeSpec one = maze_spec(1, 1, 1, 0.1);
  EXPECT_EQ(reference_centreline(build_environment(one), one, PathSpec{}).size(), 1u);
}

// Issue 2: "the centreline keeps width/2 clearance from every wall by the distance query". Corner
// radii 0 (sharp), 0.05 m (the default) and 0.1 m (half the pitch, the largest that keeps clearance,
// docs/environment.md); thick (0.1 m) and line walls alternate with the seed.
TEST(Path, RoundedCentrelineKeepsHalfLumenClearance) {
  const double radii[3] = {0.0, 0.05, 0.1};
  for (const auto& size : kSizes) {
    const int seeds = size.rows == 60 ? kClearanceSeeds60 : size.seeds;
    for (int seed = 0; seed < seeds; ++seed) {
      const double lumen = test::lumen_for_seed(seed);
      const MazeSpec spec = maze_spec(size.rows, size.cols, static_cast<std::uint64_t>(seed), lumen);
      const Environment env = build_environment(spec);
      PathSpec path;
      path.corner_radius = radii[seed % 3];
      path.solver = seed % 2 ? PathSolver::kBreadthFirst : PathSolver::kWallFollower;
      ASSERT_LE(path.corner_radius, max_clear_corner_radius(env, spec) + 1e-15);
      const Trajectory traj(reference_centreline(env, spec, path), path.corner_radius, 0.05);
      const WallDistanceField field(env.walls, lumen);
      const double least = min_clearance(traj, field, 0.2 / 8, lumen);
      ASSERT_GE(least, 0.5 * lumen * (1 - 1e-9))
          << size.rows << "x" << size.cols << " seed " << seed << " radius " << path.corner_radius;
    }
  }
}

// The clearance check above can fail: rounding with more than half the pitch cuts into the inner
// wall of a corner whose legs are long enough to give the arc its full radius.
TEST(Path, ClearanceCheckCatchesTooLargeCornerRadius) {
  int violations = 0;
  for (int seed = 0; seed < 20; ++seed) {
    const MazeSpec spec = maze_spec(5, 5, static_cast<std::uint64_t>(seed), 0.1);
    const Environment env = build_environment(spec);
    const Trajectory traj(reference_centreline(env, spec, PathSpec{}), 0.2, 0.05);
    const WallDistanceField field(env.walls, 0.1);
    if (min_clearance(traj, field, 0.2 / 8, 0.1) < 0.05 * (1 - 1e-9)) ++violations;
  }
  EXPECT_GT(violations, 0);
}

// Paper Fig. 10 as explicit zero-thickness walls. Its route, read off the wall list by hand: from the
// start cell west along the top row to column 2, down one, west one, down column 1 to the bottom row,
// west to the goal.
TEST(Path, PaperFig10ExplicitWalls) {
  const MazeSpec spec = test::paper_fig10_spec();
  const Environment env = build_environment(spec);
  EXPECT_FALSE(env.grid.has_value());
  EXPECT_EQ(env.walls.size(), 14u);
  EXPECT_NEAR(env.lumen_width, 0.2, 1e-15);

  const GridMaze grid = grid_from_walls(spec);
  EXPECT_EQ(grid.rows, 5);
  EXPECT_EQ(grid.cols, 5);
  EXPECT_EQ(grid.start, (Cell{0, 4}));
  EXPECT_EQ(grid.goal, (Cell{4, 0}));
  const std::vector<Cell> route = solve_breadth_first(grid);
  ASSERT_TRUE(is_route(grid, route));
  EXPECT_EQ(route, (std::vector<Cell>{{0, 4}, {0, 3}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {3, 1}, {4, 1}, {4, 0}}));
  EXPECT_EQ(solve_wall_follower(grid), route);  // the figure's maze is perfect: 24 passages, 25 cells

  PathSpec path;
  path.solver = PathSolver::kWallFollower;  // ignored: explicit walls always use breadth-first search
  const Polyline line = reference_centreline(env, spec, path);
  const Polyline expected = {{0.9, 0.9}, {0.5, 0.9}, {0.5, 0.7}, {0.3, 0.7}, {0.3, 0.1}, {0.1, 0.1}};
  ASSERT_EQ(line.size(), expected.size());
  for (std::size_t i = 0; i < line.size(); ++i) EXPECT_LT((line[i] - expected[i]).norm(), 1e-12) << i;
  EXPECT_EQ(line.front(), spec.start);
  EXPECT_EQ(line.back(), spec.goal);

  const Trajectory traj(line, 0.05, 0.05);
  const WallDistanceField field(env.walls, 0.2);
  EXPECT_GE(min_clearance(traj, field, 0.2 / 16, 0.2), 0.1 * (1 - 1e-9));
}

TEST(Path, ExplicitStartOffCentreIsJoinedToTheRoute) {
  MazeSpec spec = test::paper_fig10_spec();
  spec.start = Vec2(0.95, 0.85);
  const Polyline line = reference_centreline(build_environment(spec), spec, PathSpec{});
  EXPECT_EQ(line.front(), spec.start);
  EXPECT_LT((line[1] - Vec2(0.9, 0.9)).norm(), 1e-12);
  EXPECT_EQ(line.back(), spec.goal);
}

TEST(Path, ThickExplicitWallClosesEverySideItCovers) {
  MazeSpec spec = test::paper_fig10_spec();
  spec.walls = {WallSegment{Vec2(0.5, 0.5), Vec2(0.5, 0.5), 0.3}};  // a disc of radius 0.15 m on cell (2, 2)
  const GridMaze g = grid_from_walls(spec);
  EXPECT_EQ(g.open[static_cast<std::size_t>(g.index({2, 2}))], 0);
  EXPECT_FALSE(g.is_open({1, 2}, kSouth));
  EXPECT_FALSE(g.is_open({2, 1}, kEast));
  EXPECT_TRUE(g.is_open({1, 1}, kEast));  // centre segment (0.3,0.7)-(0.5,0.7) stays 0.2 m from the disc
  EXPECT_FALSE(g.is_open({0, 0}, kNorth));  // the bounds close the outer sides
}

TEST(Path, DisconnectedExplicitWallsAreAnInputError) {
  MazeSpec spec = test::paper_fig10_spec();
  spec.walls.push_back(WallSegment{Vec2(0.0, 0.5), Vec2(1.0, 0.5), 0.0});  // cuts the square in two
  try {
    grid_from_walls(spec);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("/maze: ", 0), 0u) << e.what();
  }
  EXPECT_THROW(reference_centreline(build_environment(spec), spec, PathSpec{}), InputError);
  MazeSpec fine = test::paper_fig10_spec();
  fine.grid_pitch = 1e-5;  // 10^10 cells
  EXPECT_THROW(grid_from_walls(fine), InputError);
  // One cell for the whole maze: start and goal share it, and the path went straight through the
  // walls between them (reported as a goal reached at once).
  for (const double pitch : {1.0, 5.0}) {
    MazeSpec coarse = test::paper_fig10_spec();
    coarse.grid_pitch = pitch;
    try {
      grid_from_walls(coarse);
      ADD_FAILURE() << "grid_pitch " << pitch << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("/maze/grid_pitch: expected path cells no wider than the channels", 0), 0u)
          << e.what();
    }
  }
}

TEST(Path, WallFollowerGivesUpOnALoopAroundTheGoal) {
  // A 3x3 grid with every inner side open except those around the centre goal: the goal is sealed,
  // the right-hand walk circles the ring forever, so the solver must stop and report no route.
  MazeSpec spec = test::paper_fig10_spec();
  spec.width = spec.height = 0.6;
  spec.start = Vec2(0.5, 0.5);
  spec.goal = Vec2(0.3, 0.3);
  spec.walls = {};
  GridMaze g = grid_from_walls(spec);
  for (int side : {kNorth, kEast, kSouth, kWest}) {
    g.open[static_cast<std::size_t>(g.index({1, 1}))] &= static_cast<std::uint8_t>(~side);
    const Cell d = neighbour({1, 1}, side);
    g.open[static_cast<std::size_t>(g.index(d))] &= static_cast<std::uint8_t>(~opposite(side));
  }
  EXPECT_TRUE(solve_wall_follower(g).empty());
  EXPECT_TRUE(solve_breadth_first(g).empty());
}

}  // namespace
}  // namespace vascsim

// The maze generator and the walls built from it (issue 2, item 4): every maze is perfect, the same
// seed gives the same bytes, different seeds give different mazes, and the walls sit exactly on the
// closed cell sides with the thickness that leaves lumen_width channels.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "sim/env/environment.h"
#include "sim/env/grid_maze.h"
#include "sim/env/wall_distance.h"
#include "sim/scene/input_error.h"
#include "tests/env_test_support.h"

namespace vascsim {
namespace {

using test::maze_spec;

// 1000 seeds on every size, as issue 2 asks; generation and these checks are linear in the cells, so
// even 1000 x 3600 cells stays within a second or two under the sanitizers.
const test::MazeSize kSizes[] = {{1, 1, 1000}, {5, 5, 1000}, {1, 50, 1000}, {60, 60, 1000}};

// Independent of the library's solvers: counts passages and flood-fills from cell 0.
testing::AssertionResult is_perfect(const GridMaze& m) {
  const int cells = m.rows * m.cols;
  if (static_cast<int>(m.open.size()) != cells) return testing::AssertionFailure() << "open has wrong size";
  int passages = 0;  // each open side counted from both of its cells
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c)
      for (int side : {kNorth, kEast, kSouth, kWest}) {
        if (!m.is_open({r, c}, side)) continue;
        const Cell d = neighbour({r, c}, side);
        if (!m.contains(d)) return testing::AssertionFailure() << "cell " << r << "," << c << " opens outside";
        if (!m.is_open(d, opposite(side)))
          return testing::AssertionFailure() << "cell " << r << "," << c << " side " << side << " open one way only";
        ++passages;
      }
  if (passages / 2 != cells - 1)
    return testing::AssertionFailure() << passages / 2 << " passages, a tree on " << cells << " cells has " << cells - 1;
  std::vector<char> seen(static_cast<std::size_t>(cells), 0);
  std::vector<Cell> todo{{0, 0}};
  seen[0] = 1;
  int reached = 1;
  while (!todo.empty()) {
    const Cell c = todo.back();
    todo.pop_back();
    for (int side : {kNorth, kEast, kSouth, kWest}) {
      const Cell d = neighbour(c, side);
      if (!m.is_open(c, side) || seen[static_cast<std::size_t>(m.index(d))]) continue;
      seen[static_cast<std::size_t>(m.index(d))] = 1;
      ++reached;
      todo.push_back(d);
    }
  }
  // Connected with cells - 1 edges is a spanning tree: acyclic as well.
  if (reached != cells) return testing::AssertionFailure() << "only " << reached << " of " << cells << " cells reachable";
  return testing::AssertionSuccess();
}

std::string wall_bytes(const std::vector<WallSegment>& walls) {
  std::string bytes;
  for (const auto& w : walls) {
    const double v[5] = {w.a.x(), w.a.y(), w.b.x(), w.b.y(), w.thickness};
    bytes.append(reinterpret_cast<const char*>(v), sizeof v);
  }
  return bytes;
}

TEST(Maze, EveryMazeIsPerfectWithStartTopRightAndGoalBottomLeft) {
  for (const auto& size : kSizes)
    for (int seed = 0; seed < size.seeds; ++seed) {
      const GridMaze m = generate_maze(maze_spec(size.rows, size.cols, static_cast<std::uint64_t>(seed), 0.1));
      ASSERT_EQ(m.rows, size.rows);
      ASSERT_EQ(m.cols, size.cols);
      ASSERT_TRUE(is_perfect(m)) << size.rows << "x" << size.cols << " seed " << seed;
      ASSERT_EQ(m.start, (Cell{0, size.cols - 1}));
      ASSERT_EQ(m.goal, (Cell{size.rows - 1, 0}));
    }
}

TEST(Maze, SameSeedGivesIdenticalBytes) {
  for (const auto& size : kSizes)
    for (int seed = 0; seed < 50; ++seed) {
      const MazeSpec spec = maze_spec(size.rows, size.cols, static_cast<std::uint64_t>(seed), test::lumen_for_seed(seed));
      const Environment a = build_environment(spec), b = build_environment(spec);
      ASSERT_EQ(a.grid->open, b.grid->open);
      ASSERT_EQ(wall_bytes(a.walls), wall_bytes(b.walls));
    }
}

// Pins the generator's output, so a change of the random mapping or of the platform's
// std::mt19937_64 shows up here (values recorded from this implementation; a regression guard).
TEST(Maze, Seed1FiveByFiveIsPinned) {
  const GridMaze m = generate_maze(maze_spec(5, 5, 1, 0.1));
  const std::vector<std::uint8_t> expected = {2, 10, 14, 12, 4, 6, 10, 9, 5, 5, 5, 6, 12, 5, 5, 5, 5, 5, 1, 5, 3, 9, 3, 10, 9};
  EXPECT_EQ(m.open, expected);
}

TEST(Maze, DifferentSeedsGiveDifferentMazes) {
  // 1x1 and 1x50 grids have exactly one spanning tree, so every seed must give that same maze.
  for (const auto& size : {kSizes[0], kSizes[2]})
    for (int seed = 1; seed < 100; ++seed)
      ASSERT_EQ(generate_maze(maze_spec(size.rows, size.cols, static_cast<std::uint64_t>(seed), 0.1)).open,
                generate_maze(maze_spec(size.rows, size.cols, 0, 0.1)).open);
  for (const auto& size : {kSizes[1], kSizes[3]}) {
    std::set<std::vector<std::uint8_t>> distinct;
    std::vector<std::uint8_t> previous;
    for (int seed = 0; seed < size.seeds; ++seed) {
      auto open = generate_maze(maze_spec(size.rows, size.cols, static_cast<std::uint64_t>(seed), 0.1)).open;
      ASSERT_NE(open, previous) << size.rows << "x" << size.cols << " seeds " << seed - 1 << " and " << seed;
      distinct.insert(open);
      previous = std::move(open);
    }
    // 5x5 has about 5.6e8 spanning trees, but depth-first search favours long corridors and reaches
    // far fewer of them, so some of 1000 seeds repeat a maze (976 distinct with this generator):
    // require 95 %. A 60x60 repeat would mean the seed is being ignored.
    const std::size_t least = size.rows == 5 ? 950 : static_cast<std::size_t>(size.seeds);
    EXPECT_GE(distinct.size(), least) << size.rows << "x" << size.cols;
  }
  EXPECT_NE(generate_maze(maze_spec(5, 5, 1, 0.1)).open, generate_maze(maze_spec(5, 5, 2, 0.1)).open);
}

TEST(Maze, CellCentresFollowTheConventions) {
  MazeSpec spec = maze_spec(5, 4, 3, 0.1);
  spec.width = 1.0;
  spec.height = 2.0;
  const GridMaze m = generate_maze(spec);
  // Row 0 is the top row: y largest. Cells are 0.25 m wide and 0.4 m tall.
  EXPECT_NEAR(m.centre({0, 0}).x(), 0.125, 1e-15);
  EXPECT_NEAR(m.centre({0, 0}).y(), 1.8, 1e-15);
  EXPECT_NEAR(m.centre({4, 3}).x(), 0.875, 1e-15);
  EXPECT_NEAR(m.centre({4, 3}).y(), 0.2, 1e-15);
  EXPECT_EQ(m.cell_at(Vec2(0.9, 0.1)), (Cell{4, 3}));
  EXPECT_EQ(m.cell_at(Vec2(-5.0, 50.0)), (Cell{0, 0}));  // clamped
}

TEST(Maze, BadSizesAreInputErrors) {
  EXPECT_THROW(generate_maze(maze_spec(0, 5, 1, 0.1)), InputError);
  EXPECT_THROW(generate_maze(maze_spec(5, -1, 1, 0.1)), InputError);
  MazeSpec spec = maze_spec(5, 5, 1, 0.1);
  spec.width = 0.0;
  EXPECT_THROW(generate_maze(spec), InputError);
  // 60 rows on the default 1 m x 1 m leave 1/60 m cells, too narrow for the default 0.1 m lumen.
  MazeSpec narrow;
  narrow.rows = 60;
  try {
    build_environment(narrow);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/maze/lumen_width"), std::string::npos) << e.what();
  }
}

// Walls lie on exactly the closed sides: the midpoint of a closed side is on a wall's centre line
// (signed distance -thickness/2), the midpoint of an open side is lumen_width/2 clear of every wall.
TEST(Maze, WallsSitOnTheClosedSidesWithChannelsOfLumenWidth) {
  for (const auto& size : kSizes)
    for (int seed = 0; seed < 20; ++seed) {
      const double lumen = test::lumen_for_seed(seed);
      const Environment env = build_environment(maze_spec(size.rows, size.cols, static_cast<std::uint64_t>(seed), lumen));
      const GridMaze& m = *env.grid;
      const WallDistanceField field(env.walls, lumen);  // checked against brute force in wall_distance_test
      const double thickness = 0.2 - lumen, tol = 1e-12;
      for (const auto& w : env.walls) ASSERT_NEAR(w.thickness, thickness, tol);
      for (int r = 0; r < m.rows; ++r)
        for (int c = 0; c < m.cols; ++c)
          for (int side : {kNorth, kEast, kSouth, kWest}) {
            const Cell d = neighbour({r, c}, side);
            const Vec2 mid = m.contains(d) ? Vec2(0.5 * (m.centre({r, c}) + m.centre(d)))
                                           : Vec2(m.centre({r, c}) + (side == kNorth ? Vec2(0, 0.1) : side == kSouth ? Vec2(0, -0.1)
                                                                     : side == kEast ? Vec2(0.1, 0) : Vec2(-0.1, 0)));
            WallHit hit;
            const bool near = field.nearest(mid, lumen, hit);  // none within lumen: clear anyway
            if (m.is_open({r, c}, side)) {
              ASSERT_TRUE(!near || hit.distance >= 0.5 * lumen - tol) << r << "," << c << " side " << side;
            } else {
              ASSERT_TRUE(near) << r << "," << c << " side " << side;
              ASSERT_NEAR(hit.distance, -0.5 * thickness, tol) << r << "," << c << " side " << side;
            }
          }
    }
}

TEST(Maze, CollinearWallPiecesAreMerged) {
  // 1x50: all inner sides open, so the walls are the four sides of the boundary rectangle.
  const Environment corridor = build_environment(maze_spec(1, 50, 7, 0.1));
  EXPECT_EQ(corridor.walls.size(), 4u);
  EXPECT_EQ(build_environment(maze_spec(1, 1, 7, 0.2)).walls.size(), 4u);
  // No two walls of the same direction may share an end point: they would lie on one line and have
  // been merged into one segment.
  for (int seed = 0; seed < 20; ++seed) {
    const auto walls = build_environment(maze_spec(60, 60, static_cast<std::uint64_t>(seed), 0.1)).walls;
    std::map<std::tuple<long long, long long, bool>, int> ends;  // (x, y in 1e-6 m, horizontal) -> count
    for (const auto& w : walls) {
      const bool horizontal = w.a.y() == w.b.y();
      ASSERT_TRUE(horizontal || w.a.x() == w.b.x()) << "generated walls are axis-aligned";
      for (const Vec2& p : {w.a, w.b})
        ASSERT_EQ(++ends[std::make_tuple(std::llround(p.x() * 1e6), std::llround(p.y() * 1e6), horizontal)], 1)
            << "two walls meet end to end on one line at " << p.transpose();
    }
  }
}

}  // namespace
}  // namespace vascsim

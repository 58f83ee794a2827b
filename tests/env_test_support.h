// Helpers shared by the maze, path and wall distance tests: maze specs for the sizes the tests sweep,
// and the explicit-walls scene of the paper's Fig. 10.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/scene/scene.h"

namespace vascsim::test {

struct MazeSize {
  int rows;
  int cols;
  int seeds;  // how many seeds the sweeping tests run on this size
};

// A rows x cols maze of 0.2 m cells. lumen 0.1 m gives 0.1 m thick walls (the paper's text), lumen
// 0.2 m zero-thickness line walls (the paper's figures).
inline MazeSpec maze_spec(int rows, int cols, std::uint64_t seed, double lumen) {
  MazeSpec m;
  m.rows = rows;
  m.cols = cols;
  m.width = 0.2 * cols;
  m.height = 0.2 * rows;
  m.lumen_width = lumen;
  m.seed = seed;
  return m;
}

// Alternate thick and line walls across seeds so every sweep covers both.
inline double lumen_for_seed(std::uint64_t seed) { return seed % 2 == 0 ? 0.1 : 0.2; }

// The maze of the paper's Fig. 10 (issue 2, item 4): boundary square 0..1 m, ten interior wall lines,
// all of zero thickness, start (0.9, 0.9), goal (0.1, 0.1), path grid pitch 0.2 m.
inline MazeSpec paper_fig10_spec() {
  MazeSpec m;
  m.explicit_walls = true;
  m.width = 1.0;
  m.height = 1.0;
  m.grid_pitch = 0.2;
  m.start = Vec2(0.9, 0.9);
  m.goal = Vec2(0.1, 0.1);
  const double lines[][4] = {
      {0, 0, 1, 0}, {1, 0, 1, 1}, {1, 1, 0, 1}, {0, 1, 0, 0},  // boundary
      {0, 0.2, 0.2, 0.2}, {0.2, 0.2, 0.2, 0.8}, {0.2, 0.8, 0.4, 0.8}, {0.4, 0, 0.4, 0.6},
      {0.4, 0.6, 0.6, 0.6}, {0.6, 0.2, 0.6, 0.8}, {0.6, 0.8, 0.8, 0.8}, {0.6, 0.4, 0.8, 0.4},
      {0.8, 0.2, 0.8, 0.4}, {0.8, 0.6, 1, 0.6}};
  for (const auto& l : lines) m.walls.push_back(WallSegment{Vec2(l[0], l[1]), Vec2(l[2], l[3]), 0.0});
  return m;
}

}  // namespace vascsim::test

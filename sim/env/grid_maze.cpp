#include "sim/env/grid_maze.h"

#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include "sim/scene/input_error.h"

namespace vascsim {

namespace {

constexpr int kSides[4] = {kNorth, kEast, kSouth, kWest};
constexpr long long kMaxCells = 1000000;  // bounds memory and time for a hand-made MazeSpec

// Uniform integer in [0, n) from a 64-bit engine, unbiased: reject the 2^64 mod n lowest raw values
// so every residue is equally likely. Written out because std::uniform_int_distribution's output is
// implementation-defined, and the maze for a seed must be the same bytes everywhere.
std::uint64_t uniform_below(std::mt19937_64& rng, std::uint64_t n) {
  const std::uint64_t reject_below = (0 - n) % n;  // 2^64 mod n
  for (;;) {
    const std::uint64_t r = rng();
    if (r >= reject_below) return r % n;
  }
}

void check_size(const MazeSpec& spec) {
  std::ostringstream msg;
  if (spec.rows < 1) msg << "/maze/rows: expected an integer >= 1, got " << spec.rows;
  else if (spec.cols < 1) msg << "/maze/cols: expected an integer >= 1, got " << spec.cols;
  else if (static_cast<long long>(spec.rows) * spec.cols > kMaxCells)
    msg << "/maze: expected at most " << kMaxCells << " cells, got " << spec.rows << " x " << spec.cols;
  else if (!(spec.width > 0.0) || !std::isfinite(spec.width))
    msg << "/maze/width: expected a positive number, got " << spec.width;
  else if (!(spec.height > 0.0) || !std::isfinite(spec.height))
    msg << "/maze/height: expected a positive number, got " << spec.height;
  else return;
  throw InputError(msg.str());
}

}  // namespace

Cell neighbour(Cell c, int side) {
  switch (side) {
    case kNorth: return {c.row - 1, c.col};
    case kEast: return {c.row, c.col + 1};
    case kSouth: return {c.row + 1, c.col};
    default: return {c.row, c.col - 1};
  }
}

int opposite(int side) { return side == kNorth ? kSouth : side == kSouth ? kNorth : side == kEast ? kWest : kEast; }

Vec2 GridMaze::centre(Cell c) const {
  return Vec2((c.col + 0.5) * pitch_x(), height - (c.row + 0.5) * pitch_y());
}

Cell GridMaze::cell_at(const Vec2& p) const {
  // Compare in double before converting: a point far outside (or NaN) must not overflow the cast.
  const auto clamp_index = [](double f, int n) {
    if (!(f >= 0.0)) return 0;
    if (f >= n) return n - 1;
    return static_cast<int>(f);
  };
  return {clamp_index((height - p.y()) / pitch_y(), rows), clamp_index(p.x() / pitch_x(), cols)};
}

// Randomised depth-first search ("recursive backtracker"), iterative so that a 1000 x 1000 maze
// cannot overflow the call stack. From the cell on top of the stack, carve into a uniformly chosen
// unvisited neighbour; when there is none, backtrack. Every cell is entered exactly once through one
// carved passage, so the result is a spanning tree: connected and acyclic. DFS gives the long winding
// corridors of the paper's Fig. 10.
GridMaze generate_maze(const MazeSpec& spec) {
  check_size(spec);
  GridMaze m;
  m.rows = spec.rows;
  m.cols = spec.cols;
  m.width = spec.width;
  m.height = spec.height;
  m.open.assign(static_cast<std::size_t>(m.rows) * m.cols, 0);
  m.start = {0, m.cols - 1};
  m.goal = {m.rows - 1, 0};

  std::mt19937_64 rng(spec.seed);
  std::vector<char> visited(m.open.size(), 0);
  std::vector<Cell> stack{m.start};
  visited[static_cast<std::size_t>(m.index(m.start))] = 1;
  while (!stack.empty()) {
    const Cell c = stack.back();
    int choices[4];
    int n = 0;
    for (int side : kSides) {
      const Cell d = neighbour(c, side);
      if (m.contains(d) && !visited[static_cast<std::size_t>(m.index(d))]) choices[n++] = side;
    }
    if (n == 0) {
      stack.pop_back();
      continue;
    }
    const int side = choices[uniform_below(rng, static_cast<std::uint64_t>(n))];
    const Cell d = neighbour(c, side);
    m.open[static_cast<std::size_t>(m.index(c))] |= static_cast<std::uint8_t>(side);
    m.open[static_cast<std::size_t>(m.index(d))] |= static_cast<std::uint8_t>(opposite(side));
    visited[static_cast<std::size_t>(m.index(d))] = 1;
    stack.push_back(d);
  }
  return m;
}

}  // namespace vascsim

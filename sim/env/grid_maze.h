// A perfect maze on a rows x cols grid of cells (paper II.A): every cell is reachable from every
// other by exactly one route, so the maze is a spanning tree of the grid graph. Cells are numbered
// like a matrix (row 0 at the top, where y is largest; col 0 at the left); each cell stores which
// of its four sides are open passages. The generator is a seeded random depth-first search whose
// output is the same bytes on every platform for a given seed. The physical walls built from a
// maze are in environment.h; docs/environment.md describes the conventions.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/env/geometry.h"
#include "sim/scene/scene.h"

namespace vascsim {

// Side bits of GridMaze::open, and the direction index d of a side: bit = 1 << d.
inline constexpr int kNorth = 1;  // towards row - 1 (y up)
inline constexpr int kEast = 2;   // towards col + 1 (x up)
inline constexpr int kSouth = 4;  // towards row + 1
inline constexpr int kWest = 8;   // towards col - 1

struct Cell {
  int row = 0;  // 0 is the TOP row (y largest)
  int col = 0;  // 0 is the left column
};
inline bool operator==(const Cell& a, const Cell& b) { return a.row == b.row && a.col == b.col; }
inline bool operator!=(const Cell& a, const Cell& b) { return !(a == b); }

// The neighbour of `c` across `side` (one of kNorth..kWest); may lie outside the grid.
Cell neighbour(Cell c, int side);
// The side of a cell facing back across `side` (kNorth <-> kSouth, kEast <-> kWest).
int opposite(int side);

struct GridMaze {
  int rows = 0;
  int cols = 0;
  double width = 0.0;              // m, x extent; cells are width/cols wide
  double height = 0.0;             // m, y extent; cells are height/rows tall
  std::vector<std::uint8_t> open;  // per cell (row * cols + col), bitmask of open sides (kNorth...)
  Cell start;                      // generated: top-right cell (0, cols - 1)
  Cell goal;                       // generated: bottom-left cell (rows - 1, 0)

  bool contains(Cell c) const { return c.row >= 0 && c.row < rows && c.col >= 0 && c.col < cols; }
  int index(Cell c) const { return c.row * cols + c.col; }
  // `c` must be inside the grid.
  bool is_open(Cell c, int side) const { return (open[static_cast<std::size_t>(index(c))] & side) != 0; }
  Vec2 centre(Cell c) const;       // m
  double pitch_x() const { return width / cols; }   // m
  double pitch_y() const { return height / rows; }  // m
  // The cell containing point p (m), clamped to the grid.
  Cell cell_at(const Vec2& p) const;
};

// A random perfect maze of spec.rows x spec.cols cells over spec.width x spec.height, from
// spec.seed. Deterministic across runs and platforms: std::mt19937_64 (fully specified by the
// standard) with our own unbiased integer mapping, never std::uniform_int_distribution.
// Throws InputError if the size is not positive.
GridMaze generate_maze(const MazeSpec& spec);

}  // namespace vascsim

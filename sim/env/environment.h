// The world the robot moves in, resolved from a MazeSpec into plain geometry: wall segments with a
// thickness (capsules, geometry.h), the start and goal points, the nominal channel width, and for a
// generated maze the cell grid it came from. Contact queries on these walls are in wall_distance.h,
// the reference path through them in centreline.h. Conventions: docs/environment.md.
#pragma once

#include <optional>
#include <vector>

#include "sim/env/geometry.h"
#include "sim/env/grid_maze.h"
#include "sim/scene/scene.h"

namespace vascsim {

struct Environment {
  Box2 bounds;                     // m, the maze rectangle 0..width x 0..height (the centre lines of the
                                   // outer walls; thick outer walls reach thickness/2 beyond it)
  std::vector<WallSegment> walls;  // m, includes the outer boundary
  Vec2 start = Vec2::Zero();       // m
  Vec2 goal = Vec2::Zero();        // m
  double lumen_width = 0.0;        // m, nominal channel width
  std::optional<GridMaze> grid;    // generated mazes only
};

// Generated maze (spec.explicit_walls false): the walls of generate_maze(spec). A wall lies on every
// closed cell side and on the outer boundary, centred on the grid line, with thickness = cell pitch -
// lumen_width (pitch 0.2 m, lumen 0.1 m: 0.1 m thick walls; lumen == pitch: zero-thickness line walls,
// as the paper's figures draw them), so every channel is exactly lumen_width wide. Collinear adjacent
// pieces are merged into one segment: fewer walls and no seams at the joints. Start and goal are the
// centres of the start (top-right) and goal (bottom-left) cells.
// Explicit walls: spec.walls, spec.start and spec.goal as given; lumen_width is the nominal
// grid_pitch - (thickest wall), assuming the walls lie on the grid lines as in the paper's Fig. 10.
// Throws InputError if lumen_width does not fit in a cell.
Environment build_environment(const MazeSpec& spec);

}  // namespace vascsim

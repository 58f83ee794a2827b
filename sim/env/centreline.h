// The ideal path of the robot's tip (paper II.A): the lumen centreline from start to goal, as the
// sharp-cornered polyline through the centres of the cells where the route turns. Corner rounding and
// timing are trajectory.h's job. In a generated maze any corner radius up to half the cell pitch keeps
// the rounded path lumen_width/2 away from every wall (docs/environment.md shows why).
#pragma once

#include <vector>

#include "sim/env/environment.h"
#include "sim/env/grid_maze.h"
#include "sim/scene/scene.h"

namespace vascsim {

// Centres of the first cell, of every cell where the route turns, and of the last cell (collinear
// centres removed): from the start point to the goal point. A one-cell route gives one point.
// `cells` must be a route of consecutive neighbouring cells (a solver's output); empty gives empty.
Polyline cell_path_centreline(const GridMaze& maze, const std::vector<Cell>& cells);

// A maze's route, solved once: the grid it was solved on, the cells from start to goal, which
// solver found them, and the reference centreline through them.
struct MazeRoute {
  GridMaze grid;
  std::vector<Cell> cells;
  bool breadth_first = false;  // else the wall follower
  Polyline corners;            // the sharp centreline, start to goal
};

// The route of a scene's maze. Generated mazes: the solver named by path.solver on env.grid
// (regenerated from `maze` if env.grid is empty). Explicit walls: always breadth-first search on
// grid_from_walls(maze), with maze.start and maze.goal as the first and last points (joined to the
// nearest cell centres when they are not centres themselves). Throws InputError if no path exists
// (message starting with a JSON path, e.g. "/maze: ...").
MazeRoute solve_route(const Environment& env, const MazeSpec& maze, const PathSpec& path);
// solve_route(...).corners.
Polyline reference_centreline(const Environment& env, const MazeSpec& maze, const PathSpec& path);

// The largest corner radius (m) that keeps the rounded centreline of a generated maze lumen_width/2
// clear of the walls: half the smaller cell pitch. For explicit walls, half of maze.grid_pitch
// (exact when the walls lie on the grid lines, as in the paper's Fig. 10).
double max_clear_corner_radius(const Environment& env, const MazeSpec& maze);

}  // namespace vascsim

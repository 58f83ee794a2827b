// Cell paths from a maze's start cell to its goal cell. The wall follower is the paper's solver
// (II.A): walk keeping the right hand on a wall, and erase every loop the walk closes (each dead-end
// excursion), which leaves the direct route. Breadth-first search gives a shortest route and also
// works on grids with loops, such as the grid laid over an explicit wall list (grid_from_walls). In a
// perfect maze the route is unique, so both solvers return the same cells.
#pragma once

#include <vector>

#include "sim/env/grid_maze.h"
#include "sim/scene/scene.h"

namespace vascsim {

// Cells from maze.start to maze.goal inclusive, consecutive cells sharing an open side. Empty if the
// walk cycles without reaching the goal (possible only when loops in the maze surround the goal).
std::vector<Cell> solve_wall_follower(const GridMaze& maze);
// A shortest such path (neighbours tried N, E, S, W: deterministic). Empty if the goal is unreachable.
std::vector<Cell> solve_breadth_first(const GridMaze& maze);

// The path grid of an explicit-walls maze: cells of about spec.grid_pitch (adjusted so a whole number
// of cells tiles spec.width x spec.height) over the bounds. A side is open when no wall capsule (with
// its thickness; touching counts) meets the segment between the two neighbouring cell centres; sides
// on the bounds are closed. start and goal are the cells containing spec.start and spec.goal. The
// grid may have loops. Throws InputError (message starting with the JSON path "/maze...") if the grid
// would exceed 10^6 cells or if start and goal are not connected.
GridMaze grid_from_walls(const MazeSpec& spec);

}  // namespace vascsim

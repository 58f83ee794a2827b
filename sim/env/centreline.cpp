#include "sim/env/centreline.h"

#include <algorithm>
#include <cmath>

#include "sim/env/maze_solvers.h"
#include "sim/scene/input_error.h"

namespace vascsim {

namespace {

// True if q lies on the straight line a-b between them (within rounding), so it is not a corner.
bool between_collinear(const Vec2& a, const Vec2& q, const Vec2& b) {
  const Vec2 u = q - a, v = b - q;
  const double cross = u.x() * v.y() - u.y() * v.x();
  return std::abs(cross) <= 1e-12 * u.norm() * v.norm() && u.dot(v) >= 0.0;
}

// Makes `first` the first point of the line: moves the first centre onto it when they coincide to
// within `snap` (rounding of the cell centres), else prepends it and drops the old first point if it
// became a straight-through point. Same for the last point with `last`.
void attach_ends(Polyline& line, const Vec2& first, const Vec2& last, double snap) {
  if ((line.front() - first).norm() <= snap) {
    line.front() = first;
  } else {
    line.insert(line.begin(), first);
    if (line.size() >= 3 && between_collinear(line[0], line[1], line[2])) line.erase(line.begin() + 1);
  }
  if ((line.back() - last).norm() <= snap) {
    line.back() = last;
  } else {
    line.push_back(last);
    const std::size_t n = line.size();
    if (n >= 3 && between_collinear(line[n - 3], line[n - 2], line[n - 1])) line.erase(line.end() - 2);
  }
}

}  // namespace

Polyline cell_path_centreline(const GridMaze& maze, const std::vector<Cell>& cells) {
  Polyline line;
  const std::size_t n = cells.size();
  for (std::size_t i = 0; i < n; ++i) {
    // Decide on cell indices, not on coordinates: the step direction either changes or it does not.
    const bool corner = i == 0 || i + 1 == n ||
                        cells[i].row - cells[i - 1].row != cells[i + 1].row - cells[i].row ||
                        cells[i].col - cells[i - 1].col != cells[i + 1].col - cells[i].col;
    if (corner) line.push_back(maze.centre(cells[i]));
  }
  return line;
}

MazeRoute solve_route(const Environment& env, const MazeSpec& maze, const PathSpec& path) {
  MazeRoute route;
  if (maze.explicit_walls) {
    route.grid = grid_from_walls(maze);  // throws if start and goal are not connected
    route.breadth_first = true;
    route.cells = solve_breadth_first(route.grid);
    route.corners = cell_path_centreline(route.grid, route.cells);
    attach_ends(route.corners, maze.start, maze.goal, 1e-9 * std::min(route.grid.pitch_x(), route.grid.pitch_y()));
    return route;
  }
  route.grid = env.grid ? *env.grid : generate_maze(maze);
  route.breadth_first = path.solver != PathSolver::kWallFollower;
  route.cells = route.breadth_first ? solve_breadth_first(route.grid) : solve_wall_follower(route.grid);
  if (route.cells.empty())  // a generated maze is perfect, so this means a hand-made grid without a route
    throw InputError("/path/solver: the solver found no route from the start cell to the goal cell");
  route.corners = cell_path_centreline(route.grid, route.cells);
  return route;
}

Polyline reference_centreline(const Environment& env, const MazeSpec& maze, const PathSpec& path) {
  return solve_route(env, maze, path).corners;
}

double max_clear_corner_radius(const Environment& env, const MazeSpec& maze) {
  if (env.grid) return 0.5 * std::min(env.grid->pitch_x(), env.grid->pitch_y());
  if (!maze.explicit_walls) return 0.5 * std::min(maze.width / maze.cols, maze.height / maze.rows);
  return 0.5 * maze.grid_pitch;
}

}  // namespace vascsim

#include "sim/io/maze_json.h"

#include <nlohmann/json.hpp>

#include "sim/env/centreline.h"
#include "sim/env/environment.h"
#include "sim/env/maze_solvers.h"
#include "sim/env/trajectory.h"
#include "sim/io/scene_reader.h"
#include "sim/scene/input_error.h"

namespace vascsim {

using nlohmann::json;

namespace {

json point(const Vec2& p) { return json::array({p.x(), p.y()}); }

json polyline(const Polyline& line) {
  json out = json::array();
  for (const auto& p : line) out.push_back(point(p));
  return out;
}

// Cells of a grid maze: the open-sides bitmask row by row, and the solved cell path.
json grid_json(const GridMaze& grid, const std::vector<Cell>& path) {
  json open = json::array();
  for (int r = 0; r < grid.rows; ++r) {
    json row = json::array();
    for (int c = 0; c < grid.cols; ++c) row.push_back(grid.open[static_cast<std::size_t>(r * grid.cols + c)]);
    open.push_back(row);
  }
  json cells = json::array();
  for (const auto& c : path) cells.push_back({c.row, c.col});
  return {{"rows", grid.rows}, {"cols", grid.cols},
          {"open_sides", open}, {"side_bits", {{"north", 1}, {"east", 2}, {"south", 4}, {"west", 8}}},
          {"start_cell", {grid.start.row, grid.start.col}}, {"goal_cell", {grid.goal.row, grid.goal.col}},
          {"path_cells", cells}};
}

std::string maze_document_unlabelled(const Scene& scene) {
  const Environment env = build_environment(scene.maze);
  const GridMaze grid = env.grid ? *env.grid : grid_from_walls(scene.maze);
  const bool use_bfs = scene.maze.explicit_walls || scene.path.solver == PathSolver::kBreadthFirst;
  const std::vector<Cell> cells = use_bfs ? solve_breadth_first(grid) : solve_wall_follower(grid);
  const Polyline corners = reference_centreline(env, scene.maze, scene.path);
  const Trajectory trajectory(corners, scene.path.corner_radius, scene.path.speed, scene.path.ramp_time);

  json walls = json::array();
  for (const auto& w : env.walls)
    walls.push_back({{"from", point(w.a)}, {"to", point(w.b)}, {"thickness", w.thickness}});
  json doc;
  doc["format"] = "vascsim-maze/1";
  Scene as_run = scene;  // with the duration a run of it would use
  as_run.run.duration = scene.run.duration_for(trajectory.duration());
  doc["scene"] = json::parse(scene_to_json(as_run));
  doc["bounds"] = {point(env.bounds.min), point(env.bounds.max)};
  doc["lumen_width"] = env.lumen_width;
  doc["start"] = point(env.start);
  doc["goal"] = point(env.goal);
  doc["walls"] = walls;
  doc["grid"] = grid_json(grid, cells);
  doc["path"] = {{"solver", use_bfs ? "bfs" : "wall_follower"},
                 {"corners", polyline(corners)},
                 {"corner_radius", scene.path.corner_radius},
                 {"length", trajectory.length()},
                 {"speed", scene.path.speed},
                 {"ramp_time", scene.path.ramp_time},
                 {"duration", trajectory.duration()},
                 {"samples", polyline(trajectory.sample(1e-4))}};
  return doc.dump(1) + "\n";
}

}  // namespace

std::string maze_document(const Scene& scene) {
  try {
    return maze_document_unlabelled(scene);
  } catch (const InputError& e) {
    // The environment code knows the JSON path, not the file.
    throw InputError((scene.file.empty() ? std::string("built-in scene") : scene.file) + ": " + e.what());
  }
}

}  // namespace vascsim

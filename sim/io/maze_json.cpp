#include "sim/io/maze_json.h"

#include <nlohmann/json.hpp>

#include "sim/io/scene_reader.h"
#include "sim/io/scene_sections.h"
#include "sim/run/compile.h"
#include "sim/run/navigation.h"

namespace vascsim {

using nlohmann::json;

namespace {

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

}  // namespace

std::string maze_document(const Scene& scene) {
  // The maze as a run compiles it: generated and solved once, the same route and trajectory.
  const auto model = compile(scene);
  const Navigation& nav = *model->navigation;
  const Environment& env = nav.maze;
  const GridMaze& grid = nav.route.grid;
  const std::vector<Cell>& cells = nav.route.cells;
  const bool use_bfs = nav.route.breadth_first;
  const Polyline& corners = nav.route.corners;
  const Trajectory& trajectory = *nav.trajectory;

  json walls = json::array();
  for (const auto& w : env.walls)
    walls.push_back({{"from", io::to_json(w.a)}, {"to", io::to_json(w.b)}, {"thickness", w.thickness}});
  json doc;
  doc["format"] = "vascsim-maze/1";
  Scene as_run = scene;  // with the duration a run of it would use
  as_run.run.duration = model->scene.run.duration;
  doc["scene"] = json::parse(scene_to_json(as_run));
  doc["bounds"] = {io::to_json(env.bounds.min), io::to_json(env.bounds.max)};
  doc["lumen_width"] = env.lumen_width;
  doc["start"] = io::to_json(env.start);
  doc["goal"] = io::to_json(env.goal);
  doc["walls"] = walls;
  doc["grid"] = grid_json(grid, cells);
  doc["path"] = io::route_timing_json(scene.path, trajectory);
  doc["path"].update({{"solver", use_bfs ? "bfs" : "wall_follower"},
                      {"corners", io::to_json(corners)},
                      {"corner_radius", scene.path.corner_radius}});
  return doc.dump(1) + "\n";
}

}  // namespace vascsim

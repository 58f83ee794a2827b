#include <cstdio>
#include <string>
#include <vector>

#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "apps/vascsim/document_output.h"
#include "sim/io/maze_json.h"
#include "sim/io/scene_reader.h"

namespace vascsim::cli {

namespace {

const std::vector<OptionSpec> kOptions = {
    {"scene", "FILE", "read the maze and path settings from a scene file (default: built-in defaults)"},
    {"seed", "S", "maze generator seed (overrides the scene)"},
    {"rows", "R", "maze rows, 1..200 (overrides the scene)"},
    {"cols", "C", "maze columns, 1..200 (overrides the scene)"},
    {"lumen-width", "W", "channel width in m (overrides the scene): wider than the rod (2 x /rod/outer_radius), at most the cell pitch"},
    {"solver", "NAME", "wall_follower or bfs (overrides the scene)"},
    {"corner-radius", "R", "path corner rounding radius in m (overrides the scene)"},
    {"speed", "V", "tip reference speed in m/s, for the trajectory duration (overrides the scene)"},
    {"out", "FILE", "where to write the maze JSON, or - for standard output (required)"},
    {"force", "", "overwrite FILE if it exists"},
    {"help", "", "show this help"},
};

void print_usage() {
  std::printf(
      "usage: vascsim maze [--scene FILE] [--seed S --rows R --cols C ...] --out FILE [--force]\n\n"
      "Generates a random perfect maze (or reads explicit walls from the scene), solves it from start\n"
      "(top-right) to goal (bottom-left) and writes walls, cell path and reference centreline as JSON\n"
      "(format in docs/scenes.md).\n\noptions:\n%s",
      format_options(kOptions).c_str());
}

}  // namespace

int run_maze_command(int argc, char** argv) {
  Args args(argc, argv, 2, kOptions);
  if (args.flag("help")) {
    print_usage();
    return 0;
  }
  if (!args.positional().empty()) throw UsageError("unexpected argument '" + args.positional().front() + "'");
  const auto out = args.value("out");
  if (!out) throw UsageError("--out FILE is required");

  Scene scene = args.value("scene") ? read_scene_file(*args.value("scene")) : Scene{};
  if (!scene.has_environment) throw UsageError("scene " + scene.file + " has no maze (\"maze\": null)");
  if (scene.environment == EnvironmentKind::kVessels)
    throw UsageError("scene " + scene.file + " has vessels, not a maze (use vascsim vessels)");
  warn_unused_fields("maze", scene);
  MazeSpec& maze = scene.maze;
  const bool generator_option = args.value("seed") || args.value("rows") || args.value("cols") || args.value("lumen-width");
  if (maze.explicit_walls && generator_option)
    throw UsageError("--seed, --rows, --cols and --lumen-width apply to generated mazes; scene " + scene.file +
                     " lists explicit walls");
  maze.seed = static_cast<std::uint64_t>(args.integer("seed", static_cast<long long>(maze.seed), 0, 9007199254740991LL));
  maze.rows = static_cast<int>(args.integer("rows", maze.rows, 1, 200));
  maze.cols = static_cast<int>(args.integer("cols", maze.cols, 1, 200));
  if (maze.rows * maze.cols < 2)
    throw UsageError("--rows " + std::to_string(maze.rows) + " --cols " + std::to_string(maze.cols) +
                     ": a maze has at least 2 cells (its start and goal are different cells)");
  const double pitch = std::min(maze.width / maze.cols, maze.height / maze.rows);
  maze.lumen_width = std::min(maze.lumen_width, pitch);  // a finer grid narrows the default lumen to fit
  maze.lumen_width = args.number("lumen-width", maze.lumen_width, 1e-6, pitch);
  // Said of the option that made the lumen too narrow, not of the scene's /maze/lumen_width.
  if (generator_option && maze.lumen_width <= 2.0 * scene.rod.outer_radius) {
    char text[240];
    std::snprintf(text, sizeof text, "%s the lumen (%g mm) must be wider than the rod (%g mm across, /rod/outer_radius)",
                  args.value("lumen-width") ? "--lumen-width:" : "--rows/--cols: cells this small narrow the lumen, and",
                  1e3 * maze.lumen_width, 2e3 * scene.rod.outer_radius);
    throw UsageError(text);
  }
  if (auto s = args.value("solver")) {
    if (*s != "wall_follower" && *s != "bfs") throw UsageError("--solver: expected wall_follower or bfs, got '" + *s + "'");
    scene.path.solver = *s == "bfs" ? PathSolver::kBreadthFirst : PathSolver::kWallFollower;
  }
  scene.path.corner_radius = args.number("corner-radius", scene.path.corner_radius, 0.0, 1e3);
  scene.path.speed = args.number("speed", scene.path.speed, 1e-9, 1e3);

  // Never replace the scene it was made from, nor a device or pipe, even with --force.
  std::vector<std::string> inputs;
  if (!scene.file.empty()) inputs.push_back(scene.file);
  check_document_output(*out, args.flag("force"), inputs);
  if (!write_document_output(*out, maze_document(scene))) return 0;
  if (maze.explicit_walls)
    std::printf("wrote %s (%zu explicit walls)\n", out->c_str(), maze.walls.size());
  else
    std::printf("wrote %s (%d x %d maze, seed %llu)\n", out->c_str(), maze.rows, maze.cols,
                static_cast<unsigned long long>(maze.seed));
  return 0;
}

}  // namespace vascsim::cli

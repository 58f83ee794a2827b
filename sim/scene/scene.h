// The scene: an immutable description of one run (environment, rod, loads, solver, output), as
// plain structs. Every default of the scene file lives here, in the member initialisers, and
// docs/scenes.md lists them; a scene file only overrides them. The io layer fills these from
// JSON and validates ranges; the simulation compiles them into a Model and never changes them.
// All quantities are SI.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sim/env/geometry.h"

namespace vascsim {

// The vascular-mimicking environment: a generated perfect maze (paper II.A) or explicit walls.
struct MazeSpec {
  bool explicit_walls = false;  // true: `walls` below; false: generate rows x cols from `seed`
  int rows = 5;
  int cols = 5;
  double width = 1.0;          // m, x extent
  double height = 1.0;         // m, y extent
  double lumen_width = 0.1;    // m, channel width; wall thickness = cell pitch - lumen width
  std::uint64_t seed = 1;      // maze generator seed
  // Explicit environment (scenes/paper_maze.json): segments with a thickness, start and goal.
  std::vector<WallSegment> walls;
  Vec2 start = Vec2(0.9, 0.9);  // m, used with explicit walls; generated mazes use cell centres
  Vec2 goal = Vec2(0.1, 0.1);   // m
  double grid_pitch = 0.2;      // m, cell size of the explicit-walls path grid
};

enum class PathSolver { kWallFollower, kBreadthFirst };

// The ideal trajectory: lumen centreline from start to goal, traversed at constant speed.
struct PathSpec {
  PathSolver solver = PathSolver::kWallFollower;
  double corner_radius = 0.05;  // m, 0 keeps sharp 90-degree corners
  double speed = 0.05;          // m/s, tip reference speed along the path
};

// The robot: a hollow circular PDMS rod, paper Table I.
struct RodSpec {
  int nodes = 50;
  double length = 0.5;            // m
  double outer_radius = 2e-3;     // m
  double inner_radius = 1e-3;     // m
  double youngs_modulus = 1.47e6; // Pa
  double poisson_ratio = 0.48;    // -, for the shear modulus G = E / (2 (1 + nu)) (0.497 MPa)
  double density = 980.0;         // kg/m^3
};

// Output of a run.
struct RunSpec {
  double duration = 10.0;         // s, simulated time
  double output_interval = 0.01;  // s, time between logged frames
};

struct Scene {
  std::string file;  // where it was read from, for messages; empty for built-in scenes
  std::string name = "scene";
  bool has_maze = true;  // false for scenes in free space ("maze": null), e.g. validation problems
  MazeSpec maze;
  PathSpec path;
  RodSpec rod;
  RunSpec run;
};

}  // namespace vascsim

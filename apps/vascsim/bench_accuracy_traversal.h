// The maze traversals of `vascsim bench accuracy` (issue 16): whole 48 s runs of the shipped
// scenes at fixed steps, at the presets and under error control without a floor, each against a
// reference run of the same scene. On maze_body_drag (a damped body) the error is the largest
// distance of any node from the reference over every frame, which converges; on maze_default (an
// undamped body bouncing on the walls) that distance does not converge at any setting, so the
// table also gives what is predictable there: goal time, tip error RMS and max, contact force.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "sim/scene/scene.h"

namespace vascsim::cli {

struct TraversalRow {
  std::string scene;            // the scene's name
  std::string stepping;         // "fixed 1e-3", "preset balanced", "error 1e-4", "reference"
  bool fixed = false;           // a fixed-step run (for the comparison against error control)
  double mean_dt = 0.0;         // s
  int steps = 0;
  double newton_per_step = 0.0;
  double wall_time = 0.0;       // s, the run alone (frames kept in memory, none written)
  double real_time = 0.0;       // simulated time / wall time
  double body_deviation = 0.0;  // m, the largest node distance from the reference over all frames
  double goal_time = 0.0;       // s (NaN: not reached)
  double tip_rms = 0.0, tip_max = 0.0;  // m
  double contact_force_max = 0.0;       // N
  int steps_over_tolerance = 0;
  bool ok = true;
};

// Runs the traversals of `scene` (read from a file) and returns them, reference last. The
// reference runs first, so `progress` is called with each row as soon as it has run.
std::vector<TraversalRow> traversal_rows(const Scene& scene, const std::function<void(const TraversalRow&)>& progress);

// The mean over several mazes of each setting's rows (rows_by_maze[k]: traversal_rows of maze k,
// in the same order): body deviation, steps, Newton iterations per step, tip error and goal time
// averaged, wall time summed over the mazes. One maze's worst deviation swings by 2-3x with any
// change to the steps; their mean ranks settings (docs/accuracy.md, "Presets").
std::vector<TraversalRow> mean_over_mazes(const std::vector<std::vector<TraversalRow>>& rows_by_maze);

void print_traversal_header();
void print_traversal_row(const TraversalRow& r);
// The Pareto front (body deviation against wall time) and, for every error-controlled run, the
// fastest fixed step with equal or smaller deviation and the wall time of a fixed step of equal
// deviation, interpolated along the fixed steps' front.
void print_traversal_comparison(const std::vector<TraversalRow>& rows);

}  // namespace vascsim::cli

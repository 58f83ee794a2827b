// Synthetic frame logs for the renderer's tests and benchmark, independent of the simulator:
// a serpentine maze of n x n cells built from per-cell wall segments, a rod sliding along the
// centre line with a gentle S-shaped wiggle, a known actuation force on the tip (along the path
// tangent) and known contact forces on chosen nodes (along the path normal).
#pragma once

#include <string>
#include <vector>

#include "sim/io/log_metadata.h"

namespace vascsim::render {

struct SyntheticLogSpec {
  int grid = 5;                  // cells per side
  double cell = 0.01;            // m, cell size (lumen width)
  double wall_thickness = 0.0;   // m
  int nodes = 40;                // rod nodes
  double rod_length = 0.025;     // m
  double rod_radius = 0.0005;    // m
  int frames = 10;
  double duration = 1.0;         // s, time of the last frame
  double speed = 0.02;           // m/s, tip speed along the path
  double actuation = 2e-3;       // N, magnitude of the tip force
  double contact = 1e-3;         // N, magnitude of each contact force
  std::vector<int> contact_nodes = {10, 20};  // node indices (0 = base) that touch a wall
  bool forces = true;            // write force/actuation and force/contact
  bool reference = true;         // write tip/reference and tip/error
  // Write force/friction (along the rod at the contact nodes, half the contact force) and
  // force/drag (against the motion at the tip, a tenth of the tip force: a tip-only drag).
  bool friction_and_drag = false;
  // Write feed/force and feed/length (control.advance): the root fed at `speed`, the drive's push
  // rising linearly from 0 to `feed_force` at the last frame.
  bool feed = false;
  double feed_force = 5e-3;      // N
  std::string title = "synthetic serpentine maze";
};

// The metadata (walls, path, start, goal, rod) the spec describes.
LogMetadata synthetic_metadata(const SyntheticLogSpec& spec);
// Writes the log to `path`. Throws InputError if the file cannot be written.
void write_synthetic_log(const std::string& path, const SyntheticLogSpec& spec);
// The same with other metadata (a vessel lumen, say): the rod slides along `metadata.path` (the
// spec's serpentine if it has fewer than 2 points), with the spec's rod, frames, speed and forces
// (its cell sets the wiggle).
void write_synthetic_log(const std::string& path, const SyntheticLogSpec& spec, const LogMetadata& metadata);

}  // namespace vascsim::render

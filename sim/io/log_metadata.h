// The metadata a frame log carries so that a renderer or a replay needs nothing but the log:
// the scene as canonical JSON, and the resolved geometry (walls, reference path, start, goal,
// rod size). Stored as JSON text in FrameLogHeader::metadata; see docs/frame-log.md.
#pragma once

#include <string>
#include <vector>

#include "sim/env/geometry.h"
#include "sim/log/channel_names.h"
#include "sim/scene/scene.h"

namespace vascsim {

struct LogMetadata {
  std::string title;                // shown in the video HUD, e.g. the scene name
  std::string scene_json;           // canonical scene (scene_to_json); empty for synthetic logs
  Box2 bounds;                      // m, the environment's extent
  std::vector<WallSegment> walls;   // m
  double lumen_width = 0.0;         // m, nominal channel width (0 if not applicable)
  // m, closed rings whose even-odd interior is the lumen (Environment::lumen); empty in older
  // logs, where the bounds rectangle is drawn as the lumen.
  std::vector<Polyline> lumen;
  Polyline path;                    // m, reference tip path, densely sampled where it curves
  Vec2 start = Vec2::Zero();        // m
  Vec2 goal = Vec2::Zero();         // m
  double rod_outer_radius = 0.0;    // m
  double rod_length = 0.0;          // m
  double output_interval = 0.0;     // s, nominal time between frames
  // How the rod is held: the scene's boundary, node indices resolved to 0..N-1, so pictures can
  // draw the clamp, pins and supports. Empty for a rod held by nothing (every maze and vessel
  // scene) and in logs written before it was recorded.
  BoundarySpec boundary;
  // Provenance (sim/io/provenance.h): empty in logs written before it was recorded.
  std::string vascsim_version, commit, scene_hash;
};

std::string write_log_metadata(const LogMetadata& metadata);
// Throws InputError naming `label` (usually the log's path) if the text is not valid metadata.
LogMetadata read_log_metadata(const std::string& text, const std::string& label);
// Whether two logs ran in the same environment (bounds, walls and lumen equal), so that one run's
// rod drawn over the other's map means something.
bool same_environment(const LogMetadata& a, const LogMetadata& b);


}  // namespace vascsim

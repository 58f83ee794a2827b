// The metadata a frame log carries so that a renderer or a replay needs nothing but the log:
// the scene as canonical JSON, and the resolved geometry (walls, reference path, start, goal,
// rod size). Stored as JSON text in FrameLogHeader::metadata; see docs/frame-log.md.
#pragma once

#include <string>
#include <vector>

#include "sim/env/geometry.h"

namespace vascsim {

struct LogMetadata {
  std::string title;                // shown in the video HUD, e.g. the scene name
  std::string scene_json;           // canonical scene (scene_to_json); empty for synthetic logs
  Box2 bounds;                      // m, the environment's extent
  std::vector<WallSegment> walls;   // m
  double lumen_width = 0.0;         // m, nominal channel width (0 if not applicable)
  Polyline path;                    // m, reference tip path, densely sampled where it curves
  Vec2 start = Vec2::Zero();        // m
  Vec2 goal = Vec2::Zero();         // m
  double rod_outer_radius = 0.0;    // m
  double rod_length = 0.0;          // m
  double output_interval = 0.0;     // s, nominal time between frames
};

std::string write_log_metadata(const LogMetadata& metadata);
// Throws InputError naming `label` (usually the log's path) if the text is not valid metadata.
LogMetadata read_log_metadata(const std::string& text, const std::string& label);

// Names of the standard frame log channels (docs/frame-log.md). A log holds only the channels
// its scene produces; readers must treat every channel but position as optional.
namespace channel {
inline constexpr const char* kPosition = "position";              // node vectors, m
inline constexpr const char* kVelocity = "velocity";              // node vectors, m/s
inline constexpr const char* kActuationForce = "force/actuation"; // node vectors, N (magnetic force)
inline constexpr const char* kContactForce = "force/contact";     // node vectors, N (wall normal force)
inline constexpr const char* kFrictionForce = "force/friction";   // node vectors, N
inline constexpr const char* kDragForce = "force/drag";           // node vectors, N
inline constexpr const char* kExternalForce = "force/external";   // node vectors, N (point loads, gravity)
inline constexpr const char* kTipReference = "tip/reference";     // vector, m (controller's target)
inline constexpr const char* kTipError = "tip/error";             // scalar, m (|tip - reference|)
}  // namespace channel

}  // namespace vascsim

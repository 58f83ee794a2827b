// Reads and validates scene files (JSON, documented in docs/scenes.md) into a Scene.
// Every error is an InputError naming the file, the JSON pointer and what was expected.
#pragma once

#include <cstddef>
#include <string>

#include "sim/scene/scene.h"

namespace vascsim {

// The largest scene file read (a scene is a few kilobytes; explicit walls of a big network a few
// megabytes).
inline constexpr std::size_t kMaxSceneBytes = std::size_t(16) << 20;
// Reads `path`. Throws InputError if the file is missing, not a regular file, larger than
// kMaxSceneBytes, not JSON, or any value is invalid.
Scene read_scene_file(const std::string& path);
// Parses scene JSON text; `label` names the source in messages.
Scene read_scene_text(const std::string& text, const std::string& label);
// The scene as canonical JSON text with every default filled in (stored in frame logs and
// summaries so that a run can be reproduced from its outputs alone), leaving out the fields its
// configuration does not use.
std::string scene_to_json(const Scene& scene);
// As scene_to_json, but with the fields the scene's configuration does not use as well
// (sim/scene/unused_fields.h): every field a file of this scene may set (what a sweep checks
// its axes against).
std::string scene_fields_json(const Scene& scene);

}  // namespace vascsim

// The `vascsim maze` output: a generated or explicit environment, its solution and reference
// trajectory as one JSON document (format "vascsim-maze/1", documented in docs/scenes.md).
#pragma once

#include <string>

#include "sim/scene/scene.h"

namespace vascsim {

// Builds the environment of `scene`, solves it and returns the document text. Deterministic:
// the same scene gives the same bytes. Throws InputError if start and goal are not connected.
std::string maze_document(const Scene& scene);

}  // namespace vascsim

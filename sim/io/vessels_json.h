// The `vascsim vessels` output: a vessel network as a run compiles it (lumen outline, walls, graph
// or mask, route, reference trajectory) as one JSON document (format "vascsim-vessels/1",
// documented in docs/environment.md), the vessel counterpart of maze_json.h.
#pragma once

#include <string>

#include "sim/scene/scene.h"

namespace vascsim {

// Compiles the vessel scene and returns the document text. Deterministic: the same scene (and
// mask image) gives the same bytes. Throws InputError for a scene the compile step refuses.
std::string vessels_document(const Scene& scene);

}  // namespace vascsim

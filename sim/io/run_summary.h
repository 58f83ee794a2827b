// DIR/summary.json of `vascsim run`: what a run did, in numbers (format in docs/frame-log.md).
#pragma once

#include <string>

#include "sim/run/run.h"

namespace vascsim {

std::string run_summary_json(const Scene& scene, const Run& run);

}  // namespace vascsim

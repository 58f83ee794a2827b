// DIR/summary.json of `vascsim run`: what a run did, in numbers (format in docs/frame-log.md).
#pragma once

#include <string>

#include "sim/run/run.h"

namespace vascsim {

std::string run_summary_json(const Scene& scene, const Run& run);

// For a run directory with summary.json: throws InputError if its frame log holds another number
// of frames (`log_frames`) than the summary gives, i.e. the log was cut or appended to after the
// run ended (a copy cut short, a log concatenated onto it), which would otherwise be drawn or
// exported silently shorter or with a frame of garbage. A log file named directly, a run without
// a summary (stopped or still running) or a summary without a frame count is not checked.
// Also throws if both name a scene hash (provenance) and they differ: the summary is another
// run's (copied beside this log, or left by a run of another scene with as many frames).
void check_log_matches_summary(const std::string& run_path, std::size_t log_frames, const std::string& log_scene_hash);

}  // namespace vascsim

// DIR/summary.json of `vascsim run`: what a run did, in numbers (format in docs/frame-log.md).
#pragma once

#include <string>

#include "sim/run/run.h"

namespace vascsim {

std::string run_summary_json(const Scene& scene, const Run& run);

// For a run directory with summary.json (`run_path` names the directory or its frames.vlog):
// throws InputError if its frame log holds another number of frames (`log_frames`) than the
// summary gives, i.e. the log was cut or appended to after the run ended (a copy cut short, a log
// concatenated onto it), which would otherwise be drawn or exported silently shorter or with a
// frame of garbage. Also throws if both name a scene hash (provenance) and they differ: the
// summary is another run's (copied beside this log, or left by a run of another scene with as
// many frames). Returns a warning when the summary cannot be read or has no frame count (damaged,
// hand-written, another version's), so the log could not be checked against it; empty otherwise,
// and for a run without a summary (stopped or still running) or a log copied out of its run.
[[nodiscard]] std::string check_log_matches_summary(const std::string& run_path, std::size_t log_frames, const std::string& log_scene_hash);

// For a run directory whose summary.json says the run failed: a warning that names its failure,
// for what is made from its log (a video, a still, a CSV) ends with the last frame before it and
// does not say so itself. Empty for a run that did not fail, has no summary, or whose summary
// cannot be read (check_log_matches_summary warns of that).
[[nodiscard]] std::string failed_run_warning(const std::string& run_path);

}  // namespace vascsim

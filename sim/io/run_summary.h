// DIR/summary.json of `vascsim run`: what a run did, in numbers (format in docs/frame-log.md).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "sim/run/run.h"

namespace vascsim {

std::string run_summary_json(const Scene& scene, const Run& run);

// DIR/summary.json, parsed: none when the directory has none (a run still writing, or killed);
// throws InputError naming the file when it cannot be read, holds more than 64 MB or is not
// JSON. The one reader of summaries for the replay, sweeps and the log check; the content is
// the caller's to check. (`vascsim run` writes it atomically: complete or absent.)
std::optional<nlohmann::json> read_run_summary(const std::string& run_dir);

// For a run directory with summary.json: throws InputError if its frame log holds another number
// of frames (`log_frames`) than the summary gives, i.e. the log was cut or appended to after the
// run ended (a copy cut short, a log concatenated onto it), which would otherwise be drawn or
// exported silently shorter or with a frame of garbage. A log file named directly, a run without
// a summary (stopped or still running) or a summary without a frame count is not checked.
void check_log_matches_summary(const std::string& run_path, std::size_t log_frames);

}  // namespace vascsim

// DIR/summary.json of `vascsim run`: what a run did, in numbers (format in docs/frame-log.md).
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "sim/run/run.h"

namespace vascsim {

std::string run_summary_json(const Scene& scene, const Run& run);

// What check_log_against_run found: the warnings, each a line, and whether the run failed.
struct LogRunCheck {
  std::vector<std::string> warnings;
  // The summary says the run failed (/ok false); pictures of the run say so.
  bool failed = false;
  // The time a failed run had reached (s, the summary's /simulated_time); NaN where it gives
  // none that is finite and >= 0 (a hand-edited summary).
  double failed_at = std::numeric_limits<double>::quiet_NaN();
};

// What a reader of a run's log (`run_path`: the run directory, or a log file) must know of its
// run, from the run directory's summary.json, read once. Throws InputError if the log holds
// another number of frames (`log_frames`) than the summary gives, i.e. the log was cut or
// appended to after the run ended (a copy cut short, a log concatenated onto it), which would
// otherwise be drawn or exported silently shorter or with a frame of garbage; or if both name a
// scene hash (provenance) and they differ: the summary is another run's (copied beside this log,
// or left by a run of another scene with as many frames). Returns warnings, each a line: the run
// directory has no summary (the run stopped or is still writing, so its log may end early); the
// summary cannot be read or has no frame count (damaged, hand-written, another version's), so the
// log was not checked against it; the run failed (what is made from its log ends with the last
// frame before the failure). None for a log copied out of its run.
[[nodiscard]] LogRunCheck check_log_against_run(const std::string& run_path, std::size_t log_frames,
                                               const std::string& log_scene_hash);

}  // namespace vascsim

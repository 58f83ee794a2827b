// Whether a run's frame log can be used as it stands, from the run directory's summary.json: the
// one check `vascsim render`, `export` and `replay` make before drawing or exporting a log, and
// how the run ended when it ended early (its pictures say so).
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace vascsim {

// A run that ended before its duration: as its summary says (/ok false), or killed before it
// could write one.
struct EarlyEnd {
  enum class How {
    kFailed,   // the simulation failed (/failure says how)
    kStopped,  // a signal asked it to stop (Ctrl-C, kill, a scheduler's time limit: /stopped_by)
    kKilled,   // killed without a summary (kill -9, a crash): its claim on the directory was left
  };
  // s, the time it had reached (/simulated_time); NaN where no summary gives one that is finite
  // and >= 0 (a killed run's, a hand-edited summary's).
  double at = std::numeric_limits<double>::quiet_NaN();
  How how = How::kFailed;
};
// "failed", "stopped" or "killed", as pictures and warnings say it.
const char* verb(EarlyEnd::How how);

// What check_log_against_run found: the warnings, each a line, and whether the run ended early.
struct LogRunCheck {
  std::vector<std::string> warnings;
  // Pictures of a run that failed or was stopped say so.
  std::optional<EarlyEnd> ended_early;
};

// What a reader of a run's log (`run_path`: the run directory, or a log file) must know of its
// run, from the run directory's summary.json, read once. Throws InputError if the log holds
// another number of frames (`log_frames`) than the summary gives, i.e. the log was cut or
// appended to after the run ended (a copy cut short, a log concatenated onto it), which would
// otherwise be drawn or exported silently shorter or with a frame of garbage; or if both name a
// scene hash (provenance) and they differ: the summary is another run's (copied beside this log,
// or left by a run of another scene with as many frames). Returns warnings, each a line: the run
// directory has no summary (the run is still writing, or was killed, so its log may end early); the
// summary cannot be read or has no frame count (damaged, hand-written, another version's), so the
// log was not checked against it; the run failed, was stopped or was killed (what is made from
// its log ends with the last frame before that). None for a log copied out of its run.
[[nodiscard]] LogRunCheck check_log_against_run(const std::string& run_path, std::size_t log_frames,
                                               const std::string& log_scene_hash);

}  // namespace vascsim

// Reading a run directory's summary.json back: the one reader of summaries for the replay,
// sweeps and the frame log's check against its summary. Not part of the installed API (it would
// expose nlohmann-json, a private dependency); run_summary.h writes them.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace vascsim {

// DIR/summary.json, parsed: none when the directory has none (a run still writing, or killed);
// throws InputError naming the file when it cannot be read, holds more than 64 MB or is not
// JSON. The content is the caller's to check. (`vascsim run` writes it atomically: complete or
// absent.)
std::optional<nlohmann::json> read_run_summary(const std::string& run_dir);

// Whether a summary says a signal stopped its run (/stopped_by a non-empty string) rather than
// the simulation failing: the one test the log check, the sweep and the replay's timeline make.
bool summary_says_stopped(const nlohmann::json& summary);

}  // namespace vascsim

#include "sim/io/log_run_check.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "sim/io/output_file.h"
#include "sim/io/run_summary_reader.h"
#include "sim/log/frame_log.h"
#include "sim/scene/input_error.h"

namespace vascsim {

using nlohmann::json;

namespace {

// For a summary saying its run failed or was stopped: what is made from the log (a video, a
// still, a CSV) ends with the last frame before that.
std::string early_end_warning(const json& summary, const std::string& summary_path, bool stopped) {
  const auto failure = summary.find("failure");
  return "warning: " + summary_path + (stopped ? ": the run was stopped before its end (" : ": the run failed (") +
         (failure != summary.end() && failure->is_string() ? failure->get<std::string>() : "no /failure given") +
         "); its log ends with the last frame before " + (stopped ? "it stopped" : "the failure");
}

// For a run directory without summary.json (written last, when a run ends, whether it reached
// its end, failed or was stopped): a warning whether a run is still writing it or was killed,
// from the run's claim on the directory, and a killed run's early end.
void check_run_without_summary(const std::string& dir, LogRunCheck& check) {
  const std::string lead = "warning: " + dir + " has no summary.json";
  switch (RunDirectoryClaim::holder(dir)) {
    case RunDirectoryClaim::Holder::kRun:
      check.warnings.push_back(lead + " yet: a run is still writing it, so its log ends with the frames written so far");
      return;
    case RunDirectoryClaim::Holder::kAbandoned:
      check.warnings.push_back(lead + ": its run was killed before its end (kill -9, a crash, the machine out of memory: it "
                                      "left its claim on the directory, which no run holds); its log ends with the last frame it wrote");
      check.ended_early = EarlyEnd{std::numeric_limits<double>::quiet_NaN(), EarlyEnd::How::kKilled};
      return;
    case RunDirectoryClaim::Holder::kNoClaim:
      check.warnings.push_back(lead + ": no run is writing it (the directory was copied without it, or its run was killed), "
                                      "so its log may end early");
      return;
    case RunDirectoryClaim::Holder::kUnknown:
      check.warnings.push_back(lead + ": the run was killed (kill -9, a crash) or is still being written, so its log may end early");
      return;
  }
}

}  // namespace

const char* verb(EarlyEnd::How how) {
  switch (how) {
    case EarlyEnd::How::kFailed: return "failed";
    case EarlyEnd::How::kStopped: return "stopped";
    case EarlyEnd::How::kKilled: return "killed";
  }
  return "failed";
}

LogRunCheck check_log_against_run(const std::string& run_path, std::size_t log_frames,
                                  const std::string& log_scene_hash) {
  namespace fs = std::filesystem;
  LogRunCheck check;
  const auto warn = [&](const std::string& warning) {
    if (!warning.empty()) check.warnings.push_back(warning);
  };
  const std::string run_dir = run_dir_of(run_path);
  if (run_dir.empty()) return check;
  const fs::path log_path = fs::path(run_dir) / "frames.vlog", summary_path = fs::path(run_dir) / "summary.json";
  std::error_code ec;
  if (!fs::exists(summary_path, ec)) {
    check_run_without_summary(run_dir, check);
    return check;
  }
  const std::string not_checked = ", so " + log_path.string() + " was not checked against it (its own checks still apply)";
  std::optional<json> summary;
  try {
    summary = read_run_summary(run_dir);
  } catch (const InputError& e) {
    warn(std::string("warning: ") + e.what() + not_checked);
    return check;
  }
  if (!summary) return check;
  if (!summary->is_object()) {
    warn("warning: " + summary_path.string() + ": not a JSON object" + not_checked);
    return check;
  }
  const json::json_pointer hash_pointer("/provenance/scene_hash");
  if (summary->contains(hash_pointer) && (*summary)[hash_pointer].is_string()) {
    const auto summary_hash = (*summary)[hash_pointer].get<std::string>();
    if (!summary_hash.empty() && !log_scene_hash.empty() && summary_hash != log_scene_hash)
      throw InputError(summary_path.string() + ": /provenance/scene_hash is " + summary_hash + ", but " + log_path.string() +
                       " was written by a run of the scene with hash " + log_scene_hash +
                       ": the summary is another run's (run the scene again, or copy the run directory whole)");
  }
  const json* frames = summary->contains("frames") ? &(*summary)["frames"] : nullptr;
  if (!frames || !frames->is_number_unsigned())
    warn("warning: " + summary_path.string() + ": no /frames count (not a summary vascsim wrote)" + not_checked);
  else if (frames->get<std::uint64_t>() != log_frames)
    throw InputError(log_path.string() + ": " + std::to_string(log_frames) + " frames, but " + summary_path.string() +
                     " says the run wrote " + std::to_string(frames->get<std::uint64_t>()) +
                     ": the log was cut or appended to after the run ended (run it again, or copy it again)");
  const auto ok = summary->find("ok");
  if (ok != summary->end() && ok->is_boolean() && !ok->get<bool>()) {
    EarlyEnd end;
    const bool stopped = summary_says_stopped(*summary);
    end.how = stopped ? EarlyEnd::How::kStopped : EarlyEnd::How::kFailed;
    const auto reached = summary->find("simulated_time");
    if (reached != summary->end() && reached->is_number() && reached->get<double>() >= 0.0) end.at = reached->get<double>();
    warn(early_end_warning(*summary, summary_path.string(), stopped));
    check.ended_early = end;
  }
  return check;
}

}  // namespace vascsim

#include "sim/io/sweep_outcome.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "sim/io/json_fields.h"
#include "sim/io/run_summary_reader.h"
#include "sim/scene/input_error.h"

namespace vascsim {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Reads a regular file of at most `limit` bytes (a larger one is read as its first `limit`
// bytes, which then fail to parse: a message, not an allocation of whatever size it claims).
bool read_small_file(const fs::path& path, std::string& text, std::size_t limit) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return false;
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  const std::uintmax_t size = fs::file_size(path, ec);
  text.assign(static_cast<std::size_t>(std::min<std::uintmax_t>(ec ? 0 : size, limit)), '\0');
  f.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(f.gcount()));
  return true;
}

double number_at(const json& j, const char* pointer) {
  const json::json_pointer p(pointer);
  if (!j.contains(p)) return kNaN;
  const json& v = j.at(p);
  if (v.is_boolean()) return v.get<bool>() ? 1.0 : 0.0;
  return v.is_number() ? v.get<double>() : kNaN;
}

// The last non-empty line the process wrote (its error message), at most 300 characters.
std::string last_line(const fs::path& log) {
  std::string text;
  if (!read_small_file(log, text, 1 << 20)) return "";
  std::istringstream lines(text);
  std::string line, last;
  while (std::getline(lines, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  if (last.size() > 300) last = io::utf8_prefix(last, 297) + "...";
  return last;
}

void read_summary(const json& s, const std::string& label, RunOutcome& out) {
  if (!s.is_object() || s.value("format", json()) != "vascsim-summary/1")
    throw InputError(label + ": /format: expected \"vascsim-summary/1\"");
  if (!s.contains("ok") || !s["ok"].is_boolean()) throw InputError(label + ": /ok: expected true or false");
  out.status = s["ok"].get<bool>() ? "done" : "failed";
  if (!s["ok"].get<bool>()) {
    const json failure = s.value("failure", json());
    out.failure = failure.is_string() ? failure.get<std::string>() : "the simulation failed (no reason recorded)";
  }
  static const char* const pointers[kMetricCount] = {
      "/navigation/goal_reached",        "/navigation/goal_time",         "/navigation/tip_error_rms",
      "/navigation/tip_error_max",       "/navigation/actuation_force_max", "/navigation/contact_force_max",
      "/navigation/advance/feed_force_max", "/navigation/max_penetration", "/steps",
      "/newton_iterations/total",        "/rejected_steps"};
  for (std::size_t k = 0; k < kMetricCount; ++k) out.metrics[k] = number_at(s, pointers[k]);
  const json::json_pointer mode("/navigation/control_mode");
  if (s.contains(mode) && s.at(mode).is_string()) out.control_mode = s.at(mode).get<std::string>();
  // A rod only pushed from its root has no tip error: summaries written before they said so
  // (null) carry the distance to a target that nothing steered towards.
  if (out.control_mode == "none") out.metrics[kTipErrorRms] = out.metrics[kTipErrorMax] = kNaN;
  const double wall = number_at(s, "/wall_time"), rtf = number_at(s, "/real_time_factor");
  out.wall_time = std::isfinite(wall) ? wall : -1;
  out.real_time_factor = std::isfinite(rtf) ? rtf : -1;
}

void read_status(const std::string& text, const std::string& label, RunStatusRecord& out) {
  const json s = io::parse_json_strictly(text, label);
  if (!s.is_object() || s.value("format", json()) != "vascsim-sweep-status/1")
    throw InputError(label + ": /format: expected \"vascsim-sweep-status/1\"");
  const auto integer = [&](const char* key) {
    const json v = s.value(key, json());
    return v.is_number_integer() ? v.get<int>() : -1;
  };
  out.exit_code = integer("exit_code");
  out.signal = std::max(0, integer("signal"));
  out.wall_time = std::max(0.0, number_at(s, "/wall_time"));
  out.cpu_time = std::max(0.0, number_at(s, "/cpu_time"));
  const json host = s.value("host", json());
  out.host = host.is_string() ? host.get<std::string>() : "";
}

}  // namespace

const std::vector<SweepMetric>& sweep_metrics() {
  static const std::vector<SweepMetric> metrics = {
      {"goal_reached", "goal reached", "", 1.0, true},
      {"goal_time_s", "goal time", "s", 1.0},
      {"tip_error_rms_m", "tip error RMS", "mm", 1e3},
      {"tip_error_max_m", "tip error max", "mm", 1e3},
      {"actuation_force_max_N", "actuation force max", "mN", 1e3},
      {"contact_force_max_N", "contact force max", "mN", 1e3},
      {"feed_force_max_N", "feed force max", "mN", 1e3},
      {"max_penetration_m", "max penetration", "mm", 1e3},
      {"steps", "steps", "", 1.0, true},
      {"newton_iterations", "Newton iterations", "", 1.0, true},
      {"rejected_steps", "rejected steps", "", 1.0, true},
  };
  return metrics;
}

RunOutcome read_run_outcome(const std::string& run_dir) {
  RunOutcome out;
  out.metrics.assign(kMetricCount, kNaN);
  const fs::path dir(run_dir);
  std::string text;
  if (read_small_file(dir / "status.json", text, 1 << 16)) {
    try {
      read_status(text, (dir / "status.json").string(), out.process);
      out.has_status = true;
    } catch (const InputError&) {
      // A status that cannot be read says nothing; the summary or its absence decides.
    }
  }
  try {
    if (const std::optional<json> summary = read_run_summary(run_dir)) {
      read_summary(*summary, (dir / "summary.json").string(), out);
      // Stopped by a signal the sweep did not see (its own Ctrl-C, a scheduler's SIGTERM to the
      // whole job, the kernel's after the sweep was killed): not run to its end, so run again.
      if (!out.has_status && summary_says_stopped(*summary)) {
        out.status = "missing";
        out.failure.clear();
        out.metrics.assign(kMetricCount, kNaN);
        out.wall_time = out.real_time_factor = -1;
      }
      return out;
    }
  } catch (const InputError& e) {
    out = RunOutcome{};
    out.metrics.assign(kMetricCount, kNaN);
    out.status = "failed";
    out.failure = std::string("unreadable summary: ") + e.what();
    return out;
  }
  if (!out.has_status) return out;  // missing
  out.status = "failed";
  const RunStatusRecord& p = out.process;
  const std::string message = last_line(dir / "run.log");
  if (p.signal > 0)
    out.failure = "vascsim run was killed by signal " + std::to_string(p.signal) + " (" + strsignal(p.signal) + ")";
  else if (p.exit_code != 0)
    out.failure = "vascsim run exited with code " + std::to_string(p.exit_code) + (message.empty() ? "" : ": " + message);
  else
    out.failure = "vascsim run exited without writing summary.json";
  return out;
}

std::string run_status_json(const RunStatusRecord& s) {
  json j;
  j["format"] = "vascsim-sweep-status/1";
  j["exit_code"] = s.signal > 0 ? json(nullptr) : json(s.exit_code);
  j["signal"] = s.signal > 0 ? json(s.signal) : json(nullptr);
  j["wall_time"] = s.wall_time;
  j["cpu_time"] = s.cpu_time;
  j["host"] = s.host;
  return j.dump(2) + "\n";
}

}  // namespace vascsim

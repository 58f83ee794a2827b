#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "apps/vascsim/cli_args.h"
#include "apps/vascsim/commands.h"
#include "apps/vascsim/stop_on_signal.h"
#include "sim/io/output_file.h"
#include "sim/io/run_files.h"
#include "sim/io/run_log.h"
#include "sim/io/run_summary.h"
#include "sim/io/run_warnings.h"
#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/run/run.h"
#include "sim/scene/input_error.h"
#ifdef VASCSIM_HAVE_RENDER
#include "render/render_run.h"
#endif

namespace vascsim::cli {

namespace {

namespace fs = std::filesystem;

// Two decimals from a second up ("48.00"), three significant digits below: a run of a millisecond
// read "0.00 s simulated in 0.00 s", and a slow one "(0.0x real time)".
std::string short_number(double x, const char* from_one = "%.2f") {
  char text[32];
  std::snprintf(text, sizeof text, std::fabs(x) >= 1 ? from_one : "%.3g", x);
  return text;
}

// A measured time likewise, in decimals with its zeros ("0.200", "0.0000123"; %g gave "0.2").
std::string measured_seconds(double x) {
  if (!(x > 0) || x >= 1) return short_number(x);
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", std::min(12, 2 - static_cast<int>(std::floor(std::log10(x)))), x);
  return text;
}

const std::vector<OptionSpec> kOptions = {
    {"out", "DIR", "run directory: DIR/frames.vlog (frame log), DIR/summary.json (required)"},
    {"force", "", "reuse DIR even if it holds files (they are replaced)"},
    {"duration", "T", "simulated time in s (overrides the scene's run.duration)"},
    {"quiet", "", "no progress line"},
    {"max-log-size", "BYTES", "refuse a run whose frame log would exceed this (default 10G; suffixes k or K, M, G)"},
    {"render", "", "render DIR/video.mp4 when the run ends (see vascsim render --help)"},
    {"help", "", "show this help"},
};

void print_usage() {
  std::printf(
      "usage: vascsim run SCENE --out DIR [--force] [--duration T] [--quiet] [--render] [--max-log-size BYTES]\n\n"
      "Simulates the scene and streams every frame to DIR/frames.vlog (format in docs/frame-log.md);\n"
      "writes DIR/summary.json when the run ends or fails. Exit code 1 if the simulation failed\n"
      "(every frame computed before the failure is kept), 2 for bad input. Ctrl-C, SIGTERM or SIGHUP\n"
      "stop it after the step in progress: its summary says so, and it then ends by that signal\n"
      "(a second Ctrl-C ends it at once).\n\noptions:\n%s",
      format_options(kOptions).c_str());
}

// Progress on a terminal only, refreshed at most 10 times a second, shown after the first second.
class Progress {
 public:
  Progress(bool enabled, double duration) : enabled_(enabled && ::isatty(STDERR_FILENO)), duration_(duration) {}
  void update(double t) {
    if (!enabled_) return;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    if (elapsed < 1.0 || elapsed - last_ < 0.1) return;
    last_ = elapsed;
    const double fraction = std::min(t / duration_, 1.0);
    const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    std::fprintf(stderr, "\r  t = %.2f / %.2f s  %3.0f%%  elapsed %.1f s  ETA %.1f s   ", t, duration_, 100 * fraction,
                 elapsed, eta);
    shown_ = true;
  }
  void finish() {
    if (shown_) std::fprintf(stderr, "\n");
  }

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  double duration_;
  Clock::time_point start_ = Clock::now();
  double last_ = 0.0;
  bool shown_ = false;
};

// A forced run first removes what a previous run wrote here, so the directory never mixes two
// runs (an old summary beside a new partial log, an old video beside a new log). The user's
// files (bookmarks, exports, anything else) stay, and the user is told which of them describe
// the earlier run: bookmarks name its times, exports show it.
void remove_run_outputs(const std::string& dir) {
  std::error_code ec;
  for (const char* name : {"summary.json", "frames.vlog", "video.mp4", "video.webm"}) fs::remove(fs::path(dir) / name, ec);
  for (const char* name : kRunPlotFiles) fs::remove(fs::path(dir) / "plots" / name, ec);
  fs::remove(fs::path(dir) / "plots" / kFeedPlotFile, ec);
  std::vector<std::string> kept;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name == "bookmarks.json" || (name.rfind("export-", 0) == 0 && entry.path().extension() == ".mp4")) kept.push_back(name);
  }
  std::sort(kept.begin(), kept.end());
  for (const auto& name : kept)
    std::fprintf(stderr, "vascsim run: note: %s/%s, of the earlier run in this directory, is kept as it was\n", dir.c_str(),
                 name.c_str());
}

// What a run writes into an existing DIR, checked before it simulates: the scene being run under
// one of those names (a --force run replaced it with its summary or log, or deleted it as a
// video), or a directory in the way, failed only after the whole simulation, or not at all. A
// symbolic link there is replaced, not written through, so it may point anywhere.
void check_run_outputs(const std::string& dir, const std::string& scene_path, bool video) {
  std::vector<std::string> names = {"frames.vlog", "summary.json"};
  if (video) names.push_back("video.mp4");
  for (const std::string& name : names) {
    const std::string path = (fs::path(dir) / name).string();
    std::error_code ec;
    const fs::file_status status = fs::symlink_status(path, ec);
    if (!fs::exists(status) || fs::is_symlink(status)) continue;
    if (!fs::is_regular_file(status)) throw InputError(path + ": exists and is not a regular file; refusing to replace it");
    if (fs::equivalent(path, scene_path, ec))
      throw InputError(path + ": is the scene being run; refusing to replace it (choose another --out)");
  }
}

// Whether `dir` is empty but for an earlier run's claim (RunDirectoryClaim's file).
bool holds_only_a_claim(const std::string& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.path().filename() != RunDirectoryClaim::kFileName) return false;
  return true;
}

// Bytes from "10G", "500M", "20000000": a whole number of bytes, or of k, M, G (powers of
// 1000), which may have a fraction ("1.5G"). Not strtod's hexadecimal or exponents.
double max_log_size(const Args& args) {
  const std::string text = args.value("max-log-size").value_or("10G");
  std::size_t digits = text.find_first_not_of("0123456789.");
  const std::string number = text.substr(0, digits), suffix = digits == std::string::npos ? "" : text.substr(digits);
  const double scale = suffix.empty() ? 1 : suffix == "k" || suffix == "K" ? 1e3 : suffix == "M" ? 1e6 : suffix == "G" ? 1e9 : NAN;
  const bool decimal = !number.empty() && number.find_first_of("0123456789") != std::string::npos &&
                       std::count(number.begin(), number.end(), '.') <= (suffix.empty() ? 0 : 1);
  const double bytes = decimal ? std::strtod(number.c_str(), nullptr) * scale : NAN;
  if (!(bytes >= 1) || !std::isfinite(bytes) || bytes != std::floor(bytes))
    throw UsageError("--max-log-size: expected a whole number of bytes, or of k, M or G (powers of 1000) such as 500M or "
                     "1.5G, got '" + text + "'");
  return bytes;
}

// A size for a message, in the unit that fits it, and in bytes (two sizes a byte apart differ).
std::string size_text(double bytes) {
  char text[64];
  if (bytes < 1e3) std::snprintf(text, sizeof text, "%.0f bytes", bytes);
  else if (bytes < 1e6) std::snprintf(text, sizeof text, "%.3g kB (%.0f bytes)", bytes / 1e3, bytes);
  else if (bytes < 1e9) std::snprintf(text, sizeof text, "%.3g MB (%.0f bytes)", bytes / 1e6, bytes);
  else std::snprintf(text, sizeof text, "%.3g GB (%.0f bytes)", bytes / 1e9, bytes);
  return text;
}

// The frame log's size is known before the run: its header (channels, and the scene and walls
// it carries) and fixed-size records at the output interval.
void check_log_size(const Run& run, const FrameLogHeader& header, double limit) {
  const Scene& scene = run.scene();
  const double frames = run.planned_frames();
  const double record = static_cast<double>(header.record_doubles()) * 8;
  const double head = static_cast<double>(frame_log_header_bytes(header));
  const double bytes = head + frames * record;
  if (bytes <= limit) return;
  char message[512];
  std::snprintf(message, sizeof message,
                "the frame log would take %s (a header of %s, and %.0f frames of %.0f bytes: run.duration %g s / "
                "run.output_interval %g s), more than --max-log-size %s: raise run.output_interval, shorten the run, or "
                "pass a larger --max-log-size",
                size_text(bytes).c_str(), size_text(head).c_str(), frames, record, scene.run.duration,
                scene.run.output_interval, size_text(limit).c_str());
  throw InputError((scene.file.empty() ? std::string("scene") : scene.file) + ": " + message);
}

}  // namespace

int run_run_command(int argc, char** argv) {
  Args args(argc, argv, 2, kOptions);
  if (args.flag("help")) {
    print_usage();
    return 0;
  }
#ifdef VASCSIM_RENDER_PROGRAM
  if (args.flag("render")) return run_in_renderer(argc, argv);  // the run and its video, in the program that draws
#endif
  if (args.positional().size() != 1) throw UsageError("expected exactly one SCENE file");
  const auto out = args.value("out");
  if (!out) throw UsageError("--out DIR is required");

  Scene input = read_scene_file(args.positional().front());
  if (args.value("duration")) {
    input.run.duration = args.number("duration", input.run.duration, 1e-9, 1e7);
    input.run.duration_from_path = false;
  }
  // Compiled before any output exists: a scene that cannot run leaves nothing behind.
  Run run(compile(input));
  const Scene& scene = run.scene();  // as resolved: the duration a maze scene runs, the rod at the entry
  warn_unused_fields("run", input);
  const FrameLogHeader log_header = run_log_header(run);
  check_log_size(run, log_header, max_log_size(args));

  // From before its first file until the summary is written: a stop asked for once anything of
  // the run can be seen (a script that waits for its directory) still ends with a summary; the
  // first step sees it. The claim's removal on a signal first, as StopOnSignal passes the signal
  // on to the handlers it found.
  RemovedOnSignal::install_handlers();
  std::optional<StopOnSignal> stop(std::in_place);
  // Refuse to mix a new run into a directory holding someone's files.
  std::error_code ec;
  std::unique_ptr<RunDirectoryClaim> claim;
  if (fs::exists(*out, ec)) {
    if (!fs::is_directory(*out, ec)) throw InputError(*out + ": exists and is not a directory");
    // A killed earlier run's or render's temporaries first: they are no one's files, and a
    // directory holding only them was refused as not empty; so is an earlier run's claim.
    remove_stale_temporaries(*out);
    if (!holds_only_a_claim(*out) && !args.flag("force"))
      throw InputError(*out + ": directory is not empty (pass --force to replace its run files)");
    claim = std::make_unique<RunDirectoryClaim>(*out);
    check_run_outputs(*out, args.positional().front(), args.flag("render"));
    remove_run_outputs(*out);
  } else if (!fs::create_directories(*out, ec)) {
    throw InputError(*out + ": cannot create directory (" + ec.message() + ")");
  } else {
    claim = std::make_unique<RunDirectoryClaim>(*out);
  }

  const std::string log_path = (fs::path(*out) / "frames.vlog").string();
  FrameLogWriter writer(log_path, log_header);
  FrameLogSink sink(writer);
  Progress progress(!args.flag("quiet"), scene.run.duration);
  const bool ok = run.run(sink, [&](double t) { progress.update(t); }, [&] { return stop->reason(); });
  progress.finish();
  writer.close();

  const std::string summary_path = (fs::path(*out) / "summary.json").string();
  const std::string summary = run_summary_json(scene, run);
  write_file_atomically(summary_path, summary);
  const RunStatistics& s = run.statistics();
  const char* outcome = ok ? "done" : s.stopped_by.empty() ? "FAILED" : "STOPPED";
  if (scene.solver.mode == SolveMode::kStatic)
    std::printf("%s: static equilibrium in %d load increments, %lld Newton iterations, %s s, %zu frames -> %s\n",
                outcome, s.steps, s.newton_iterations, measured_seconds(s.wall_time).c_str(), s.frames, log_path.c_str());
  else
    std::printf("%s: %d step%s, %s s simulated in %s s (%sx real time), %zu frames -> %s\n", outcome, s.steps,
                s.steps == 1 ? "" : "s", short_number(s.simulated_time).c_str(), measured_seconds(s.wall_time).c_str(),
                short_number(s.wall_time > 0 ? s.simulated_time / s.wall_time : 0.0, "%.1f").c_str(), s.frames,
                log_path.c_str());
  // Where a controlled run's steps went: what a user tuning rtol or the floors looks at first.
  if (scene.solver.mode != SolveMode::kStatic && run.model().solver.adaptive == StepControl::kError) {
    std::printf("error control: mean step %.3g s, %d steps rejected over the tolerance, %d kept over it at a floor\n",
                s.steps ? s.simulated_time / s.steps : 0.0, s.error_rejected_steps, s.warnings.step_over_tolerance.count);
    // The main job's run keeps most of its steps there, by design: say so, and how to follow the
    // tolerance instead, rather than leave a new user to wonder whether the run went wrong.
    if (s.warnings.step_over_tolerance.count > 0)
      std::printf("  (a floor, solver.dt_floor or dt_mean_min, caps the cost of motion the tolerance cannot follow, "
                  "such as a body rattling on walls; lower them to follow it: docs/accuracy.md, \"Presets\")\n");
  }
  if (run.navigation()) {
    char goal[64] = "goal not reached";
    if (s.goal_reached) std::snprintf(goal, sizeof goal, "goal reached at t = %.3f s", s.goal_time);
    // Without tip actuation (control.mode "none") nothing follows the reference: no tracking error to report.
    if (scene.control.mode == ActuationMode::kNone)
      std::printf("%s, no tip control, max penetration %.3f mm\n", goal, 1e3 * s.max_penetration);
    else
      std::printf("%s, tip error rms %.2f mm max %.2f mm, max penetration %.3f mm\n", goal, 1e3 * s.tip_error_rms,
                  1e3 * s.tip_error_max, 1e3 * s.max_penetration);
    if (scene.control.advance.enabled())
      std::printf("feed: pushed with up to %.3g N (mean %.3g N)\n", s.feed_force_max, s.feed_force_mean);
  }
  std::printf("summary: %s\n", summary_path.c_str());
  // Worded once for here and the replay page's timeline (sim/io/run_warnings.h).
  for (const RunWarning& w : listed_warnings(nlohmann::json::parse(summary)))
    std::fprintf(stderr, "vascsim run: warning: %s (summary.json /warnings)\n", w.line().c_str());
  if (!s.stopped_by.empty())
    std::fprintf(stderr, "vascsim run: %s; the frames computed until then are kept\n", s.failure.c_str());
  // Also a signal that came after the last step: the run is complete, but nothing more is done.
  if (!stop->reason().empty()) {
    stop->raise_again();  // ends the process by the signal, as without the summary
    return 130;
  }
  stop.reset();
  if (!ok) {
    std::fprintf(stderr, "vascsim run: simulation failed: %s\n", s.failure.c_str());
    return 1;
  }
  if (args.flag("render")) {
#ifdef VASCSIM_HAVE_RENDER
    render::RenderOptions options;
    options.mp4_path = (fs::path(*out) / "video.mp4").string();
    options.force = args.flag("force");
    const render::RenderReport report = render::render_run(*out, options);
    if (!report.note.empty()) std::printf("%s\n", report.note.c_str());
    std::printf("video: %s (%zu frames)\n", report.video_path.c_str(), report.frames);
#else
    throw UsageError("--render: this build has no renderer (configure with -DVASCSIM_RENDER=ON)");
#endif
  }
  return 0;
}

}  // namespace vascsim::cli

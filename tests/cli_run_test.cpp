// `vascsim run` as a user drives it: outputs, refusal to overwrite, bad scenes, a diverging run
// that keeps its frames and says why, and a killed run that leaves a readable log.
#include <gtest/gtest.h>
#include <poll.h>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/log/frame_log.h"
#include "tests/cli_test_support.h"

namespace vascsim::test {
namespace {

namespace fs = std::filesystem;

std::string exact(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

const char* kShortMaze = R"({"name": "short", "maze": {"seed": 4}, "rod": {"nodes": 12},
                             "path": {"speed": 0.2}, "run": {"duration": 0.5, "output_interval": 0.05}})";

TEST(CliRun, WritesLogAndSummaryAndRefusesToReuseADirectory) {
  const std::string dir = fresh_temp_dir("run_ok");
  write_text(dir + "/scene.json", kShortMaze);
  CommandResult r = run_vascsim("run " + dir + "/scene.json --out " + dir + "/out --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  FrameLogReader log(dir + "/out/frames.vlog");
  EXPECT_EQ(log.frame_count(), 11u);  // t = 0, 0.05, ..., 0.5
  EXPECT_GE(log.header().find_channel("force/contact"), 0);
  EXPECT_GE(log.header().find_channel("tip/error"), 0);
  const std::string summary = read_text(dir + "/out/summary.json");
  EXPECT_NE(summary.find("\"ok\": true"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"goal_reached\""), std::string::npos);
  // The default preset controls the error: the run says where its steps went, as summary.json does.
  const nlohmann::json j = nlohmann::json::parse(summary);
  char expected[160];
  std::snprintf(expected, sizeof expected, "error control: mean step %.3g s, %d steps rejected over the tolerance, %d kept over it at a floor\n",
                j["simulated_time"].get<double>() / j["steps"].get<double>(), j["error_control"]["rejected_steps"].get<int>(),
                j["warnings"]["step_over_tolerance"]["count"].get<int>());
  EXPECT_NE(r.output.find(expected), std::string::npos) << "expected: " << expected << "output:\n" << r.output;
  // A second run into the same directory must not replace it silently.
  r = run_vascsim("run " + dir + "/scene.json --out " + dir + "/out --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("directory is not empty (pass --force"), std::string::npos) << r.output;
  EXPECT_EQ(read_text(dir + "/out/summary.json"), summary);
  fs::remove_all(dir);
}

// Steps kept over the tolerance at a floor are the presets' design (the default maze run keeps
// most of its steps there): the run says why and how to follow the tolerance instead, and only
// when it kept any. A clamped rod sagging under its own weight keeps every step at the floor; the
// same rod under a slowly ramped, damped tip load none.
TEST(CliRun, StepsKeptAtAFloorAreExplainedWhenThereAreAny) {
  const std::string dir = fresh_temp_dir("run_floor");
  const char* rod = R"("maze": null, "rod": {"nodes": 21}, "shape": {"start": [0, 0], "direction": 0},
                      "boundary": {"clamp": "first_edge"}, )";
  write_text(dir + "/sag.json", std::string("{") + rod + R"("loads": {"gravity": {"enabled": true}},
             "run": {"duration": 0.05, "output_interval": 0.01}})");
  write_text(dir + "/calm.json", std::string("{") + rod + R"("loads": {"damping": {"enabled": true, "coefficient": 0.05},
             "point": [{"node": -1, "force": [0, -1e-4], "profile": "ramp", "ramp_time": 0.5}]},
             "run": {"duration": 0.5, "output_interval": 0.1}})");
  const std::string hint = "(a floor, solver.dt_floor or dt_mean_min, caps the cost of motion the tolerance cannot follow";
  for (const char* name : {"sag", "calm"}) {
    const CommandResult r = run_vascsim("run " + dir + "/" + name + ".json --out " + dir + "/" + name);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const int kept = nlohmann::json::parse(read_text(dir + "/" + name + "/summary.json"))["warnings"]["step_over_tolerance"]["count"];
    EXPECT_EQ(kept > 0, std::string(name) == "sag") << name << " kept " << kept << " steps at a floor";
    EXPECT_EQ(r.output.find(hint) != std::string::npos, kept > 0) << name << ":\n" << r.output;
  }
  fs::remove_all(dir);
}

TEST(CliRun, BadSceneExitsTwoAndWritesNothing) {
  const std::string dir = fresh_temp_dir("run_bad");
  write_text(dir + "/scene.json", R"({"control": {"mode": "magic"}})");
  const CommandResult r = run_vascsim("run " + dir + "/scene.json --out " + dir + "/out");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find(dir + "/scene.json: /control/mode: expected one of \"none\", \"force\", \"kinematic\", \"field\", got \"magic\""),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir + "/out"));
  fs::remove_all(dir);
}

TEST(CliRun, DivergingRunStopsWithMessageAndKeepsItsFrames) {
  const std::string dir = fresh_temp_dir("run_fail");
  // One Newton iteration, no retries: the first step cannot converge.
  write_text(dir + "/scene.json", R"({"maze": {"seed": 4}, "rod": {"nodes": 12}, "run": {"duration": 1},
      "solver": {"max_iterations": 1, "adaptive": false, "rel_tol": 1e-14}})");
  const CommandResult r = run_vascsim("run " + dir + "/scene.json --out " + dir + "/out --quiet");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("simulation failed: at t = "), std::string::npos) << r.output;
  FrameLogReader log(dir + "/out/frames.vlog");
  EXPECT_GE(log.frame_count(), 1u);
  const std::string summary = read_text(dir + "/out/summary.json");
  EXPECT_NE(summary.find("\"ok\": false"), std::string::npos) << summary;
  EXPECT_NE(summary.find("Newton"), std::string::npos) << summary;
  fs::remove_all(dir);
}

TEST(CliRun, StaticModeRecordsTheUnloadedRodAndItsEquilibrium) {
  // Small-deflection cantilever, tip deflection P L^3 / (3 EI) (docs/references.md section 1);
  // alpha = P L^2 / EI = 0.01 keeps the elastica's nonlinear correction below 1e-5.
  const double pi = 3.14159265358979323846;
  const double ei = 1.47e6 * pi * (std::pow(0.002, 4) - std::pow(0.001, 4)) / 4.0;  // Table I
  const double length = 0.5, alpha = 0.01;
  const double load = alpha * ei / (length * length);
  const std::string dir = fresh_temp_dir("run_static");
  write_text(dir + "/scene.json", R"({"maze": null, "rod": {"nodes": 41}, "boundary": {"clamp": "centred"},
      "solver": {"mode": "static"}, "loads": {"point": [{"node": -1, "force": [0, )" + exact(-load) + "]}]}}");
  const CommandResult r = run_vascsim("run " + dir + "/scene.json --out " + dir + "/out --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  FrameLogReader log(dir + "/out/frames.vlog");
  ASSERT_EQ(log.frame_count(), 2u);
  const int position = log.header().find_channel("position");
  ASSERT_GE(position, 0);
  const std::size_t tip_y = log.header().channel_offset(position) + 2 * 40 + 1;
  std::vector<double> unloaded, loaded;
  log.read(0, unloaded);
  log.read(1, loaded);
  EXPECT_EQ(unloaded[0], 0.0);
  EXPECT_EQ(loaded[0], 1.0);
  EXPECT_EQ(unloaded[tip_y], 0.0);
  EXPECT_NEAR(-loaded[tip_y], length * alpha / 3.0, 2e-3 * length * alpha / 3.0);
  fs::remove_all(dir);
}

// Ctrl-C, or a scheduler's SIGTERM, stops a run after the step in progress, and the run says so:
// its summary (/ok false, /stopped_by, the frames it kept), the command line, and the process's
// end by that very signal, as a shell or a sweep expect of a stopped command. What is made of the
// run warns that it was stopped (its pictures say "Run stopped": tests/render_failed_run_test.cpp).
TEST(CliRun, ARunStoppedBySignalWritesASummaryThatSaysSoAndEndsByTheSignal) {
  const std::string dir = fresh_temp_dir("run_stopped");
  write_text(dir + "/long.json", kLongRunScene);
  for (const auto& [signal, name] : {std::pair<int, std::string>{SIGINT, "SIGINT (Ctrl-C)"}, {SIGTERM, "SIGTERM"}}) {
    const std::string out = dir + "/out" + std::to_string(signal), printed = dir + "/printed.txt";
    const pid_t run = start_vascsim({"run", dir + "/long.json", "--out", out, "--quiet"}, {printed});
    ASSERT_TRUE(wait_for_files({out + "/frames.vlog"})) << "the run never started";
    ::usleep(300000);
    ::kill(run, signal);
    int status = 0;
    ASSERT_EQ(::waitpid(run, &status, 0), run);
    const std::string output = read_text(printed);
    ASSERT_TRUE(WIFSIGNALED(status)) << status << "\n" << output;
    EXPECT_EQ(WTERMSIG(status), signal);
    ASSERT_TRUE(fs::exists(out + "/summary.json")) << output;
    const nlohmann::json summary = nlohmann::json::parse(read_text(out + "/summary.json"));
    EXPECT_EQ(summary["ok"], false);
    EXPECT_EQ(summary["stopped_by"], name);
    const std::string failure = summary["failure"].get<std::string>();
    EXPECT_EQ(failure.rfind("stopped by " + name + " at t = ", 0), 0u) << failure;
    EXPECT_NE(failure.find("before the run's end (1000 s)"), std::string::npos) << failure;
    FrameLogReader log(out + "/frames.vlog");
    ASSERT_GE(log.frame_count(), 2u);
    EXPECT_EQ(summary["frames"], log.frame_count()) << "the summary does not describe the log kept";
    std::vector<double> last;
    log.read(log.frame_count() - 1, last);
    EXPECT_GE(summary["simulated_time"].get<double>(), last[0]);
    EXPECT_LT(summary["simulated_time"].get<double>(), last[0] + 0.01 + 1e-9) << "it went on past the next frame";
    EXPECT_NE(output.find("STOPPED: "), std::string::npos) << output;
    EXPECT_NE(output.find("vascsim run: " + failure + "; the frames computed until then are kept"), std::string::npos)
        << output;
    EXPECT_FALSE(fs::exists(out + "/.vascsim-run.lock")) << "the stopped run left its claim";
    const CommandResult csv = run_vascsim("export " + out + " --csv " + dir + "/csv" + std::to_string(signal));
    EXPECT_EQ(csv.exit_code, 0) << csv.output;
    EXPECT_NE(csv.output.find(out + "/summary.json: the run was stopped before its end (" + failure +
                              "); its log ends with the last frame before it stopped"),
              std::string::npos)
        << csv.output;
  }
  fs::remove_all(dir);
}

// A stop asked for the moment the run's directory shows its first file (a sweep's Ctrl-C, a script
// that waits for the run to start) is handled like any other: the run ends with a summary that
// says so. The handler was installed only after the log was opened, so a signal in between ended
// the run by default, without a summary (seen once in a sweep test under load). inotify tells of
// the claim's file within microseconds of its creation, sooner than that window closed.
TEST(CliRun, AStopAskedForAsSoonAsTheRunsFirstFileAppearsIsHandled) {
  const std::string dir = fresh_temp_dir("run_stopped_early");
  write_text(dir + "/long.json", kLongRunScene);
  for (int attempt = 0; attempt < 5; ++attempt) {
    const std::string out = dir + "/out" + std::to_string(attempt), printed = dir + "/printed.txt";
    fs::create_directories(out);  // empty: a run may take it
    const int watch = ::inotify_init1(IN_CLOEXEC);
    ASSERT_GE(watch, 0);
    ASSERT_GE(::inotify_add_watch(watch, out.c_str(), IN_CREATE), 0);
    const pid_t run = start_vascsim({"run", dir + "/long.json", "--out", out, "--quiet"}, {printed});
    alignas(inotify_event) char events[4096];
    pollfd ready{watch, POLLIN, 0};
    const bool created = ::poll(&ready, 1, 60000) == 1 && ::read(watch, events, sizeof events) > 0;
    ::kill(run, SIGTERM);
    ::close(watch);
    int status = 0;
    ASSERT_EQ(::waitpid(run, &status, 0), run);
    ASSERT_TRUE(created) << "the run created nothing in its directory";
    const std::string output = read_text(printed);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status << "\n" << output;
    ASSERT_TRUE(fs::exists(out + "/summary.json")) << "attempt " << attempt << ": ended without its summary\n" << output;
    EXPECT_EQ(nlohmann::json::parse(read_text(out + "/summary.json"))["stopped_by"], "SIGTERM");
  }
  fs::remove_all(dir);
}

// A run started ignoring SIGHUP (under nohup, to outlive its terminal) goes on when the terminal
// closes; SIGTERM still stops it as above.
TEST(CliRun, ARunStartedUnderNohupGoesOnWhenItsTerminalCloses) {
  const std::string dir = fresh_temp_dir("run_nohup");
  write_text(dir + "/long.json", kLongRunScene);
  const std::string out = dir + "/out";
  StartOptions nohup;
  nohup.ignored_signal = SIGHUP;
  const pid_t run = start_vascsim({"run", dir + "/long.json", "--out", out, "--quiet"}, nohup);
  ASSERT_TRUE(wait_for_files({out + "/frames.vlog"})) << "the run never started";
  ::kill(run, SIGHUP);
  ::usleep(500000);  // a run that took it as a stop ends within a step (under a millisecond)
  int status = 0;
  EXPECT_EQ(::waitpid(run, &status, WNOHANG), 0) << "the run ended on SIGHUP";
  EXPECT_FALSE(fs::exists(out + "/summary.json"));
  ::kill(run, SIGTERM);
  ASSERT_EQ(::waitpid(run, &status, 0), run);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_EQ(nlohmann::json::parse(read_text(out + "/summary.json"))["stopped_by"], "SIGTERM");
  fs::remove_all(dir);
}

TEST(CliRun, KilledRunLeavesAReadableLog) {
  const std::string dir = fresh_temp_dir("run_kill");
  write_text(dir + "/scene.json", kLongRunScene);
  const CommandResult r = run_vascsim_killed_after("run " + dir + "/scene.json --out " + dir + "/out --quiet", 1.5);
  (void)r;
  FrameLogReader log(dir + "/out/frames.vlog");
  const std::size_t n = log.frame_count();
  ASSERT_GE(n, 2u);
  std::vector<double> last;
  log.read(n - 1, last);
  EXPECT_NEAR(last[0], 0.01 * static_cast<double>(n - 1), 1e-9);
  // Its claim's file stays (no program cleans up after kill -9), but no process holds it: what is
  // made of the log says the run was killed, not that it may still be running.
  EXPECT_TRUE(fs::exists(dir + "/out/.vascsim-run.lock"));
  const CommandResult csv = run_vascsim("export " + dir + "/out --csv " + dir + "/csv");
  EXPECT_EQ(csv.exit_code, 0) << csv.output;
  EXPECT_NE(csv.output.find(dir + "/out has no summary.json: its run was killed before its end (kill -9, a crash, the machine "
                                  "out of memory: it left its claim on the directory, which no run holds)"),
            std::string::npos)
      << csv.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vascsim::test

namespace vascsim::test {
namespace {

// run.output_interval has a floor, and a run whose log would exceed --max-log-size (default 10G)
// is refused before anything is written (1e-9 s once wrote 810 MB in 3 s).
TEST(CliRun, TinyOutputIntervalsAndHugeLogsAreRefusedUpFront) {
  const std::string dir = fresh_temp_dir("run_log_size");
  write_text(dir + "/tiny.json", R"({"maze": null, "run": {"output_interval": 1e-9}})");
  CommandResult r = run_vascsim("run " + dir + "/tiny.json --out " + dir + "/a");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("/run/output_interval"), std::string::npos) << r.output;
  write_text(dir + "/long.json", R"({"maze": null, "rod": {"nodes": 40}, "run": {"duration": 1000, "output_interval": 1e-5}})");
  r = run_vascsim("run " + dir + "/long.json --out " + dir + "/b");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("GB"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--max-log-size"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/b")) << "nothing may be written for a refused run";
  // The limit is the user's to move, either way.
  write_text(dir + "/short.json", R"({"maze": null, "rod": {"nodes": 10}, "run": {"duration": 0.1}})");
  r = run_vascsim("run " + dir + "/short.json --out " + dir + "/c --quiet --max-log-size 1k");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = run_vascsim("run " + dir + "/short.json --out " + dir + "/c --quiet --max-log-size 1M");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  r = run_vascsim("run " + dir + "/short.json --out " + dir + "/d --max-log-size lots");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  // The limit counts the header (the scene and the walls a log carries), and the log written
  // fits it: a maze run's header is most of a short log (the records alone were counted, and a
  // log three times the limit was written).
  write_text(dir + "/maze.json", R"({"run": {"duration": 0.2}})");
  r = run_vascsim("run " + dir + "/maze.json --out " + dir + "/e --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto size = fs::file_size(dir + "/e/frames.vlog");
  r = run_vascsim("run " + dir + "/maze.json --out " + dir + "/f --quiet --max-log-size " + std::to_string(size - 1));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("a header of "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(" + std::to_string(size) + " bytes"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(" + std::to_string(size - 1) + " bytes): raise"), std::string::npos) << r.output;
  r = run_vascsim("run " + dir + "/maze.json --out " + dir + "/f --quiet --max-log-size " + std::to_string(size));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(fs::file_size(dir + "/f/frames.vlog"), size);
  // A duration between two output times ends with a frame at the duration, and one that the
  // quotient rounds below a whole number (0.03 / 0.01) with one at the last multiple: the limit
  // counts those frames too (the log of 0.025 s took one frame more than the limit allowed).
  for (const std::string duration : {"0.025", "0.03"}) {
    write_text(dir + "/odd.json", R"({"maze": null, "rod": {"nodes": 10}, "run": {"duration": )" + duration +
                                      R"(, "output_interval": 0.01}})");
    fs::remove_all(dir + "/h");
    r = run_vascsim("run " + dir + "/odd.json --out " + dir + "/h --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto odd_size = fs::file_size(dir + "/h/frames.vlog");
    r = run_vascsim("run " + dir + "/odd.json --out " + dir + "/i --quiet --max-log-size " + std::to_string(odd_size - 1));
    EXPECT_EQ(r.exit_code, 2) << duration << ": " << r.output;
    EXPECT_NE(r.output.find("and 4 frames of "), std::string::npos) << duration << ": " << r.output;
  }
  // Whole bytes, or k, M, G: not hexadecimal, exponents or fractions of a byte.
  for (const char* size_text : {"0x10", "1e6", "0.5", "1.0001k", "-5", "0", "5 M"}) {
    r = run_vascsim("run " + dir + "/short.json --out " + dir + "/g --max-log-size '" + size_text + "'");
    EXPECT_EQ(r.exit_code, 2) << size_text << ": " << r.output;
    EXPECT_NE(r.output.find("--max-log-size: expected a whole number of bytes"), std::string::npos) << size_text << ": " << r.output;
  }
  fs::remove_all(dir);
}

// What a run would write over is checked before it simulates: the scene itself under an output's
// name (a forced run replaced it with its summary or log, or deleted it as its video), or a
// directory in the way (found after the whole simulation).
TEST(CliRun, TheSceneAndDirectoriesInTheWayAreRefusedBeforeSimulating) {
  const std::string dir = fresh_temp_dir("run_outputs_in_the_way");
  const std::string scene = R"({"maze": null, "rod": {"nodes": 10}, "run": {"duration": 0.05}})";
  for (const char* name : {"summary.json", "frames.vlog", "video.mp4"}) {
    const std::string out = dir + "/" + name + "_dir";
    fs::create_directories(out);
    write_text(out + "/" + name, scene);
    const CommandResult r = run_vascsim("run " + out + "/" + name + " --out " + out + " --quiet --force --render");
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.output;
    EXPECT_NE(r.output.find(out + "/" + name + ": is the scene being run; refusing to replace it"), std::string::npos) << r.output;
    EXPECT_EQ(read_text(out + "/" + name), scene) << name << ": the scene was replaced";
  }
  write_text(dir + "/scene.json", scene);
  fs::create_directories(dir + "/blocked/summary.json/inside");
  const CommandResult r = run_vascsim("run " + dir + "/scene.json --out " + dir + "/blocked --quiet --force");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("blocked/summary.json: exists and is not a regular file"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/blocked/frames.vlog")) << "simulated before refusing";
  fs::remove_all(dir);
}

// Two runs into one directory at once: the second is refused while the first writes (both ran,
// and one's log was left beside the other's summary). The claim's hidden file goes with the run,
// also when a signal stops it.
TEST(CliRun, ASecondRunIntoADirectoryBeingWrittenIsRefused) {
  const std::string dir = fresh_temp_dir("run_claim");
  write_text(dir + "/long.json", kLongRunScene);
  write_text(dir + "/short.json", R"({"maze": null, "rod": {"nodes": 10}, "run": {"duration": 0.02}})");
  const std::string out = dir + "/out";
  const pid_t first = start_vascsim({"run", dir + "/long.json", "--out", out, "--quiet"});
  ASSERT_TRUE(wait_for_files({out + "/frames.vlog"})) << "the first run never started";
  CommandResult r = run_vascsim("run " + dir + "/short.json --out " + out + " --quiet --force");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(out + ": another vascsim run is writing into this directory"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(out + "/frames.vlog")) << "the second run removed the first one's log";
  // What is made of the log meanwhile says the run goes on (not that it may have been killed).
  r = run_vascsim("export " + out + " --csv " + dir + "/csv");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(out + " has no summary.json yet: a run is still writing it, so its log ends with the frames written so far"),
            std::string::npos)
      << r.output;
  ::kill(first, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(first, &status, 0), first);
  EXPECT_TRUE(WIFSIGNALED(status)) << status;
  EXPECT_FALSE(fs::exists(out + "/.vascsim-run.lock")) << "the stopped run left its claim";
  r = run_vascsim("run " + dir + "/short.json --out " + out + " --quiet --force");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(fs::exists(out + "/.vascsim-run.lock"));
  fs::remove_all(dir);
}

// A forced run first removes the previous run's outputs: killed early or run with another scene,
// it never leaves an old summary or video beside its own log. The user's other files stay.
TEST(CliRun, ForcedRunRemovesThePreviousRunsOutputsFirst) {
  const std::string dir = fresh_temp_dir("run_force");
  write_text(dir + "/ok.json", R"({"maze": null, "rod": {"nodes": 10}, "run": {"duration": 0.05}})");
  ASSERT_EQ(run_vascsim("run " + dir + "/ok.json --out " + dir + "/out --quiet").exit_code, 0);
  write_text(dir + "/out/video.mp4", "an old video");
  fs::create_directories(dir + "/out/plots");
  write_text(dir + "/out/plots/snapshots.png", "an old plot");
  write_text(dir + "/out/notes.txt", "mine");
  write_text(dir + "/out/bookmarks.json", R"({"format": "vascsim-bookmarks/1", "bookmarks": []})");
  write_text(dir + "/out/export-001.mp4", "a replay export");
  // The next run fails at its first step: it writes a new summary (ok false) and keeps nothing old.
  write_text(dir + "/bad.json", R"({"maze": null, "rod": {"nodes": 10}, "run": {"duration": 1},
      "loads": {"point": [{"node": -1, "force": [0, 1e6]}]}, "solver": {"max_iterations": 1, "adaptive": false, "rel_tol": 1e-14}})");
  const CommandResult r = run_vascsim("run " + dir + "/bad.json --out " + dir + "/out --quiet --force");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/out/video.mp4")) << "the previous run's video survived";
  EXPECT_FALSE(fs::exists(dir + "/out/plots/snapshots.png")) << "the previous run's plot survived";
  EXPECT_NE(read_text(dir + "/out/summary.json").find("\"ok\": false"), std::string::npos);
  EXPECT_EQ(read_text(dir + "/out/notes.txt"), "mine");
  // The replay's files of the earlier run stay, and the user is told they describe that run.
  EXPECT_EQ(read_text(dir + "/out/export-001.mp4"), "a replay export");
  EXPECT_NE(r.output.find("note: " + dir + "/out/bookmarks.json, of the earlier run in this directory, is kept as it was"),
            std::string::npos) << r.output;
  EXPECT_NE(r.output.find(dir + "/out/export-001.mp4, of the earlier run"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

// The run's closing line gives the times of a short run in digits that are not all zero: a run of
// a millisecond printed "1 steps, 0.00 s simulated in 0.00 s".
TEST(CliRun, TheClosingLineOfAShortRunGivesItsTimes) {
  const std::string dir = fresh_temp_dir("run_short_line");
  write_text(dir + "/short.json", R"({"maze": null, "rod": {"nodes": 10}, "solver": {"dt": 1e-3, "adaptive": false},
      "run": {"duration": 1e-3, "output_interval": 1e-3}})");
  const CommandResult r = run_vascsim("run " + dir + "/short.json --out " + dir + "/out --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("done: 1 step, 0.001 s simulated in "), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find(" in 0.00 s"), std::string::npos) << r.output;
  // A measured time keeps three significant digits, zeros too ("0.200 s", not "0.2 s").
  const std::size_t in = r.output.find(" s simulated in ") + 16, end = r.output.find(" s (", in);
  ASSERT_NE(end, std::string::npos) << r.output;
  const std::string wall = r.output.substr(in, end - in);
  EXPECT_EQ(wall.size() - wall.find_first_not_of("0."), 3u) << wall;
  fs::remove_all(dir);
}

TEST(CliRun, ADirectoryOrADeviceIsNotASceneFile) {
  const std::string dir = fresh_temp_dir("run_scene_kind");
  CommandResult r = run_vascsim("run " + dir + " --out " + dir + "/out");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("is a directory"), std::string::npos) << r.output;
  r = run_vascsim("run /dev/zero --out " + dir + "/out");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("not a regular file"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

// The summary line gives the goal time to the millisecond, as summary.json has it (it printed
// "45.859982 s").
TEST(CliRun, TheGoalTimeIsPrintedToTheMillisecond) {
  const std::string dir = fresh_temp_dir("run_goal");
  write_text(dir + "/scene.json", R"({"name": "tiny", "maze": {"seed": 4, "rows": 2, "cols": 2}, "rod": {"nodes": 12},
                                      "path": {"speed": 0.2}, "run": {"duration": 6, "output_interval": 0.5}})");
  const CommandResult r = run_vascsim("run " + dir + "/scene.json --out " + dir + "/out");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(read_text(dir + "/out/summary.json"));
  ASSERT_TRUE(j["navigation"]["goal_reached"].get<bool>()) << r.output;
  char expected[64];
  std::snprintf(expected, sizeof expected, "goal reached at t = %.3f s, tip error rms ",
                j["navigation"]["goal_time"].get<double>());
  EXPECT_NE(r.output.find(expected), std::string::npos) << r.output;
  fs::remove_all(dir);
}

// A catheter only pushed from its root (control.mode "none", control.advance) follows no
// reference: the summary line reports the drive's push, not a tracking error it cannot have.
TEST(CliRun, ARunWithoutTipControlReportsTheFeedNotATrackingError) {
  const std::string dir = fresh_temp_dir("run_feed_only");
  const CommandResult r = run_vascsim("run " + std::string(VASCSIM_SOURCE_DIR) + "/scenes/coil_chamber.json --out " + dir +
                                      "/out --duration 0.3 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("no tip control"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("feed: pushed with up to "), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("tip error"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace vascsim::test

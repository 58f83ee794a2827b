// vascsim sweep on the local engine, through the command line: the sweep directory, resume,
// failed runs and --retry-failed, Ctrl-C, --run-index and --shard, the merged table and its
// determinism, the files for GNU parallel and Slurm, and bad input (exit code 2, the file and
// JSON path named, nothing written). Runs are the default maze for 0.3 s: a few ms each.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "sim/io/output_file.h"
#include "tests/cli_test_support.h"
#include "tests/sweep_test_support.h"

namespace vascsim::test {
namespace {

namespace fs = std::filesystem;

TEST(SweepCli, RunsEveryEntryInItsOwnDirectoryAndMerges) {
  const std::string dir = fresh_temp_dir("sweep_local");
  const std::string sweep = write_maze_sweep(dir, "kp", kAxes, 0.3);
  const CommandResult r = sweep_command(sweep + " --out " + dir + "/out --jobs 2 | cat");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(has(r.output, "ran 8 of 8 runs")) << r.output;
  EXPECT_TRUE(has(r.output, "utilisation")) << r.output;
  for (const char* f : {"manifest.json", "sweep.json", "results.csv", "results.json"}) EXPECT_TRUE(fs::exists(dir + "/out/" + f)) << f;
#ifdef VASCSIM_HAVE_RENDER
  for (const char* f : {"plots/control_kp.png", "plots/maze_seed.png"}) EXPECT_TRUE(fs::exists(dir + "/out/" + f)) << f;
#else
  EXPECT_TRUE(has(r.output, "no plots: this build has no renderer")) << r.output;
#endif
  for (const char* id : {"0000", "0007"})
    for (const char* f : {"scene.json", "frames.vlog", "summary.json", "status.json", "run.log"})
      EXPECT_TRUE(fs::exists(dir + "/out/runs/" + id + "/" + f)) << id << "/" << f;
  const std::string csv = read_text(dir + "/out/results.csv");
  EXPECT_EQ(parse_csv(csv).size(), 9u);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "index,id,repeat,/control/kp,/maze/seed,status,goal_reached,goal_time_s,tip_error_rms_m,tip_error_max_m,"
            "actuation_force_max_N,contact_force_max_N,feed_force_max_N,max_penetration_m,steps,newton_iterations,"
            "rejected_steps,failure,"
            "wall_time_s,real_time_factor,process_time_s,cpu_time_s,host");
  EXPECT_EQ(csv_cell(csv, 5, "/control/kp"), "4");
  EXPECT_EQ(csv_cell(csv, 5, "/maze/seed"), "2");
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(csv_cell(csv, i, "status"), "done") << i;
    // The steps the run itself reports (error-controlled: fewer than the 300 of a fixed 1 ms).
    char id[8];
    std::snprintf(id, sizeof id, "%04zu", i);
    const std::string run_summary = read_text(dir + "/out/runs/" + id + "/summary.json");
    EXPECT_TRUE(has(run_summary, "\"steps\": " + csv_cell(csv, i, "steps") + ",")) << i;
    EXPECT_LT(std::stoi(csv_cell(csv, i, "steps")), 300) << i;
  }
  // The gain matters: kp = 4 tracks closer than kp = 2 (the figures are the runs' own).
  EXPECT_LT(std::stod(csv_cell(csv, 4, "tip_error_rms_m")), std::stod(csv_cell(csv, 0, "tip_error_rms_m")));
  const std::string summary = read_text(dir + "/out/runs/0004/summary.json");
  EXPECT_TRUE(has(summary, "\"tip_error_rms\": " + csv_cell(csv, 4, "tip_error_rms_m"))) << summary.substr(0, 2000);
  // The summary table: one line per axis value.
  EXPECT_TRUE(has(r.output, "sweep kp (")) << r.output;
  EXPECT_TRUE(has(r.output, "8 runs: 8 done, 0 failed, 0 missing")) << r.output;
  EXPECT_TRUE(has(r.output, "tip error RMS (mm)") && !has(r.output, "feed")) << "steered runs, none fed:\n" << r.output;
  EXPECT_EQ(csv_cell(csv, 0, "feed_force_max_N"), "") << "a run whose root is not fed has no feed force";

  // The same sweep again, elsewhere: the same table but for the timing columns, byte for byte.
  const CommandResult again = sweep_command(sweep + " --out " + dir + "/again --jobs 1 --quiet");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_EQ(deterministic_columns(read_text(dir + "/again/results.csv")), deterministic_columns(csv));
  EXPECT_NE(read_text(dir + "/again/results.csv"), csv) << "the timing columns should differ (they are measured)";

#ifdef VASCSIM_HAVE_RENDER
  // A merge without plots takes the earlier merge's figures away (they would show other results
  // beside the new tables), and only with --force, as it replaces the tables.
  EXPECT_EQ(sweep_command("merge " + dir + "/out --no-plots").exit_code, 2);
  EXPECT_TRUE(fs::exists(dir + "/out/plots/control_kp.png"));
  const CommandResult tables_only = sweep_command("merge " + dir + "/out --no-plots --force");
  ASSERT_EQ(tables_only.exit_code, 0) << tables_only.output;
  for (const char* f : {"plots/control_kp.png", "plots/maze_seed.png"}) EXPECT_FALSE(fs::exists(dir + "/out/" + f)) << f;
#endif
}

// A sweep of runs only pushed from their root (scenes/coil_chamber.json, control.mode "none")
// tabulates the drive's push and not a tip error nothing steered; one that also steers shows both.
TEST(SweepCli, ASweepOfRunsPushedFromTheirRootTabulatesTheDrivesPush) {
  const std::string dir = fresh_temp_dir("sweep_fed");
  const auto write_sweep = [&](const std::string& name, const std::string& axes) {
    const std::string path = dir + "/" + name + ".json";
    write_text(path, R"({"format": "vascsim-sweep/1", "scene": ")" + source_path("scenes/coil_chamber.json") +
                         R"(", "axes": )" + axes + R"(, "overrides": {"/run/duration": 0.2}})" + "\n");
    return path;
  };
  const CommandResult pushed =
      sweep_command(write_sweep("speed", R"({"/control/advance/speed": [0.02, 0.05]})") + " --out " + dir + "/speed");
  ASSERT_EQ(pushed.exit_code, 0) << pushed.output;
  EXPECT_TRUE(has(pushed.output, "feed force max (mN)") && !has(pushed.output, "tip error")) << pushed.output;
  const std::string csv = read_text(dir + "/speed/results.csv");
  for (std::size_t i = 0; i < 2; ++i) {
    const nlohmann::json summary =
        nlohmann::json::parse(read_text(dir + "/speed/runs/000" + std::to_string(i) + "/summary.json"));
    EXPECT_EQ(summary["navigation"]["control_mode"], "none");
    EXPECT_TRUE(summary["navigation"]["tip_error_rms"].is_null() && summary["navigation"]["tip_error_max"].is_null())
        << "a tip error nothing steered, in run " << i << "'s summary: " << summary["navigation"].dump();
    EXPECT_EQ(csv_cell(csv, i, "tip_error_rms_m"), "") << "nothing steered the tip of run " << i;
    EXPECT_EQ(std::stod(csv_cell(csv, i, "feed_force_max_N")),
              summary["navigation"]["advance"]["feed_force_max"].get<double>()) << i;
  }
  EXPECT_GT(std::stod(csv_cell(csv, 1, "feed_force_max_N")), std::stod(csv_cell(csv, 0, "feed_force_max_N")))
      << "pushed faster against the blood's drag, the drive pushes harder";

  const CommandResult mixed =
      sweep_command(write_sweep("mode", R"({"/control/mode": ["none", "force"]})") + " --out " + dir + "/mode");
  ASSERT_EQ(mixed.exit_code, 0) << mixed.output;
  EXPECT_TRUE(has(mixed.output, "tip error RMS (mm)") && has(mixed.output, "feed force max (mN)")) << mixed.output;
  const std::string mixed_csv = read_text(dir + "/mode/results.csv");
  EXPECT_EQ(csv_cell(mixed_csv, 0, "/control/mode"), "none");
  EXPECT_EQ(csv_cell(mixed_csv, 0, "tip_error_rms_m"), "");
  EXPECT_NE(csv_cell(mixed_csv, 1, "tip_error_rms_m"), "") << "the steered run has a tip error";
}

TEST(SweepCli, ResumesSkippingCompletedRunsAndRerunsOnlyWhatIsMissing) {
  const std::string dir = fresh_temp_dir("sweep_resume");
  const std::string sweep = write_maze_sweep(dir, "kp", kAxes, 0.3);
  ASSERT_EQ(sweep_command(sweep + " --out " + dir + "/out --no-merge --quiet").exit_code, 0);
  const std::string log = read_text(dir + "/out/runs/0002/summary.json");
  // A run that was killed leaves no summary: it is missing, and resume runs it (only it).
  fs::remove(dir + "/out/runs/0005/summary.json");
  fs::remove(dir + "/out/runs/0005/status.json");
  const CommandResult r = sweep_command(sweep + " --out " + dir + "/out");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(has(r.output, "(resuming)")) << r.output;
  EXPECT_TRUE(has(r.output, "ran 1 of 8 runs (7 completed before")) << r.output;
  EXPECT_EQ(read_text(dir + "/out/runs/0002/summary.json"), log) << "a completed run must not be run again";
  EXPECT_TRUE(fs::exists(dir + "/out/runs/0005/summary.json"));
  // The directory alone resumes too (what an engine or a user without the sweep file does).
  const CommandResult d = sweep_command(dir + "/out --quiet");
  EXPECT_EQ(d.exit_code, 0) << d.output;
  EXPECT_TRUE(has(d.output, "results.csv is from an earlier merge")) << d.output;
  // results.csv deleted but results.json left: the merge it would refuse is not started (the
  // sweep exited 2, "merging failed", after every run had completed).
  fs::remove(dir + "/out/results.csv");
  const CommandResult j = sweep_command(dir + "/out --quiet");
  EXPECT_EQ(j.exit_code, 0) << j.output;
  EXPECT_TRUE(has(j.output, "results.json is from an earlier merge")) << j.output;
  EXPECT_FALSE(fs::exists(dir + "/out/results.csv"));
}

TEST(SweepCli, AFailedRunIsARowAndIsRetriedOnlyWhenAsked) {
  const std::string dir = fresh_temp_dir("sweep_failed");
  // A rod 120 mm across in a 100 mm lumen: `vascsim run` refuses it (exit 2) before simulating.
  const std::string sweep =
      write_maze_sweep(dir, "radius", R"({"/rod/outer_radius": [0.002, 0.06]})", 0.3, R"(, "name": "radius")");
  const CommandResult r = sweep_command(sweep + " --out " + dir + "/out");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(has(r.output, "run 0001 (/rod/outer_radius = 0.06) failed: vascsim run exited with code 2: vascsim run: "
                            "runs/0001/scene.json: /maze/lumen_width: the lumen (100 mm) must be wider than the rod"))
      << r.output;
  const std::string csv = read_text(dir + "/out/results.csv");
  EXPECT_EQ(csv_cell(csv, 0, "status"), "done");
  EXPECT_EQ(csv_cell(csv, 1, "status"), "failed");
  EXPECT_TRUE(has(csv_cell(csv, 1, "failure"), "must be wider than the rod")) << csv;
  EXPECT_EQ(csv_cell(csv, 1, "tip_error_rms_m"), "");
  EXPECT_TRUE(has(r.output, "2 runs: 1 done, 1 failed, 0 missing")) << r.output;

  const CommandResult skip = sweep_command(sweep + " --out " + dir + "/out --no-merge");
  EXPECT_EQ(skip.exit_code, 1) << skip.output;
  EXPECT_TRUE(has(skip.output, "ran 0 of 2 runs (1 completed before, 1 failed before)")) << skip.output;
  const CommandResult retry = sweep_command(sweep + " --out " + dir + "/out --no-merge --retry-failed");
  EXPECT_EQ(retry.exit_code, 1) << retry.output;
  EXPECT_TRUE(has(retry.output, "ran 1 of 2 runs")) << retry.output;
}

TEST(SweepCli, CtrlCStopsCleanlyAndAResumeGivesTheSameTable) {
  const std::string dir = fresh_temp_dir("sweep_interrupt");
  // One short run, then long ones: the signal is sent when the sweep has recorded the short one
  // (its status.json) and the first long one is writing its log, so some are completed and some
  // running when it lands, however fast the machine.
  const std::string sweep = dir + "/durations.json";
  write_text(sweep, R"({"format": "vascsim-sweep/1", "scene": ")" + source_path("scenes/maze_default.json") +
                        R"(", "axes": {"/run/duration": [0.2, 20, 20.5, 21], "/control/kp": [4]}})");
  // kill signals the sweep alone (not its process group): the sweep must pass it on.
  const CommandResult r = run_shell("{ " + std::string(VASCSIM_EXE) + " sweep " + sweep + " --out " + dir +
                                    "/out --jobs 2 & pid=$!; "
                                    "until [ -e " + dir + "/out/runs/0000/status.json ] && [ -e " + dir + "/out/runs/0001/frames.vlog ] || "
                                    "! kill -0 $pid 2>/dev/null; do sleep 0.01; done; "
                                    "kill -INT $pid; wait $pid; echo \"exit code $?\"; }");
  ASSERT_TRUE(has(r.output, "exit code 130")) << r.output;
  EXPECT_TRUE(has(r.output, "interrupted")) << r.output;
  std::size_t completed = 0, stopped = 0;
  for (int i = 0; i < 4; ++i) {
    const std::string run = dir + "/out/runs/000" + std::to_string(i);
    const bool summary = fs::exists(run + "/summary.json"), status = fs::exists(run + "/status.json");
    // A recorded run has its summary. (A run stopped after writing its summary, before it exited,
    // has no status.json and still counts as completed: summary.json is written last.)
    EXPECT_TRUE(summary || !status) << run << ": a status without a summary";
    // A run the sweep stopped (passing on the signal as SIGTERM) ended after its step in
    // progress, and its summary says so; the sweep records no status for it.
    const bool stopped_by_sweep =
        summary && nlohmann::json::parse(read_text(run + "/summary.json")).value("stopped_by", nlohmann::json()) == "SIGTERM";
    EXPECT_FALSE(stopped_by_sweep && status) << run << ": a run the sweep stopped was recorded";
    completed += summary && !stopped_by_sweep;
    stopped += stopped_by_sweep;
  }
  EXPECT_GE(completed, 1u) << r.output;
  EXPECT_LT(completed, 4u) << r.output;
  EXPECT_GE(stopped, 1u) << "no run was interrupted mid-way: " << r.output;
  EXPECT_FALSE(fs::exists(dir + "/out/results.csv")) << "an interrupted sweep does not merge";

  const CommandResult resumed = sweep_command(sweep + " --out " + dir + "/out --jobs 2");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_TRUE(has(resumed.output, "ran " + std::to_string(4 - completed) + " of 4 runs")) << resumed.output;
  ASSERT_EQ(sweep_command(sweep + " --out " + dir + "/whole --jobs 2 --quiet").exit_code, 0);
  EXPECT_EQ(deterministic_columns(read_text(dir + "/out/results.csv")),
            deterministic_columns(read_text(dir + "/whole/results.csv")));
}

// Slurm's time limit (or scancel) sends SIGTERM to every process of the task: the sweep and its
// run. The run gets a second SIGTERM when the sweep passes its own on, and still ends as a run
// stopped by the first: it writes a summary that says so, and the sweep records no status for it
// (it is run again when the array is submitted again).
TEST(SweepCli, SigtermToTheWholeTaskStopsEachRunWithASummaryThatSaysSo) {
  const std::string dir = fresh_temp_dir("sweep_group_sigterm");
  const std::string sweep = dir + "/long.json";
  write_text(sweep, R"({"format": "vascsim-sweep/1", "scene": ")" + source_path("scenes/maze_default.json") +
                        R"(", "axes": {"/run/duration": [1000, 1001], "/control/kp": [4]}})");
  const std::string out = dir + "/out", printed = dir + "/printed.txt";
  const pid_t task = start_vascsim({"sweep", sweep, "--out", out, "--jobs", "2", "--no-merge"}, {printed, true});
  const bool started = wait_for_files({out + "/runs/0000/frames.vlog", out + "/runs/0001/frames.vlog"}, 60);
  ::usleep(200000);
  ::kill(-task, SIGTERM);
  EXPECT_TRUE(started) << "the runs never started";
  int status = 0;
  ASSERT_EQ(::waitpid(task, &status, 0), task);
  const std::string output = read_text(printed);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 143) << status << "\n" << output;
  for (const char* id : {"0000", "0001"}) {
    const std::string run = out + "/runs/" + id;
    ASSERT_TRUE(fs::exists(run + "/summary.json")) << run << ": killed before it wrote its summary\n"
                                                   << read_text(run + "/run.log");
    const nlohmann::json summary = nlohmann::json::parse(read_text(run + "/summary.json"));
    EXPECT_EQ(summary["stopped_by"], "SIGTERM") << run;
    EXPECT_EQ(summary["ok"], false) << run;
    EXPECT_FALSE(fs::exists(run + "/status.json")) << run << ": a run the sweep stopped was recorded";
  }
}

TEST(SweepCli, ASweepKilledWithSigkillTakesItsRunsWithIt) {
  // A resumed sweep must not start an entry beside an orphan still writing it: the runs of a
  // sweep killed with SIGKILL stop (the kernel sends them SIGTERM), and until they have, each
  // holds its entry's lock.
  const std::string dir = fresh_temp_dir("sweep_sigkill");
  const std::string sweep = dir + "/long.json";
  write_text(sweep, R"({"format": "vascsim-sweep/1", "scene": ")" + source_path("scenes/maze_default.json") +
                        R"(", "axes": {"/run/duration": [1000, 1001], "/control/kp": [4]}})");
  const std::string out = dir + "/out";
  const CommandResult r = run_shell("{ " + std::string(VASCSIM_EXE) + " sweep " + sweep + " --out " + out +
                                    " --jobs 2 --no-merge & pid=$!; "
                                    "until [ -s " + out + "/runs/0000/frames.vlog ] && [ -s " + out + "/runs/0001/frames.vlog ] || "
                                    "! kill -0 $pid 2>/dev/null; do sleep 0.01; done; "
                                    "kill -KILL $pid; wait $pid; echo \"exit code $?\"; "
                                    // Both locks free within 20 s: the runs have ended.
                                    "for i in $(seq 200); do flock -n " + out + "/runs/0000/.lock true && flock -n " + out +
                                    "/runs/0001/.lock true && { echo unlocked; break; }; sleep 0.1; done; }");
  ASSERT_TRUE(has(r.output, "exit code 137")) << r.output;
  ASSERT_TRUE(has(r.output, "unlocked")) << r.output;
  // Nothing writes the logs any more (an orphan would: 1000 s of maze take minutes).
  const auto size0 = fs::file_size(out + "/runs/0000/frames.vlog"), size1 = fs::file_size(out + "/runs/0001/frames.vlog");
  ::usleep(500000);
  EXPECT_EQ(fs::file_size(out + "/runs/0000/frames.vlog"), size0);
  EXPECT_EQ(fs::file_size(out + "/runs/0001/frames.vlog"), size1);
  EXPECT_FALSE(fs::exists(out + "/runs/0000/status.json")) << "a run the sweep did not see end is not recorded";
}

// Stopped while it writes the sweep directory (thousands of run scenes), a sweep says what it
// left and how to go on, instead of ending silently; the same command then completes it.
TEST(SweepCli, StoppedWhileWritingItsDirectorySaysSoAndIsTakenUpAgain) {
  const std::string dir = fresh_temp_dir("sweep_stopped_writing");
  const std::string sweep = write_maze_sweep(dir, "seeds", R"({"/maze/seed": {"from": 1, "to": 4000}})", 0.3);
  const std::string out = dir + "/out";
  const std::string command = std::string(VASCSIM_EXE) + " sweep " + sweep + " --out " + out + " --emit gnu-parallel";
  const CommandResult r = run_shell("{ " + command + " & pid=$!; until [ -e " + out + "/runs ] || ! kill -0 $pid 2>/dev/null; "
                                    "do sleep 0.01; done; kill -TERM $pid; wait $pid; echo \"exit code $?\"; }");
  ASSERT_FALSE(fs::exists(out + "/manifest.json")) << "the sweep wrote its directory before the signal; make it larger\n" << r.output;
  EXPECT_TRUE(has(r.output, "exit code 143")) << r.output;
  EXPECT_TRUE(has(r.output, "vascsim sweep: interrupted while writing the sweep directory " + out +
                                "; the same command takes it up again")) << r.output;
  const CommandResult again = run_shell(command);
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_TRUE(has(again.output, "sweep seeds: 4000 runs in " + out + " (resuming)")) << again.output;
  EXPECT_TRUE(fs::exists(out + "/runs/3999/scene.json"));
}

TEST(SweepCli, ShowsProgressWithCountsAndAnEtaOnATerminalOnly) {
  const std::string dir = fresh_temp_dir("sweep_progress");
  const std::string sweep = write_maze_sweep(dir, "kp", kAxes, 0.3);
  // script (util-linux) gives the sweep a terminal.
  const CommandResult tty = run_shell("script -qec '" + std::string(VASCSIM_EXE) + " sweep " + sweep + " --out " + dir +
                                      "/tty --jobs 2 --no-merge' /dev/null");
  ASSERT_EQ(tty.exit_code, 0) << tty.output;
  EXPECT_TRUE(has(tty.output, "\r  sweep: 8/8 finished, 0 failed, 0 running, elapsed ")) << tty.output;
  EXPECT_TRUE(has(tty.output, "ETA ")) << tty.output;
  const CommandResult pipe = sweep_command(sweep + " --out " + dir + "/pipe --jobs 2 --no-merge");
  ASSERT_EQ(pipe.exit_code, 0) << pipe.output;
  EXPECT_FALSE(has(pipe.output, "ETA")) << pipe.output;
}

TEST(SweepCli, RunIndexAndShardSelectEntries) {
  const std::string dir = fresh_temp_dir("sweep_select");
  const std::string sweep = write_maze_sweep(dir, "kp", kAxes, 0.3);
  ASSERT_EQ(sweep_command(sweep + " --out " + dir + "/out --emit gnu-parallel").exit_code, 0);  // makes DIR, runs nothing
  EXPECT_FALSE(fs::exists(dir + "/out/runs/0000/summary.json"));
  // A merge before any run: the table has the maze scene's columns, not the free-space ones
  // (chosen from runs' figures, there were none).
  const CommandResult early = sweep_command("merge " + dir + "/out --no-plots");
  ASSERT_EQ(early.exit_code, 0) << early.output;
  EXPECT_TRUE(has(early.output, "8 runs: 0 done, 0 failed, 8 missing")) << early.output;
  EXPECT_TRUE(has(early.output, "tip error RMS (mm)")) << early.output;
  EXPECT_FALSE(has(early.output, "Newton iterations")) << early.output;
  for (const char* merged : {"/out/results.csv", "/out/results.json"}) fs::remove(dir + merged);
  const CommandResult one = sweep_command(dir + "/out --run-index 6");
  ASSERT_EQ(one.exit_code, 0) << one.output;
  EXPECT_TRUE(has(one.output, "run 0006: done")) << one.output;
  EXPECT_TRUE(fs::exists(dir + "/out/runs/0006/summary.json"));
  EXPECT_FALSE(fs::exists(dir + "/out/runs/0005/summary.json"));
  const CommandResult twice = sweep_command(dir + "/out --run-index 6");
  EXPECT_EQ(twice.exit_code, 0) << twice.output;
  EXPECT_TRUE(has(twice.output, "run 0006: completed before; skipped")) << twice.output;
  const CommandResult beyond = sweep_command(dir + "/out --run-index 8");
  EXPECT_EQ(beyond.exit_code, 2) << beyond.output;
  EXPECT_TRUE(has(beyond.output, "--run-index: expected an integer in [0, 7], got '8'")) << beyond.output;

  const CommandResult shard = sweep_command(dir + "/out --shard 1/3 --no-merge");
  ASSERT_EQ(shard.exit_code, 0) << shard.output;
  EXPECT_TRUE(has(shard.output, "ran 3 of 3 runs (0 completed before")) << shard.output;  // 1, 4, 7
  for (int i = 0; i < 8; ++i)
    EXPECT_EQ(fs::exists(dir + "/out/runs/000" + std::to_string(i) + "/summary.json"), i % 3 == 1 || i == 6) << i;
  for (const char* bad : {"3/3", "' 0/3'", "+0/3", "0/3x", "0/0"})
    EXPECT_EQ(sweep_command(dir + "/out --shard " + bad).exit_code, 2) << bad;

  // Merging now: the runs not yet made are rows that say so.
  const CommandResult merge = sweep_command("merge " + dir + "/out --no-plots");
  ASSERT_EQ(merge.exit_code, 0) << merge.output;
  EXPECT_TRUE(has(merge.output, "8 runs: 4 done, 0 failed, 4 missing")) << merge.output;
  const std::string csv = read_text(dir + "/out/results.csv");
  EXPECT_EQ(csv_cell(csv, 0, "status"), "missing");
  EXPECT_EQ(csv_cell(csv, 1, "status"), "done");
  EXPECT_EQ(parse_csv(csv).size(), 9u);
  const CommandResult refused = sweep_command("merge " + dir + "/out --no-plots");
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_TRUE(has(refused.output, "results.csv: already exists (pass --force")) << refused.output;
  EXPECT_EQ(sweep_command("merge " + dir + "/out --no-plots --force").exit_code, 0);
}

TEST(SweepCli, EmitsGnuParallelAndSlurmFiles) {
  const std::string dir = fresh_temp_dir("sweep_emit");
  const std::string sweep = write_maze_sweep(dir, "kp", kAxes, 0.3);
  const std::string out = dir + "/out";
  write_text(dir + "/hosts", "# the lab's nodes\n4/node1\n");
  const CommandResult p = sweep_command(sweep + " --out " + out + " --emit gnu-parallel --jobs 2 --sshloginfile " + dir + "/hosts");
  ASSERT_EQ(p.exit_code, 0) << p.output;
  EXPECT_EQ(read_text(out + "/parallel/jobs.txt"), "0\n1\n2\n3\n4\n5\n6\n7\n");
  const std::string script = read_text(out + "/parallel/run.sh");
  EXPECT_TRUE(has(script, "exec parallel --jobs 2 --joblog " + out + "/parallel/joblog --resume --sshloginfile " + dir +
                              "/hosts --arg-file " + out + "/parallel/jobs.txt '" + std::string(VASCSIM_EXE) + " sweep " + out +
                              " --run-index {}'"))
      << script;
  EXPECT_EQ(sweep_command(out + " --emit gnu-parallel").exit_code, 2) << "emitted files are not replaced without --force";
  EXPECT_EQ(sweep_command(out + " --emit gnu-parallel --force").exit_code, 0);

  const CommandResult s = sweep_command(out + " --emit slurm --max-parallel 2 --partition debug --time 0:10:00");
  ASSERT_EQ(s.exit_code, 0) << s.output;
  const std::string array = read_text(out + "/slurm/array.sbatch");
  EXPECT_TRUE(has(array, "#SBATCH --array=0-7%2\n")) << array;
  EXPECT_TRUE(has(array, "#SBATCH --output=" + out + "/slurm/logs/run_%A_%a.out\n")) << array;
  EXPECT_TRUE(has(array, "#SBATCH --partition=debug\n#SBATCH --time=0:10:00\n")) << array;
  EXPECT_TRUE(has(array, "exec " + std::string(VASCSIM_EXE) + " sweep " + out + " --run-index \"$index\"")) << array;
  EXPECT_TRUE(has(read_text(out + "/slurm/merge.sbatch"), "sweep merge " + out + " --force")) << read_text(out + "/slurm/merge.sbatch");
  const std::string submit = read_text(out + "/slurm/submit.sh");
  EXPECT_TRUE(has(submit, "--dependency=\"$dependency\"")) << submit;
  EXPECT_TRUE(has(submit, "dependency=afterany")) << submit;

  // A value that would end its #SBATCH line (and add a directive) is refused, before any file.
  const CommandResult injected = sweep_command(sweep + " --out " + dir + "/injected --emit slurm --partition \"$(printf 'debug\\n#SBATCH --wrap=x')\"");
  EXPECT_EQ(injected.exit_code, 2) << injected.output;
  EXPECT_TRUE(has(injected.output, "--partition: expected partition names")) << injected.output;
  EXPECT_FALSE(fs::exists(dir + "/injected")) << "a refused emit made the sweep directory";
  // --time as sbatch reads it (UNLIMITED and -1 included), not any run of digits, ':' and '-';
  // an option of another way of running is refused, not ignored.
  for (const char* time : {"1-", "1:2:3:4", "--5", "soon"}) {
    const CommandResult t = sweep_command(sweep + " --out " + dir + "/timed --emit slurm --time '" + time + "'");
    EXPECT_EQ(t.exit_code, 2) << time << ": " << t.output;
    EXPECT_TRUE(has(t.output, "--time: expected a Slurm time")) << time << ": " << t.output;
  }
  EXPECT_EQ(sweep_command(sweep + " --out " + dir + "/timed --emit slurm --time ''").exit_code, 2);
  EXPECT_EQ(sweep_command(sweep + " --out " + dir + "/unlimited --emit slurm --time UNLIMITED").exit_code, 0);
  const CommandResult jobs = sweep_command(sweep + " --out " + dir + "/jobs --emit slurm --jobs 3");
  EXPECT_EQ(jobs.exit_code, 2) << jobs.output;
  EXPECT_TRUE(has(jobs.output, "--jobs goes with a local run or --emit gnu-parallel, not with --emit slurm")) << jobs.output;
  const CommandResult partition = sweep_command(sweep + " --out " + dir + "/partition --emit gnu-parallel --partition x");
  EXPECT_EQ(partition.exit_code, 2) << partition.output;
  EXPECT_FALSE(fs::exists(dir + "/jobs")) << "a refused emit made the sweep directory";
  // A name with a space is one word in #SBATCH --job-name.
  const std::string spaced = write_maze_sweep(dir, "spaced", kAxes, 0.3, R"(, "name": "kp sweep")");
  ASSERT_EQ(sweep_command(spaced + " --out " + dir + "/spaced --emit slurm").exit_code, 0);
  EXPECT_TRUE(has(read_text(dir + "/spaced/slurm/array.sbatch"), "#SBATCH --job-name=vascsim-kp_sweep\n"));
}

// run.sh runs later, maybe from another directory: a host list parallel would not find there, or
// that names no host, is refused at --emit, before any file, with the file's name.
TEST(SweepCli, GnuParallelHostListIsCheckedWhenEmitted) {
  const std::string dir = fresh_temp_dir("sweep_hosts");
  const std::string sweep = write_maze_sweep(dir, "kp", R"({"/control/kp": [1, 2]})", 0.3);
  const auto emit = [&](const std::string& out, const std::string& hosts, const std::string& env = "") {
    return run_shell("cd " + dir + " && " + env + " " + std::string(VASCSIM_EXE) + " sweep " + sweep + " --out " + out +
                     " --emit gnu-parallel --sshloginfile " + hosts);
  };
  const CommandResult missing = emit("missing", "nodes.txt", "PARALLEL_HOME=" + dir + "/config");
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_TRUE(has(missing.output, "--sshloginfile nodes.txt: " + dir + "/nodes.txt does not exist (parallel's config directory")) << missing.output;
  EXPECT_FALSE(fs::exists(dir + "/missing")) << "a refused emit made the sweep directory";

  write_text(dir + "/comments.txt", "# none yet\n\n   # indented comment\n  \n");
  const CommandResult empty = emit("empty", "comments.txt");
  EXPECT_EQ(empty.exit_code, 2) << empty.output;
  EXPECT_TRUE(has(empty.output, dir + "/comments.txt lists no host")) << empty.output;
  const CommandResult stdin_list = emit("stdin", "-");
  EXPECT_EQ(stdin_list.exit_code, 2) << stdin_list.output;
  EXPECT_TRUE(has(stdin_list.output, "standard input is not a host list")) << stdin_list.output;
  EXPECT_EQ(emit("directory", dir).exit_code, 2);
  EXPECT_FALSE(fs::exists(dir + "/empty") || fs::exists(dir + "/stdin") || fs::exists(dir + "/directory"));

  // Found where parallel looks: this directory (named absolutely in run.sh), then its config
  // directory; '..' is the config directory's sshloginfile.
  fs::create_directories(dir + "/config");
  write_text(dir + "/config/nodes.txt", "2/node7\n");
  write_text(dir + "/config/sshloginfile", "node8\n");
  ASSERT_EQ(emit("out_config", "nodes.txt", "PARALLEL_HOME=" + dir + "/config").exit_code, 0);
  EXPECT_TRUE(has(read_text(dir + "/out_config/parallel/run.sh"), "--sshloginfile " + dir + "/config/nodes.txt "));
  ASSERT_EQ(emit("out_shorthand", "..", "PARALLEL_HOME=" + dir + "/config").exit_code, 0);
  EXPECT_TRUE(has(read_text(dir + "/out_shorthand/parallel/run.sh"), "--sshloginfile " + dir + "/config/sshloginfile "));
  write_text(dir + "/nodes.txt", "node9\n");
  ASSERT_EQ(emit("out_here", "nodes.txt", "PARALLEL_HOME=" + dir + "/config").exit_code, 0);
  EXPECT_TRUE(has(read_text(dir + "/out_here/parallel/run.sh"), "--sshloginfile " + dir + "/nodes.txt "));
}

TEST(SweepCli, SlurmArraysLongerThanAChunkAreSplitWithOffsets) {
  const std::string dir = fresh_temp_dir("sweep_chunks");
  const std::string sweep = write_maze_sweep(dir, "seeds", R"({"/maze/seed": {"from": 1, "to": 2500}})", 0.3);
  const CommandResult s = sweep_command(sweep + " --out " + dir + "/out --emit slurm --max-parallel 50");
  ASSERT_EQ(s.exit_code, 0) << s.output;
  const std::string submit = read_text(dir + "/out/slurm/submit.sh");
  EXPECT_TRUE(has(submit, "--array=0-999%50 --export=ALL,VASCSIM_SWEEP_OFFSET=0 ")) << submit;
  // Each array after the first waits for the one before: Slurm throttles each array alone.
  EXPECT_TRUE(has(submit, "--array=0-999%50 --dependency=afterany:\"${ids[-1]}\" --export=ALL,VASCSIM_SWEEP_OFFSET=1000 ")) << submit;
  EXPECT_TRUE(has(submit, "--array=0-499%50 --dependency=afterany:\"${ids[-1]}\" --export=ALL,VASCSIM_SWEEP_OFFSET=2000 ")) << submit;
  EXPECT_TRUE(fs::exists(dir + "/out/runs/2499/scene.json"));
}

TEST(SweepCli, BadInputIsRefusedBeforeAnythingIsWritten) {
  const std::string dir = fresh_temp_dir("sweep_bad");
  const std::string sweep = write_maze_sweep(dir, "bad", R"({"/control/kp": [2, 4], "/maze/sede": [1, 2]})", 0.3);
  const CommandResult r = sweep_command(sweep + " --out " + dir + "/out");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_TRUE(has(r.output, sweep + ": /axes/~1maze~1sede: the scene " + source_path("scenes/maze_default.json") +
                                " has no field /maze/sede (fields of /maze: "))
      << r.output;
  EXPECT_FALSE(fs::exists(dir + "/out"));

  const std::string value = write_maze_sweep(dir, "value", R"({"/maze/rows": [5, 0]})", 0.3);
  const CommandResult v = sweep_command(value + " --out " + dir + "/out");
  EXPECT_EQ(v.exit_code, 2) << v.output;
  EXPECT_TRUE(has(v.output, value + ": run 0001 (/maze/rows = 0): ")) << v.output;
  EXPECT_TRUE(has(v.output, "/maze/rows: expected an integer in [1, 200], got 0")) << v.output;
  EXPECT_FALSE(fs::exists(dir + "/out"));

  // A sweep file that cannot be opened says why, and nothing is made.
  const CommandResult absent = sweep_command(dir + "/absent.json --out " + dir + "/out");
  EXPECT_EQ(absent.exit_code, 2) << absent.output;
  EXPECT_TRUE(has(absent.output, dir + "/absent.json: cannot open sweep file (No such file or directory)")) << absent.output;
  EXPECT_FALSE(fs::exists(dir + "/out"));

  // Somebody's folder is never used; another sweep's needs --force.
  fs::create_directories(dir + "/mine");
  write_text(dir + "/mine/notes.txt", "mine");
  const CommandResult mine = sweep_command(write_maze_sweep(dir, "good", R"({"/control/kp": [2]})", 0.3) + " --out " + dir + "/mine");
  EXPECT_EQ(mine.exit_code, 2) << mine.output;
  EXPECT_TRUE(has(mine.output, "is not empty and holds no sweep")) << mine.output;
  EXPECT_EQ(read_text(dir + "/mine/notes.txt"), "mine");
  ASSERT_EQ(sweep_command(dir + "/good.json --out " + dir + "/s --quiet").exit_code, 0);
  const std::string other = write_maze_sweep(dir, "other", R"({"/control/kp": [3]})", 0.3);
  const CommandResult differs = sweep_command(other + " --out " + dir + "/s");
  EXPECT_EQ(differs.exit_code, 2) << differs.output;
  EXPECT_TRUE(has(differs.output, "holds a different sweep")) << differs.output;
  EXPECT_TRUE(fs::exists(dir + "/s/runs/0000/summary.json"));
  EXPECT_EQ(sweep_command(other + " --out " + dir + "/s --force --quiet").exit_code, 0);
  EXPECT_TRUE(has(read_text(dir + "/s/manifest.json"), "\"/control/kp\":3"));

  EXPECT_EQ(sweep_command(dir + "/nothing.json --out " + dir + "/x").exit_code, 2);
  EXPECT_EQ(sweep_command(dir + "/s --shard 1").exit_code, 2);
  EXPECT_EQ(sweep_command(dir + "/s --emit condor").exit_code, 2);
  EXPECT_EQ(sweep_command("merge " + dir + "/mine").exit_code, 2);
}

// A run's scene edited by hand, then resumed through the directory: it ran the edited scene and
// filed its results under the manifest's value (through the sweep file it was refused).
TEST(SweepCli, AnEditedRunSceneIsRefusedOnResume) {
  const std::string dir = fresh_temp_dir("sweep_edited");
  const std::string sweep = write_maze_sweep(dir, "kp", R"({"/control/kp": [2, 4]})", 0.3);
  const std::string out = dir + "/out";
  ASSERT_EQ(sweep_command(sweep + " --out " + out + " --emit gnu-parallel").exit_code, 0);
  const std::string scene = out + "/runs/0001/scene.json", original = read_text(scene);
  const std::size_t kp = original.find("\"kp\": 4");
  ASSERT_NE(kp, std::string::npos) << original;
  write_text(scene, original.substr(0, kp) + "\"kp\": 3" + original.substr(kp + 7));
  for (const std::string& command : {out, out + " --run-index 1"}) {
    const CommandResult r = sweep_command(command);
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.output;
    EXPECT_TRUE(has(r.output, scene + ": changed since the sweep wrote it")) << r.output;
  }
  EXPECT_FALSE(fs::exists(out + "/runs/0000/summary.json")) << "nothing runs before the check";
  write_text(scene, original);
  EXPECT_EQ(sweep_command(out + " --quiet").exit_code, 0);
}

// A sweep stopped while it wrote its run directories (the manifest comes last) left a directory
// that it then refused as "somebody's folder", even with --force. The program's own leftovers
// are taken up by the same sweep, by another one with --force; a user's file among them still
// makes the directory somebody's.
TEST(SweepCli, ASweepStoppedBeforeItsManifestIsTakenUpAgain) {
  const std::string dir = fresh_temp_dir("sweep_unfinished");
  const std::string sweep = write_maze_sweep(dir, "kp", R"({"/control/kp": [2, 4]})", 0.3);
  const std::string out = dir + "/out";
  // What the stopped sweep left: its copy of the sweep file, one run's scene (cut short), a
  // temporary of a process that no longer runs.
  fs::create_directories(out + "/runs/0000");
  fs::copy_file(sweep, out + "/sweep.json");
  write_text(out + "/runs/0000/scene.json", "{\"rod\": {");
  const std::string temporary = temporary_sibling(out + "/runs/0000/scene.json");  // ...-HOST-PID
  write_text(temporary.substr(0, temporary.rfind('-') + 1) + "999999999", "{");  // beyond any pid
  const CommandResult r = sweep_command(sweep + " --out " + out + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(out + "/manifest.json"));
  EXPECT_TRUE(fs::exists(out + "/runs/0001/summary.json"));
  EXPECT_NE(read_text(out + "/runs/0000/scene.json"), "{\"rod\": {");

  const std::string other = write_maze_sweep(dir, "other", R"({"/control/kp": [3]})", 0.3);
  fs::remove_all(out + "/runs/0001");
  fs::remove(out + "/manifest.json");
  for (const char* name : {"runs/0000/summary.json", "runs/0000/status.json", "runs/0000/frames.vlog", "runs/0000/run.log",
                           "runs/0000/.lock", "results.csv", "results.json"})
    fs::remove(out + "/" + name);
  fs::remove_all(out + "/plots");
  const CommandResult refused = sweep_command(other + " --out " + out);
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_TRUE(has(refused.output, out + ": holds the start of another sweep, stopped before its manifest.json was written"))
      << refused.output;
  ASSERT_EQ(sweep_command(other + " --out " + out + " --force --quiet").exit_code, 0);
  EXPECT_TRUE(has(read_text(out + "/manifest.json"), "\"/control/kp\":3"));

  fs::remove_all(out);
  fs::create_directories(out + "/runs/0000");
  fs::copy_file(sweep, out + "/sweep.json");
  write_text(out + "/runs/0000/notes.txt", "mine");
  const CommandResult mine = sweep_command(sweep + " --out " + out + " --force");
  EXPECT_EQ(mine.exit_code, 2) << mine.output;
  EXPECT_TRUE(has(mine.output, "is not empty and holds no sweep")) << mine.output;
  EXPECT_EQ(read_text(out + "/runs/0000/notes.txt"), "mine");
}

// Two runners on one directory: the one that ends last sees the other's runs ended and exits 0
// (it merged a complete table and exited 1, "being run by another process", before).
TEST(SweepCli, ARunnerThatEndsAfterAnotherOnOneDirectoryExitsZero) {
  const std::string dir = fresh_temp_dir("sweep_two_runners");
  const std::string sweep = dir + "/two.json";
  write_text(sweep, R"({"format": "vascsim-sweep/1", "scene": ")" + source_path("scenes/maze_default.json") +
                        R"(", "axes": {"/run/duration": [0.3, 30]}})");
  const std::string out = dir + "/out", exe = VASCSIM_EXE;
  ASSERT_EQ(sweep_command(sweep + " --out " + out + " --emit gnu-parallel").exit_code, 0);
  // The other runner holds entry 0's lock (flock(1), as a runner does) until the sweep has found
  // it held, then runs entry 0 (0.3 s simulated) while the sweep runs entry 1 (30 s simulated).
  // (Every wait also ends when the process it waits on has, so a failure fails, never hangs.)
  const std::string other = "touch " + dir + "/locked; until grep -q 'being run by another process' " + dir +
                            "/second.err 2>/dev/null || [ -e " + dir + "/second.done ]; do sleep 0.01; done; " + exe + " run " + out +
                            "/runs/0000/scene.json --out " + out + "/runs/0000 --force --quiet";
  const CommandResult r = run_shell("{ flock " + out + "/runs/0000/.lock sh -c \"" + other + "\" & holder=$!; until [ -e " + dir +
                                    "/locked ] || ! kill -0 $holder 2>/dev/null; do sleep 0.005; done; " + exe + " sweep " + out + " --jobs 1 --no-merge 2>" +
                                    dir + "/second.err; echo \"second exit code $?\"; touch " + dir + "/second.done; wait $holder; echo \"other exit code $?\"; "
                                    "cat " + dir + "/second.err; }");
  EXPECT_TRUE(has(r.output, "other exit code 0")) << r.output;
  EXPECT_TRUE(has(r.output, "run 0000 is being run by another process; skipped")) << r.output;
  EXPECT_TRUE(has(r.output, "ran 1 of 2 runs")) << r.output;
  EXPECT_TRUE(fs::exists(out + "/runs/0000/summary.json"));
  EXPECT_TRUE(has(r.output, "second exit code 0")) << r.output;
}

}  // namespace
}  // namespace vascsim::test

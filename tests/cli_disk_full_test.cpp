// `vascsim run` onto a full disk (a small tmpfs, as root; tests/tmpfs_support.h): it stops with
// exit 2 and a message naming the log and the system's reason, the log keeps every frame it
// completed and renders to the last of them, and nothing partial stands under a final name; a
// sweep whose run meets a full disk says how the run ended.
#include <gtest/gtest.h>

#include <filesystem>

#include "sim/log/frame_log.h"
#include "tests/cli_test_support.h"
#include "tests/tmpfs_support.h"

namespace vascsim::test {
namespace {

namespace fs = std::filesystem;

// About 2 kB a frame for 5000 frames: a 96 kB disk fills after a few dozen.
const char* const kBigLogScene = R"({"maze": null, "rod": {"nodes": 20}, "run": {"duration": 5, "output_interval": 0.001}})";

TEST(DiskFull, RunStopsWithExit2AndKeepsEveryCompletedFrame) {
  SmallTmpfs disk("run", 96 * 1024);
  ASSERT_TRUE(disk.ok()) << disk.error();
  const std::string dir = fresh_temp_dir("disk_full_run");
  write_text(dir + "/scene.json", kBigLogScene);
  const std::string out = disk.path() + "/run";
  const CommandResult r = run_vascsim("run " + dir + "/scene.json --out " + out + " --quiet");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(out + "/frames.vlog: cannot write"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("No space left on device"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;

  // Every complete frame is there, in order; a torn last record is not counted.
  FrameLogReader log(out + "/frames.vlog");
  const std::size_t n = log.frame_count();
  ASSERT_GE(n, 5u);
  EXPECT_LT(n, 5001u);
  EXPECT_DOUBLE_EQ(log.time_of(n - 1), 0.001 * static_cast<double>(n - 1));
  // No summary claims a result, and no temporary file is left behind.
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_EQ(e.path().filename(), "frames.vlog") << "unexpected " << e.path();
  fs::remove_all(dir);
}

// A sweep's run on a full disk: its run.log could not take its message, nor its directory the
// status; the sweep said only "status.json: cannot write". It now says how the run ended.
TEST(DiskFull, ASweepSaysHowTheRunEndedWhenItsStatusCannotBeWritten) {
  SmallTmpfs disk("sweep", 96 * 1024);
  ASSERT_TRUE(disk.ok()) << disk.error();
  const std::string dir = fresh_temp_dir("disk_full_sweep");
  write_text(dir + "/scene.json", kBigLogScene);
  write_text(dir + "/sweep.json", R"({"format": "vascsim-sweep/1", "scene": "scene.json", "axes": {"/rod/length": [0.4]}})");
  const CommandResult r = run_vascsim("sweep " + dir + "/sweep.json --out " + disk.path() + "/out --quiet");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("run 0000 ended with exit code 2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("status.json: cannot write (No space left on device)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("running the sweep again repeats it"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

// An export onto a full disk: the small tip/error.csv fits, position.csv does not. The export
// fails naming the file, and leaves none of its files (tip_error.csv was left, so the export was
// half done and retrying it needed --force) and no temporary.
TEST(DiskFull, AnExportLeavesAllItsFilesOrNone) {
  SmallTmpfs disk("export", 96 * 1024);
  ASSERT_TRUE(disk.ok()) << disk.error();
  const std::string dir = fresh_temp_dir("disk_full_export");
  write_text(dir + "/scene.json", R"({"maze": {"seed": 4}, "rod": {"nodes": 20}, "run": {"duration": 0.5, "output_interval": 0.001}})");
  ASSERT_EQ(run_vascsim("run " + dir + "/scene.json --out " + dir + "/run --quiet").exit_code, 0);
  const std::string csv = disk.path() + "/csv";
  fs::create_directory(csv);
  const CommandResult r = run_vascsim("export " + dir + "/run --csv " + csv + " --channels tip/error,position");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(csv + "/position.csv: cannot write (No space left on device)"), std::string::npos) << r.output;
  for (const auto& e : fs::directory_iterator(csv)) ADD_FAILURE() << "left behind: " << e.path();
  fs::remove_all(dir);
}

// Standard output on a full disk: a maze's JSON or a run's result line lost is an error, not
// exit 0 with nothing written (stdout to a file is buffered until exit).
TEST(DiskFull, AFullStandardOutputIsAnError) {
  const std::string dir = fresh_temp_dir("disk_full_stdout");
  // The braces keep run_shell's own 2>&1 from sending the error message to /dev/full as well.
  CommandResult r = run_shell("{ " + std::string(VASCSIM_EXE) + " maze --seed 3 --out - 2>&1 >/dev/full; }");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("vascsim maze: cannot write to standard output (No space left on device)"), std::string::npos)
      << r.output;
  write_text(dir + "/scene.json", R"({"maze": null, "rod": {"nodes": 8}, "run": {"duration": 0.01}})");
  r = run_shell("{ " + std::string(VASCSIM_EXE) + " run " + dir + "/scene.json --out " + dir + "/run 2>&1 >/dev/full; }");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("vascsim run: cannot write to standard output"), std::string::npos) << r.output;
  // The same commands to a working standard output succeed.
  EXPECT_EQ(run_shell(std::string(VASCSIM_EXE) + " maze --seed 3 --out - >/dev/null").exit_code, 0);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vascsim::test

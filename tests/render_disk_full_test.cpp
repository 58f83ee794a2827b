// `vascsim render` (video, PNG sequence, plots) onto a full disk (a small tmpfs, as root;
// tests/tmpfs_support.h), with the space running out at many points (the video's header, its
// frames, its trailer and index; the n-th PNG; the n-th plot): each time exit 2 with a message
// naming the output and the system's reason, or success if it fitted; never a partial file under
// a final name, and no temporary file left behind. And a log cut short by a full disk renders
// to its last complete frame.
#include <gtest/gtest.h>

#include <fstream>

#include "render/video_encoder.h"
#include "render_test_util.h"
#include "sim/io/png_file.h"
#include "sim/log/frame_log.h"
#include "tests/tmpfs_support.h"

namespace vascsim::render {
namespace {

using test::SmallTmpfs;
using testing::ScratchDir;
namespace fs = std::filesystem;

constexpr int kFrames = 31;  // 0 .. 3 s at 10 fps
const char* kView = " --width 320 --height 240 --fps 10 ";

// Leaves `free` bytes free on `disk` with a filler file (tmpfs counts whole pages).
void leave_free(const SmallTmpfs& disk, std::size_t free) {
  const std::size_t now = disk.free_bytes();
  ASSERT_GT(now, free);
  std::ofstream filler(disk.path() + "/filler", std::ios::binary);
  const std::string block(now - free, 'x');
  filler.write(block.data(), static_cast<std::streamsize>(block.size()));
  ASSERT_TRUE(filler.good()) << "cannot fill " << disk.path();
}

void empty(const SmallTmpfs& disk) {
  for (const auto& e : fs::directory_iterator(disk.path())) fs::remove_all(e.path());
}

// Files under `dir` other than the filler: each a complete output of its kind, none hidden.
void expect_no_partial_outputs(const std::string& dir, const std::string& context) {
  SCOPED_TRACE(context);
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (e.is_directory() || name == "filler") continue;
    EXPECT_NE(name[0], '.') << "a temporary file was left behind: " << e.path();
    if (e.path().extension() == ".png") {
      try {
        io::read_png(e.path().string(), 3);
      } catch (const std::exception& ex) {
        ADD_FAILURE() << e.path() << " is not a complete PNG: " << ex.what();
      }
    } else if (e.path().extension() == ".mp4") {
      EXPECT_EQ(probe_video(e.path().string()).frames, kFrames) << e.path();
    } else {
      ADD_FAILURE() << "unexpected file " << e.path();
    }
  }
}

// The command failed cleanly for want of space, or fitted.
void expect_clean_exit(const testing::CommandResult& r, const std::string& context) {
  if (r.exit_code == 0) return;
  EXPECT_EQ(r.exit_code, 2) << context << ": " << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << context << ": " << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << context << ": " << r.err;
}

SyntheticLogSpec three_seconds() {
  SyntheticLogSpec spec;
  spec.frames = 31;
  spec.duration = 3.0;
  return spec;
}

TEST(DiskFull, VideoAndPngSequenceNeverLeavePartialFiles) {
  SmallTmpfs disk("render", 1024 * 1024);
  ASSERT_TRUE(disk.ok()) << disk.error();
  ScratchDir dir("disk_full_render");
  const std::string run = testing::make_run(dir, three_seconds());
  int failures = 0, fits = 0;
  // From no room for the video's header to room for all of it.
  for (std::size_t free_kb : {4, 12, 24, 40, 64, 96, 160, 256}) {
    empty(disk);
    leave_free(disk, free_kb * 1024);
    const std::string context = "--mp4 with " + std::to_string(free_kb) + " kB free";
    const auto r = testing::run_vascsim("render '" + run + "'" + kView + "--mp4 '" + disk.path() + "/out.mp4'", dir);
    expect_clean_exit(r, context);
    if (r.exit_code != 0) {
      EXPECT_NE(r.err.find(disk.path() + "/out.mp4"), std::string::npos) << r.err;
    }
    EXPECT_EQ(fs::exists(disk.path() + "/out.mp4"), r.exit_code == 0) << context;
    expect_no_partial_outputs(disk.path(), context);
    (r.exit_code == 0 ? fits : failures)++;
  }
  EXPECT_GT(failures, 0) << "no size was small enough to fail: the test tested nothing";
  for (std::size_t free_kb : {8, 48, 200}) {
    empty(disk);
    leave_free(disk, free_kb * 1024);
    const std::string context = "--png-dir with " + std::to_string(free_kb) + " kB free";
    const auto r = testing::run_vascsim("render '" + run + "'" + kView + "--png-dir '" + disk.path() + "/png'", dir);
    expect_clean_exit(r, context);
    EXPECT_NE(r.exit_code, 0) << context << ": 31 frames of 320 x 240 do not fit";
    EXPECT_NE(r.err.find(disk.path() + "/png/frame_"), std::string::npos) << r.err;
    expect_no_partial_outputs(disk.path(), context);
  }
}

TEST(DiskFull, PlotsNeverLeavePartialFiles) {
  SmallTmpfs disk("plots", 1024 * 1024);
  ASSERT_TRUE(disk.ok()) << disk.error();
  ScratchDir dir("disk_full_plots");
  const std::string run = testing::make_run(dir, three_seconds());
  int failures = 0;
  for (std::size_t free_kb : {8, 20, 40, 80, 160}) {
    empty(disk);
    leave_free(disk, free_kb * 1024);
    const std::string context = "--plots with " + std::to_string(free_kb) + " kB free";
    const auto r = testing::run_vascsim("render '" + run + "' --plots '" + disk.path() + "/plots'", dir);
    expect_clean_exit(r, context);
    if (r.exit_code != 0) {
      ++failures;
      EXPECT_NE(r.err.find(disk.path() + "/plots/"), std::string::npos) << r.err;
    }
    expect_no_partial_outputs(disk.path(), context);
  }
  EXPECT_GT(failures, 0) << "no size was small enough to fail: the test tested nothing";
}

TEST(DiskFull, LogCutShortByAFullDiskRendersToItsLastCompleteFrame) {
  SmallTmpfs disk("run_render", 96 * 1024);
  ASSERT_TRUE(disk.ok()) << disk.error();
  ScratchDir dir("disk_full_run_render");
  {
    std::ofstream(dir / "scene.json")
        << R"({"maze": null, "rod": {"nodes": 20}, "run": {"duration": 5, "output_interval": 0.01}})";
  }
  const std::string out = disk.path() + "/run";
  auto r = testing::run_vascsim("run '" + (dir / "scene.json") + "' --out '" + out + "' --quiet", dir);
  ASSERT_EQ(r.exit_code, 2) << r.err;
  const std::size_t n = FrameLogReader(out + "/frames.vlog").frame_count();
  ASSERT_GE(n, 2u);
  // One video frame per logged frame (100 fps at 0.01 s), to the last complete one.
  r = testing::run_vascsim("render '" + out + "' --width 64 --height 48 --fps 100 --png-dir '" + (dir / "png") + "'", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::size_t frames = 0;
  for (const auto& e : fs::directory_iterator(dir / "png")) frames += e.path().extension() == ".png";
  EXPECT_EQ(frames, n);
}

}  // namespace
}  // namespace vascsim::render

// The render and diff commands through the executable: outputs appear, bad input (missing or
// truncated log, unwritable destination, bad options) exits 2 with a message naming the
// problem and leaves no file under a final name, and existing outputs need --force.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>

#include <nlohmann/json.hpp>

#include "render/image_diff.h"
#include "render/png_writer.h"
#include "sim/log/frame_log.h"
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>
#include "render_test_util.h"
#include "tests/png_bytes_support.h"

namespace vascsim::render {
namespace {

using testing::run_vascsim;
using testing::ScratchDir;
namespace fs = std::filesystem;

const char* kSmall = " --width 160 --height 120 --fps 5 ";

bool has_final_outputs(const fs::path& dir) {
  if (!fs::exists(dir)) return false;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (ext == ".mp4" || ext == ".png" || ext == ".webm") return true;
  }
  return false;
}

TEST(RenderCli, WritesMp4PngAndPlots) {
  ScratchDir dir("cli_ok");
  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  const auto r = run_vascsim("render '" + run + "'" + kSmall + "--png-dir '" + (dir / "png") + "' --mp4 '" +
                                 (dir / "v.mp4") + "' --plots '" + (dir / "plots") + "'",
                             dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "v.mp4"));
  EXPECT_TRUE(fs::exists(png_frame_path(dir / "png", 5)));  // 0..1 s at 5 fps: 6 frames
  EXPECT_FALSE(fs::exists(png_frame_path(dir / "png", 6)));
  EXPECT_TRUE(fs::exists(dir / "plots/tracking_error.png"));
  EXPECT_NE(r.out.find("v.mp4"), std::string::npos);
}

TEST(RenderCli, DefaultOutputIsVideoInRunDirAndNeedsForceToOverwrite) {
  ScratchDir dir("cli_force");
  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  ASSERT_EQ(run_vascsim("render '" + run + "'" + kSmall, dir).exit_code, 0);
  EXPECT_TRUE(fs::exists(run + "/video.mp4"));
  const auto again = run_vascsim("render '" + run + "'" + kSmall, dir);
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("--force"), std::string::npos) << again.err;
  EXPECT_EQ(run_vascsim("render '" + run + "'" + kSmall + "--force", dir).exit_code, 0);
}

// --force replaces a render's own frames only, and only once the whole command has been checked
// (QA, stop 38: a refused --plots, or too many frames, had removed them and written nothing;
// frame_final.png, a link and a directory named frame_*.png were removed too).
TEST(RenderCli, ForceRemovesOnlyItsOwnFramesAndOnlyOnceTheCommandIsChecked) {
  ScratchDir dir("cli_png_force");
  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  const std::string png = dir / "png";
  const auto write = [](const std::string& path) { std::ofstream(path) << "mine"; };
  ASSERT_EQ(run_vascsim("render '" + run + "'" + kSmall + "--png-dir '" + png + "'", dir).exit_code, 0);
  ASSERT_TRUE(fs::exists(png_frame_path(png, 5)));
  write(dir / "plots_file");
  const auto refused = run_vascsim("render '" + run + "'" + kSmall + "--png-dir '" + png + "' --force --plots '" + (dir / "plots_file") + "'", dir);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_TRUE(fs::exists(png_frame_path(png, 5))) << "a refused render removed the earlier frames";
  const auto too_many = run_vascsim("render '" + run + "'" + kSmall + "--png-dir '" + png + "' --force --plots '" + (dir / "plots") + "' --speed 1e-9", dir);
  EXPECT_EQ(too_many.exit_code, 2) << too_many.err;
  EXPECT_TRUE(fs::exists(png_frame_path(png, 5)));
  EXPECT_FALSE(fs::exists(dir / "plots")) << "plots were written before the frame count was refused";

  write(png + "/frame_final.png");
  fs::create_directory(png + "/frame_000100.png");
  fs::create_symlink(dir / "plots_file", png + "/frame_000101.png");
  ASSERT_EQ(run_vascsim("render '" + run + "'" + kSmall + "--png-dir '" + png + "' --force --to 0.4", dir).exit_code, 0);
  EXPECT_TRUE(fs::exists(png_frame_path(png, 2)));
  EXPECT_FALSE(fs::exists(png_frame_path(png, 3))) << "an earlier render's frame beyond this one's was kept";
  EXPECT_TRUE(fs::is_regular_file(png + "/frame_final.png"));
  EXPECT_TRUE(fs::is_directory(png + "/frame_000100.png"));
  EXPECT_TRUE(fs::is_symlink(png + "/frame_000101.png"));
}

TEST(RenderCli, MissingAndTruncatedLogsExit2WithoutOutput) {
  ScratchDir dir("cli_badlog");
  auto r = run_vascsim("render '" + (dir / "nope") + "' --mp4 '" + (dir / "out/v.mp4") + "'", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no such run directory"), std::string::npos) << r.err;

  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  const std::string log = run + "/frames.vlog";
  const std::string bytes = testing::read_bytes(log);
  {
    std::ofstream cut(log, std::ios::binary | std::ios::trunc);
    cut.write(bytes.data(), 40);  // inside the header
  }
  fs::create_directories(dir / "out");
  r = run_vascsim("render '" + run + "'" + kSmall + "--mp4 '" + (dir / "out/v.mp4") + "' --png-dir '" +
                      (dir / "out/png") + "'",
                  dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("truncated"), std::string::npos) << r.err;
  EXPECT_FALSE(has_final_outputs(dir / "out"));
}

// A finished run's summary.json counts its frames: a log cut or appended to afterwards (a copy
// cut short, another log concatenated) is refused by render and export, not drawn silently
// shorter or with an extra frame (a copy of the last record passes every time check).
TEST(RenderCli, ALogWithOtherFramesThanItsSummaryIsRefused) {
  ScratchDir dir("cli_summary_frames");
  SyntheticLogSpec spec;
  spec.frames = 10;
  const std::string run = testing::make_run(dir, spec);
  const std::string log = run + "/frames.vlog";
  testing::write_bytes(run + "/summary.json", R"({"format": "vascsim-summary/1", "ok": true, "frames": 10})");
  const std::string still = " --still 0.5 --width 64 --height 64 --png '" + (dir / "still.png") + "'";
  ASSERT_EQ(run_vascsim("render '" + run + "'" + still, dir).exit_code, 0);
  const std::string bytes = testing::read_bytes(log);
  const std::size_t record = 8 * FrameLogReader(log).header().record_doubles();
  for (const std::string& changed : {bytes + bytes.substr(bytes.size() - record), bytes.substr(0, bytes.size() - record)}) {
    SCOPED_TRACE(changed.size() > bytes.size() ? "appended" : "cut");
    testing::write_bytes(log, changed);
    testing::CommandResult r = run_vascsim("render '" + run + "'" + still + " --force", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("frames, but " + run + "/summary.json says the run wrote 10"), std::string::npos) << r.err;
    r = run_vascsim("export '" + run + "' --csv '" + (dir / "csv") + "'", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("cut or appended to after the run ended"), std::string::npos) << r.err;
  }
  // A hand-written summary without a count holds the log to nothing more than its own checks.
  testing::write_bytes(run + "/summary.json", R"({"ok": true})");
  EXPECT_EQ(run_vascsim("render '" + run + "'" + still + " --force", dir).exit_code, 0);
}

// The run's log named directly (RUN/frames.vlog) is the run's, as its directory is: it was
// rendered and exported without the check against summary.json or the stopped-run warning, and
// its default video went to RUN/frames.mp4 beside the run's video.mp4.
TEST(RenderCli, ARunsLogNamedDirectlyIsCheckedAndRenderedAsItsRun) {
  ScratchDir dir("cli_log_named_directly");
  SyntheticLogSpec spec;
  spec.frames = 10;
  const std::string run = testing::make_run(dir, spec);
  const std::string log = run + "/frames.vlog";
  const std::string still = " --still 0.5 --width 64 --height 64 --png '" + (dir / "still.png") + "' --force";
  fs::remove(run + "/summary.json");
  fs::create_directories(dir / "csv");
  testing::CommandResult r = run_vascsim("render '" + log + "'" + still, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + run + " has no summary.json"), std::string::npos) << r.err;
  r = run_vascsim("export '" + log + "' --csv '" + (dir / "csv") + "' --force", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + run + " has no summary.json"), std::string::npos) << r.err;
  testing::write_bytes(run + "/summary.json", R"({"format": "vascsim-summary/1", "ok": true, "frames": 9})");
  r = run_vascsim("render '" + log + "'" + still, dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(log + ": 10 frames, but " + run + "/summary.json says the run wrote 9"), std::string::npos) << r.err;
  r = run_vascsim("export '" + log + "' --csv '" + (dir / "csv") + "' --force", dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("says the run wrote 9"), std::string::npos) << r.err;
  testing::write_bytes(run + "/summary.json", R"({"format": "vascsim-summary/1", "ok": true, "frames": 10})");
  r = run_vascsim("render '" + log + "'" + kSmall, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(run + "/video.mp4"));
  EXPECT_FALSE(fs::exists(run + "/frames.mp4"));
  // A log copied out of its run is no run's: nothing to check it against, nothing to warn about.
  fs::create_directories(dir / "copies");
  fs::copy_file(log, dir / "copies/run1.vlog");
  r = run_vascsim("render '" + (dir / "copies/run1.vlog") + "'" + still, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

// A summary that cannot be read, or has no frame count, leaves the log unchecked against it: a
// warning says so (the check was skipped silently), and the log is still rendered and exported.
TEST(RenderCli, ASummaryTheLogCannotBeCheckedAgainstIsAWarning) {
  ScratchDir dir("cli_summary_damaged");
  SyntheticLogSpec spec;
  spec.frames = 10;
  const std::string run = testing::make_run(dir, spec);
  const std::string still = " --still 0.5 --width 64 --height 64 --png '" + (dir / "still.png") + "' --force";
  const std::string not_checked = ", so " + run + "/frames.vlog was not checked against it";
  fs::create_directories(dir / "csv");
  for (const auto& [summary, why] : std::vector<std::pair<std::string, std::string>>{
           {R"({"ok": tru)", run + "/summary.json: "},
           {R"([1, 2])", run + "/summary.json: not a JSON object"},
           {R"({"ok": true, "frames": "ten"})", run + "/summary.json: no /frames count"}}) {
    SCOPED_TRACE(summary);
    testing::write_bytes(run + "/summary.json", summary);
    testing::CommandResult r = run_vascsim("render '" + run + "'" + still, dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("vascsim render: warning: " + why), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(not_checked), std::string::npos) << r.err;
    r = run_vascsim("export '" + run + "' --csv '" + (dir / "csv") + "' --force", dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("vascsim export: warning: " + why), std::string::npos) << r.err;
  }
}

// A video, still or CSV of a failed run ends with its last frame before the failure and does not
// say so itself: render and export warn, naming the failure as summary.json gives it.
TEST(RenderCli, AFailedRunIsSaidToHaveFailed) {
  ScratchDir dir("cli_failed_run");
  const std::string run = dir / "run";
  testing::CommandResult r =
      run_vascsim("run '" + std::string(VASCSIM_SOURCE_DIR) + "/tests/scenes/crammed_feed.json' --out '" + run + "' --quiet", dir);
  ASSERT_EQ(r.exit_code, 1) << r.err;
  std::ifstream in(run + "/summary.json");
  const std::string failure = nlohmann::json::parse(in)["failure"];
  const std::string said = "warning: " + run + "/summary.json: the run failed (" + failure + "); its log ends";
  const std::string still = " --still 0.05 --width 320 --height 180 --png '" + (dir / "still.png") + "' --force";
  r = run_vascsim("render '" + run + "'" + still, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("vascsim render: " + said), std::string::npos) << r.err;
  r = run_vascsim("export '" + run + "' --csv '" + (dir / "csv") + "'", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("vascsim export: " + said), std::string::npos) << r.err;
  // The picture says so too (its HUD's last row, render_failed_run_test.cpp): the same still of
  // the run with its summary edited to a finished run's differs.
  const std::string failed_still = testing::read_bytes(dir / "still.png");
  std::ifstream summary_in(run + "/summary.json");
  nlohmann::json summary = nlohmann::json::parse(summary_in);
  summary["ok"] = true;
  summary["failure"] = nullptr;
  testing::write_bytes(run + "/summary.json", summary.dump());
  r = run_vascsim("render '" + run + "'" + still, dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("the run failed"), std::string::npos) << r.err;
  EXPECT_NE(testing::read_bytes(dir / "still.png"), failed_still);
}

// A summary names the scene its run ran (provenance.scene_hash), as the log does: another run's
// summary beside a log with as many frames is refused, not shown as this run's numbers.
TEST(RenderCli, ASummaryOfAnotherSceneIsRefused) {
  ScratchDir dir("cli_summary_scene");
  SyntheticLogSpec spec;
  spec.frames = 10;
  LogMetadata metadata = synthetic_metadata(spec);
  metadata.scene_hash = "1111111111111111";
  const std::string run = dir / "run";
  fs::create_directories(run);
  write_synthetic_log(run + "/frames.vlog", spec, metadata);
  const std::string summary = R"({"format": "vascsim-summary/1", "ok": true, "frames": 10, "provenance": {"scene_hash": ")";
  const std::string still = " --still 0.5 --width 64 --height 64 --png '" + (dir / "still.png") + "' --force";
  testing::write_bytes(run + "/summary.json", summary + "2222222222222222\"}}");
  testing::CommandResult r = run_vascsim("render '" + run + "'" + still, dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(run + "/summary.json: /provenance/scene_hash is 2222222222222222, but " + run +
                       "/frames.vlog was written by a run of the scene with hash 1111111111111111"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "still.png"));
  r = run_vascsim("export '" + run + "' --csv '" + (dir / "csv") + "'", dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("the summary is another run's"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "csv"));
  // The run's own summary, and one written before hashes were recorded, are accepted.
  for (const std::string& hash : {std::string("1111111111111111"), std::string()}) {
    testing::write_bytes(run + "/summary.json", summary + hash + "\"}}");
    EXPECT_EQ(run_vascsim("render '" + run + "'" + still, dir).exit_code, 0) << hash;
  }
}

TEST(RenderCli, UnwritableDestinationExits2WithoutPartialFiles) {
  ScratchDir dir("cli_unwritable");
  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  { std::ofstream(dir / "a_file") << "x"; }  // a directory cannot be created under a file
  auto r = run_vascsim("render '" + run + "'" + kSmall + "--mp4 '" + (dir / "a_file/v.mp4") + "'", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("a_file/v.mp4"), std::string::npos) << r.err;
  r = run_vascsim("render '" + run + "'" + kSmall + "--png-dir '" + (dir / "a_file/png") + "'", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("a_file/png"), std::string::npos) << r.err;
  EXPECT_FALSE(has_final_outputs(dir.path()));
}

// Outputs of one command that name the same file are refused before anything is written: the
// video named as a plot or a frame was written over halfway, with only the encoder's noise to say.
TEST(RenderCli, OutputsNamingTheSameFileAreRefused) {
  ScratchDir dir("cli_outputs_apart");
  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  const std::string out = dir / "out";
  fs::create_directories(out);
  for (const auto& [outputs, expected] : std::vector<std::pair<std::string, std::string>>{
           {"--plots '" + out + "' --mp4 '" + out + "/tip_trajectory.png'", "is one of the files --plots " + out + " writes"},
           {"--png-dir '" + out + "' --mp4 '" + out + "/frame_000003.png'", "is one of the files --png-dir " + out + " writes"},
           {"--png-dir '" + out + "/' --mp4 '" + dir.path().string() + "/./out/frame_000000.png'", "is one of the files --png-dir"},
           {"--png-dir '" + out + "' --mp4 '" + out + "'", "is the directory --png-dir writes to"}}) {
    SCOPED_TRACE(outputs);
    const auto r = run_vascsim("render '" + run + "'" + kSmall + outputs, dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_empty(out));
  }
  // Beside each other, in one directory, they are fine.
  const auto r = run_vascsim("render '" + run + "'" + kSmall + "--png-dir '" + out + "' --plots '" + out + "' --mp4 '" + out + "/video.mp4'", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out + "/video.mp4"));
  EXPECT_TRUE(fs::exists(out + "/frame_000000.png"));
  EXPECT_TRUE(fs::exists(out + "/tip_trajectory.png"));
}

TEST(RenderCli, BadOptionsExit2) {
  ScratchDir dir("cli_options");
  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  // Each message names the option (or the argument) that was wrong.
  for (const auto& [opts, named] : std::vector<std::pair<std::string, std::string>>{
           {"--width abc", "--width"},
           {"--camera sideways", "--camera"},
           {"--fps 0", "--fps"},
           {"--zoom -1", "--zoom"},
           {"--width 161 --height 120", "--width 161 --height 120"},  // the MP4 needs an even size
           {"--from 2 --to 1", "--from"},
           {"--bogus", "--bogus"},
           {"--width 320 --width 640", "--width"},
           {"--speed 0x10", "--speed"},
           {"", "RUN_DIR"}}) {
    const std::string args = opts.empty() ? "render" : "render '" + run + "' " + opts;
    const auto r = run_vascsim(args, dir);
    EXPECT_EQ(r.exit_code, 2) << opts << ": " << r.err;
    EXPECT_NE(r.err.find(named), std::string::npos) << opts << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(run + "/video.mp4"));
  // Too many frames: the numbers read as the user gave them ("speed 1e-09", not "0.000000").
  const auto r = run_vascsim("render '" + run + "' --speed 1e-9 --mp4 '" + (dir / "v.mp4") + "'", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(" fps and speed 1e-09 makes "), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("0.000000"), std::string::npos) << r.err;
}

// A render stopped by Ctrl-C or kill leaves no temporary behind (its video's was left for the
// next render into the directory to remove), and the signal still ends it.
TEST(RenderCli, ARenderStoppedBySignalLeavesNoTemporary) {
  ScratchDir dir("cli_render_signal");
  SyntheticLogSpec spec;
  spec.frames = 2000;
  spec.duration = 200;  // s: 6000 video frames, far more than the test waits for
  const std::string run = testing::make_run(dir, spec);
  const std::string video = dir / "v.mp4";
  const auto temporaries = [&] {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir.path())) n += e.path().filename().string().rfind(".v.mp4.tmp-", 0) == 0;
    return n;
  };
  for (const int signal : {SIGINT, SIGTERM}) {
    const pid_t pid = ::fork();
    if (pid == 0) {
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 1);
      ::dup2(null, 2);
      ::execl(VASCSIM_EXE, VASCSIM_EXE, "render", run.c_str(), "--mp4", video.c_str(), "--width", "160", "--height", "120",
              "--quiet", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    for (int k = 0; k < 3000 && temporaries() == 0; ++k) ::usleep(10000);  // up to 30 s
    ASSERT_EQ(temporaries(), 1) << "the render never started its video";
    ::kill(pid, signal);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "status " << status;
    EXPECT_EQ(temporaries(), 0) << "signal " << signal;
    EXPECT_FALSE(fs::exists(video));
  }
}

// A width x height image of one grey level.
Image flat_image(int width, int height, std::uint8_t level) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgb.assign(static_cast<std::size_t>(width) * height * 3, level);
  return image;
}

TEST(DiffCli, ExitCodesAndHeatMap) {
  ScratchDir dir("cli_diff");
  Image a = flat_image(8, 4, 200);
  Image b = a;
  b.rgb[3 * 9] = 150;  // one pixel off by 50
  write_image_png(dir / "a.png", a);
  write_image_png(dir / "b.png", b);
  auto r = run_vascsim("diff '" + (dir / "a.png") + "' '" + (dir / "a.png") + "'", dir);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("inf"), std::string::npos);
  r = run_vascsim("diff '" + (dir / "a.png") + "' '" + (dir / "b.png") + "' --out '" + (dir / "heat.png") + "'", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("max difference  50"), std::string::npos) << r.out;
  const Image heat = load_png(dir / "heat.png");
  EXPECT_EQ(heat.rgb[3 * 9], 255);  // the differing pixel is marked red-ish
  EXPECT_EQ(run_vascsim("diff '" + (dir / "a.png") + "' '" + (dir / "b.png") + "' --tolerance 50", dir).exit_code, 0);
  EXPECT_EQ(run_vascsim("diff '" + (dir / "a.png") + "' '" + (dir / "missing.png") + "'", dir).exit_code, 2);
  Image c = a;
  c.width = 4;
  c.rgb.resize(4 * 4 * 3);
  write_image_png(dir / "c.png", c);
  EXPECT_EQ(run_vascsim("diff '" + (dir / "a.png") + "' '" + (dir / "c.png") + "'", dir).exit_code, 2);
  EXPECT_EQ(run_vascsim("diff '" + (dir / "a.png") + "' --tolerance x", dir).exit_code, 2);
  // --force without --out has nothing to replace: said, not ignored.
  r = run_vascsim("diff '" + (dir / "a.png") + "' '" + (dir / "a.png") + "' --force", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--force replaces an existing --out file, and no --out was given"), std::string::npos) << r.err;

  // The same colours half transparent differ from the opaque original (alpha was dropped).
  // (Written with stb's RGBA encoder: vascsim's own PNGs are opaque RGB.)
  std::vector<std::uint8_t> rgba(8 * 4 * 4, 200);
  for (std::size_t p = 0; p < 32; ++p) rgba[4 * p + 3] = 128;
  std::string half;
  stbi_write_png_to_func([](void* out, void* data, int size) { static_cast<std::string*>(out)->append(static_cast<char*>(data), size); },
                         &half, 8, 4, 4, rgba.data(), 8 * 4);
  std::ofstream(dir / "half.png", std::ios::binary) << half;
  r = run_vascsim("diff '" + (dir / "a.png") + "' '" + (dir / "half.png") + "'", dir);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("max difference  127"), std::string::npos) << r.out;
}

// 16-bit PNGs (from other tools) are compared whole: read at 8 bits, two images differing in
// their low bytes only compared as identical. Differences are in 8-bit levels (value / 257).
TEST(DiffCli, SixteenBitImagesAreComparedAtFullPrecision) {
  ScratchDir dir("cli_diff16");
  std::vector<std::uint16_t> a(4 * 2 * 3, 0x8000);
  std::vector<std::uint16_t> b = a;
  b[3 * 5 + 1] = 0x8000 + 0x80;  // pixel 5's green: the low byte only, 128/257 of an 8-bit level
  std::ofstream(dir / "a16.png", std::ios::binary) << vascsim::test::png16_bytes(4, 2, 2, a);
  std::ofstream(dir / "b16.png", std::ios::binary) << vascsim::test::png16_bytes(4, 2, 2, b);
  auto r = run_vascsim("diff '" + (dir / "a16.png") + "' '" + (dir / "b16.png") + "'", dir);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("max difference  0.4981\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pixels over 0  1 of 8"), std::string::npos) << r.out;
  EXPECT_EQ(run_vascsim("diff '" + (dir / "a16.png") + "' '" + (dir / "b16.png") + "' --tolerance 1", dir).exit_code, 0);
  EXPECT_EQ(run_vascsim("diff '" + (dir / "a16.png") + "' '" + (dir / "a16.png") + "'", dir).exit_code, 0);
  // Against an 8-bit image of the same colours (0x80 is 0x8080 at 16 bits): 0x8000 is 128/257 off.
  write_image_png(dir / "c8.png", flat_image(4, 2, 0x80));
  r = run_vascsim("diff '" + (dir / "a16.png") + "' '" + (dir / "c8.png") + "'", dir);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("pixels over 0  8 of 8"), std::string::npos) << r.out;
  std::vector<std::uint16_t> same(4 * 2 * 3, 0x8080);
  std::ofstream(dir / "d16.png", std::ios::binary) << vascsim::test::png16_bytes(4, 2, 2, same);
  r = run_vascsim("diff '" + (dir / "d16.png") + "' '" + (dir / "c8.png") + "'", dir);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("inf (identical)"), std::string::npos) << r.out;
}

// --out follows the rules of every other output: no existing file replaced without --force, and
// never an input or anything but a regular file, even with --force.
TEST(DiffCli, OutNeverReplacesWithoutForceNorAnInputNorADevice) {
  ScratchDir dir("cli_diff_out");
  Image a = flat_image(8, 4, 200);
  Image b = a;
  b.rgb[0] = 10;
  write_image_png(dir / "a.png", a);
  write_image_png(dir / "b.png", b);
  const std::string a_bytes = testing::read_bytes(dir / "a.png");
  std::ofstream(dir / "notes.txt") << "mine";
  const std::string diff = "diff '" + (dir / "a.png") + "' '" + (dir / "b.png") + "' --out ";
  auto r = run_vascsim(diff + "'" + (dir / "notes.txt") + "'", dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_EQ(testing::read_bytes(dir / "notes.txt"), "mine");
  r = run_vascsim(diff + "'" + (dir / "notes.txt") + "' --force", dir);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NO_THROW(load_png(dir / "notes.txt")) << "with --force the heat map replaces it";
  for (const std::string input : {"a.png", "b.png"}) {
    r = run_vascsim(diff + "'" + (dir / input) + "' --force", dir);
    EXPECT_EQ(r.exit_code, 2) << input;
    EXPECT_NE(r.err.find("input"), std::string::npos) << r.err;
  }
  EXPECT_EQ(testing::read_bytes(dir / "a.png"), a_bytes);
  // Special files are never renamed over, even by root with --force (it once replaced /dev/full).
  // A FIFO and a directory in the scratch directory stand for them, so a regression breaks nothing.
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  fs::create_directories(dir / "folder");
  for (const std::string special : {"fifo", "folder"}) {
    r = run_vascsim(diff + "'" + (dir / special) + "' --force", dir);
    EXPECT_EQ(r.exit_code, 2) << special << ": " << r.err;
    EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << r.err;
  }
  EXPECT_TRUE(fs::is_fifo(dir / "fifo"));
  EXPECT_TRUE(fs::is_directory(dir / "folder"));
}

// Damaged PNGs are refused naming the file, where stb_image alone decoded them: a flipped byte
// (bad CRC), a file cut short (no IEND), a text file; and a size mismatch names both files.
TEST(DiffCli, DamagedPngsAndSizeMismatchesNameTheFile) {
  ScratchDir dir("cli_diff_damaged");
  const Image a = flat_image(8, 4, 120);
  write_image_png(dir / "a.png", a);
  const std::string good = testing::read_bytes(dir / "a.png");
  std::string flipped = good;
  flipped[flipped.size() - 20] ^= 0x01;  // inside the last IDAT chunk's data or CRC
  std::ofstream(dir / "flipped.png", std::ios::binary) << flipped;
  std::ofstream(dir / "short.png", std::ios::binary) << good.substr(0, good.size() - 12);
  std::ofstream(dir / "text.png") << "not an image";
  const std::pair<std::string, std::string> cases[] = {
      {"flipped.png", "CRC"}, {"short.png", "IEND"}, {"text.png", "signature"}};
  for (const auto& [name, why] : cases) {
    const auto r = run_vascsim("diff '" + (dir / "a.png") + "' '" + (dir / name) + "'", dir);
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.out;
    EXPECT_NE(r.err.find(dir / name), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
  }
  Image wide = a;
  wide.width = 4;
  wide.rgb.resize(4 * 4 * 3);
  write_image_png(dir / "wide.png", wide);
  const auto r = run_vascsim("diff '" + (dir / "a.png") + "' '" + (dir / "wide.png") + "'", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(dir / "a.png"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(dir / "wide.png"), std::string::npos) << r.err;
  // Sizes are compared from the headers before either image is decoded (a small file can decode
  // to gigabytes): a file claiming 40000 x 40000 px with no pixel data is a size mismatch, not
  // decoded first.
  std::string huge = good.substr(0, 24);
  for (const int at : {16, 20}) huge[at] = 0, huge[at + 1] = 0, huge[at + 2] = char(0x9c), huge[at + 3] = 0x40;
  std::ofstream(dir / "huge.png", std::ios::binary) << huge;
  const auto bomb = run_vascsim("diff '" + (dir / "a.png") + "' '" + (dir / "huge.png") + "'", dir);
  EXPECT_EQ(bomb.exit_code, 2);
  EXPECT_NE(bomb.err.find("is 40000x40000: images of different sizes cannot be compared"), std::string::npos) << bomb.err;
}

}  // namespace
}  // namespace vascsim::render

namespace vascsim::render {
namespace {

// A progress line (frames, frames/s, ETA) on a terminal, as vascsim run has; none on a pipe or
// with --quiet. `script` (util-linux) gives the command a pseudo-terminal.
TEST(RenderCli, ProgressLineOnATerminalOnly) {
  ScratchDir dir("render_progress");
  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  const std::string render = std::string("'") + VASCSIM_EXE + "' render '" + run + "'" + kSmall + "--png-dir '" +
                             (dir / "png") + "' --force";
  auto on_terminal = [&](const std::string& extra) {
    return testing::run_program("script", "-qec \"" + render + extra + "\" /dev/null", dir);
  };
  const auto shown = on_terminal("");
  ASSERT_EQ(shown.exit_code, 0) << shown.out << shown.err;
  EXPECT_NE(shown.out.find("frames/s  ETA"), std::string::npos) << shown.out;
  const auto quiet = on_terminal(" --quiet");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.out << quiet.err;
  EXPECT_EQ(quiet.out.find("frames/s"), std::string::npos) << quiet.out;
  const auto piped = run_vascsim("render '" + run + "'" + kSmall + "--png-dir '" + (dir / "png") + "' --force", dir);
  ASSERT_EQ(piped.exit_code, 0);
  EXPECT_EQ(piped.err.find("frames/s"), std::string::npos) << piped.err;
}

}  // namespace
}  // namespace vascsim::render

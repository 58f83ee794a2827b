// `vascsim render --mp4 --png-dir` killed with SIGKILL at several moments (the video file just
// opened, a few frames in, half-way, at the end): nothing under a final name is ever partial
// (no out.mp4 unless complete; every frame_*.png a complete PNG), and what a killed render left
// under its hidden temporary names neither blocks nor survives the next render into the same
// place (sim/io/output_file.h; docs/rendering.md).
#include <gtest/gtest.h>

#include "render/png_writer.h"
#include "render/video_encoder.h"
#include "render_test_util.h"
#include "sim/io/png_file.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;
namespace fs = std::filesystem;

constexpr int kFrames = 91;  // 0 .. 3 s at 30 fps
const char* kView = " --width 320 --height 240 --fps 30 ";

std::size_t count_in(const fs::path& dir, const std::string& prefix) {
  std::size_t n = 0;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    n += it->path().filename().string().rfind(prefix, 0) == 0;
  return n;
}

// Every file under a final name in `png` is a whole frame (read_png checks every CRC and the
// final IEND), and out.mp4 exists only complete.
void expect_only_complete_outputs(const ScratchDir& dir, const std::string& moment, bool render_finished) {
  SCOPED_TRACE("killed " + moment);
  for (const auto& e : fs::directory_iterator(dir / "png")) {
    const std::string name = e.path().filename().string();
    if (name[0] == '.') continue;  // a temporary name: allowed to be partial
    ASSERT_EQ(name.rfind("frame_", 0), 0u) << name;
    try {
      const io::PngPixels p = io::read_png(e.path().string(), 3);
      EXPECT_EQ(p.width, 320);
      EXPECT_EQ(p.height, 240);
    } catch (const std::exception& ex) {
      ADD_FAILURE() << name << " is not a complete PNG: " << ex.what();
    }
  }
  if (!render_finished) {
    EXPECT_FALSE(fs::exists(dir / "out.mp4")) << "no render finished, so out.mp4 must not exist";
  } else {
    EXPECT_EQ(probe_video(dir / "out.mp4").frames, kFrames);
  }
}

TEST(RenderKill, KilledRendersLeaveOnlyCompleteOutputsAndDoNotBlockTheNext) {
  ScratchDir dir("render_kill");
  SyntheticLogSpec spec;
  spec.frames = 31;
  spec.duration = 3.0;
  const std::string run = testing::make_run(dir, spec);
  fs::create_directories(dir / "png");
  const std::string both =
      "render '" + run + "'" + kView + "--mp4 '" + (dir / "out.mp4") + "' --png-dir '" + (dir / "png") + "' --force";
  const auto frames_written = [&](std::size_t n) { return [&, n] { return count_in(dir / "png", "frame_") >= n; }; };
  struct Moment {
    std::string what;
    std::function<bool()> ready;
  };
  const std::vector<Moment> moments = {
      {"as the video's temporary file appears", [&] { return count_in(dir.path(), ".out.mp4.tmp-") > 0; }},
      {"after 5 frames", frames_written(5)},
      {"half-way", frames_written(kFrames / 2)},
      {"at the last frames", frames_written(kFrames - 1)},
  };
  bool finished = false;
  std::size_t left_behind = 0;
  for (std::size_t k = 0; k < moments.size(); ++k) {
    const auto r = testing::run_vascsim_killed_when(both, dir, moments[k].ready);
    // The first three moments come well before the end of a 91-frame render: it must have been
    // killed there, or the test is not testing a kill.
    if (k < 3) EXPECT_EQ(r.exit_code, 128 + 9) << moments[k].what << ": " << r.err;
    else EXPECT_TRUE(r.exit_code == 128 + 9 || r.exit_code == 0) << r.exit_code << " " << r.err;
    // A kill at the last frames can land after the video was renamed into place but before the
    // process ended: killed, yet out.mp4 is there, and then it must be complete.
    finished = finished || r.exit_code == 0 || (k == moments.size() - 1 && fs::exists(dir / "out.mp4"));
    expect_only_complete_outputs(dir, moments[k].what, finished);
    left_behind += count_in(dir.path(), ".out.mp4.tmp-") + count_in(dir / "png", ".frame_");
  }
  EXPECT_GT(left_behind, 0u) << "a kill as the video's file appears leaves its temporary name behind";

  // The next render of the video alone needs no --force (no out.mp4 was completed, unless the
  // last kill came too late), is not blocked, and clears the killed renders' video leftovers.
  const auto video = testing::run_vascsim("render '" + run + "'" + kView + "--mp4 '" + (dir / "out.mp4") + "'" +
                                              (finished ? " --force" : ""),
                                          dir);
  ASSERT_EQ(video.exit_code, 0) << video.err;
  EXPECT_EQ(probe_video(dir / "out.mp4").frames, kFrames);
  EXPECT_EQ(count_in(dir.path(), "."), 0u) << "no hidden leftovers beside out.mp4";
  // The PNG sequence: frames exist, so --force, as for any directory holding frames.
  const auto png = testing::run_vascsim("render '" + run + "'" + kView + "--png-dir '" + (dir / "png") + "' --force", dir);
  ASSERT_EQ(png.exit_code, 0) << png.err;
  EXPECT_EQ(count_in(dir / "png", "frame_"), static_cast<std::size_t>(kFrames));
  EXPECT_EQ(count_in(dir / "png", "."), 0u) << "no hidden leftovers among the frames";
  expect_only_complete_outputs(dir, "(none: the final renders)", true);
}

}  // namespace
}  // namespace vascsim::render

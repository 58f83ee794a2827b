// The plots of a run whose root is fed through the inlet (control.advance) include the drive's
// push against time, feed_force.png; a run without a feed has no such plot. Before, a catheter
// only pushed from its root got a flat-zero magnetic force plot and nothing of its feed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "render/frame_source.h"
#include "render/plots.h"
#include "render_test_util.h"
#include "sim/io/png_file.h"
#include "sim/io/run_files.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;
namespace fs = std::filesystem;

std::vector<std::string> file_names(const std::vector<std::string>& paths) {
  std::vector<std::string> names;
  for (const auto& path : paths) names.push_back(fs::path(path).filename().string());
  return names;
}

// The rows (px, top down) where the plot's curve (#2B8A3E) is, at the left and right ends of
// its x extent.
struct CurveEnds {
  int left_x = -1, right_x = -1, left_y = -1, right_y = -1;
};
CurveEnds curve_ends(const io::PngPixels& image) {
  CurveEnds e;
  for (int x = 0; x < image.width; ++x)
    for (int y = 0; y < image.height; ++y) {
      const std::uint8_t* p = &image.data[(static_cast<std::size_t>(y) * image.width + x) * 3];
      if (std::abs(p[0] - 0x2B) < 6 && std::abs(p[1] - 0x8A) < 6 && std::abs(p[2] - 0x3E) < 6) {
        if (e.left_x < 0) e.left_x = x, e.left_y = y;
        e.right_x = x, e.right_y = y;
      }
    }
  return e;
}

TEST(RenderPlotsFeed, AFedRunHasAFeedPlotThatFollowsThePush) {
  ScratchDir dir("plots_feed");
  std::vector<std::string> always(std::begin(kRunPlotFiles), std::end(kRunPlotFiles));

  SyntheticLogSpec unfed;
  EXPECT_EQ(file_names(write_plots(FrameSource(testing::make_run(dir, unfed, "unfed")), dir / "unfed_plots", false)), always);
  EXPECT_FALSE(fs::exists(dir / (std::string("unfed_plots/") + kFeedPlotFile)));

  SyntheticLogSpec pushed;
  pushed.feed = true;
  pushed.frames = 30;  // the push rises linearly from 0 to 5 mN
  const std::string pushed_run = testing::make_run(dir, pushed, "pushed");
  std::vector<std::string> with_feed = always;
  with_feed.push_back(kFeedPlotFile);
  EXPECT_EQ(file_names(write_plots(FrameSource(pushed_run), dir / "pushed_plots", false)), with_feed);
  const CurveEnds rising = curve_ends(io::read_png(dir / (std::string("pushed_plots/") + kFeedPlotFile), 3));
  ASSERT_GE(rising.left_x, 0) << "no curve in the feed plot";
  // Time runs left to right over most of the width; the push rises, so the curve ends higher up
  // (smaller y) than it starts, by most of the plot's height (800 px at the default size).
  EXPECT_GT(rising.right_x - rising.left_x, 800);
  EXPECT_GT(rising.left_y - rising.right_y, 400) << rising.left_y << " -> " << rising.right_y;

  SyntheticLogSpec pulled = pushed;
  pulled.feed_force = -5e-3;
  const CurveEnds falling = curve_ends(io::read_png(
      write_plots(FrameSource(testing::make_run(dir, pulled, "pulled")), dir / "pulled_plots", false).back(), 3));
  EXPECT_GT(falling.right_y - falling.left_y, 400) << falling.left_y << " -> " << falling.right_y;

  // Written over only with force, as every plot.
  EXPECT_THROW(write_plots(FrameSource(pushed_run), dir / "pushed_plots", false), InputError);
  EXPECT_NO_THROW(write_plots(FrameSource(pushed_run), dir / "pushed_plots", true));
}

}  // namespace
}  // namespace vascsim::render

// The tip trajectory plot explains only what it draws: a free rod's run (no path) listed a
// "reference path" in its legend, and a run without magnetic force (only pushed from its root, or
// a free rod) was titled "Tip trajectory and magnetic force". Checked by colour: the path's blue
// anywhere in the plot (the dashed path and its legend line), and the width of the title's ink.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "render/frame_source.h"
#include "render/plots.h"
#include "render/synthetic_log.h"
#include "render_test_util.h"
#include "sim/io/png_file.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;

struct TrajectoryPlot {
  int path_pixels = 0;  // of the path's colour (#4C6EF5)
  int title_width = 0;  // px, from the title's first dark pixel to its last
};

TrajectoryPlot plot_of(const ScratchDir& dir, const std::string& run) {
  const std::string plots = dir / (std::filesystem::path(run).filename().string() + "_plots");
  write_plots(FrameSource(run), plots, false);
  const io::PngPixels image = io::read_png(plots + "/tip_trajectory.png", 3);
  TrajectoryPlot p;
  int first = image.width, last = -1;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* c = &image.data[(static_cast<std::size_t>(y) * image.width + x) * 3];
      if (std::abs(c[0] - 0x4C) < 6 && std::abs(c[1] - 0x6E) < 6 && std::abs(c[2] - 0xF5) < 6) ++p.path_pixels;
      // The title is the only ink in the top margin (the axes start below 8 % of the height).
      if (y < image.height * 8 / 100 && std::max({c[0], c[1], c[2]}) < 100) first = std::min(first, x), last = std::max(last, x);
    }
  p.title_width = last - first;
  return p;
}

TEST(RenderPlotsTrajectory, ExplainsOnlyWhatItDraws) {
  ScratchDir dir("plots_trajectory");
  const TrajectoryPlot steered = plot_of(dir, testing::make_run(dir, SyntheticLogSpec{}, "steered"));
  EXPECT_GT(steered.path_pixels, 100) << "no path drawn or explained";
  ASSERT_GT(steered.title_width, 0);

  SyntheticLogSpec pushed;  // a path to follow, but no magnetic force
  pushed.forces = false;
  pushed.reference = false;
  pushed.feed = true;
  const TrajectoryPlot pushed_plot = plot_of(dir, testing::make_run(dir, pushed, "pushed"));
  EXPECT_GT(pushed_plot.path_pixels, 100);
  // "Tip trajectory" is less than half as wide as "Tip trajectory and magnetic force".
  EXPECT_LT(pushed_plot.title_width, steered.title_width / 2) << "the title names a magnetic force not drawn";

  LogMetadata no_path = synthetic_metadata(pushed);
  no_path.path.clear();
  const std::string free_rod = dir / "free_rod";
  std::filesystem::create_directories(free_rod);
  write_synthetic_log(free_rod + "/frames.vlog", pushed, no_path);
  const TrajectoryPlot free_plot = plot_of(dir, free_rod);
  EXPECT_EQ(free_plot.path_pixels, 0) << "a reference path in the legend of a run without one";
  EXPECT_EQ(free_plot.title_width, pushed_plot.title_width);
}

}  // namespace
}  // namespace vascsim::render

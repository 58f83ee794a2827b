// The tip trajectory and snapshot plots explain only what they draw: a free rod's run (no path)
// listed a "reference path" in its legend, a run without magnetic force (only pushed from its
// root, or a free rod) was titled "Tip trajectory and magnetic force", and one without contact
// "Rod snapshots and contact forces". Checked by colour: the path's blue anywhere in the plot,
// and the width of the title's ink.
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

// What the checks read of a plot: pixels of the path's colour (#4C6EF5: the dashed path and its
// legend line) and the width of the title's ink.
struct PlotInk {
  int path_pixels = 0;
  int title_width = 0;  // px, from the title's first dark pixel to its last
};

PlotInk ink_of(const std::string& png) {
  const io::PngPixels image = io::read_png(png, 3);
  PlotInk p;
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

// The tip trajectory and snapshot plots of a run.
struct RunPlots {
  PlotInk trajectory, snapshots;
};

RunPlots plots_of(const ScratchDir& dir, const std::string& run) {
  const std::string plots = dir / (std::filesystem::path(run).filename().string() + "_plots");
  write_plots(FrameSource(run), plots, false);
  return {ink_of(plots + "/tip_trajectory.png"), ink_of(plots + "/snapshots.png")};
}

TEST(RenderPlotsTrajectory, ExplainsOnlyWhatItDraws) {
  ScratchDir dir("plots_trajectory");
  const RunPlots steered = plots_of(dir, testing::make_run(dir, SyntheticLogSpec{}, "steered"));
  EXPECT_GT(steered.trajectory.path_pixels, 100) << "no path drawn or explained";
  ASSERT_GT(steered.trajectory.title_width, 0);
  ASSERT_GT(steered.snapshots.title_width, 0);

  SyntheticLogSpec pushed;  // a path to follow, but no magnetic or contact force
  pushed.forces = false;
  pushed.reference = false;
  pushed.feed = true;
  const RunPlots pushed_plots = plots_of(dir, testing::make_run(dir, pushed, "pushed"));
  EXPECT_GT(pushed_plots.trajectory.path_pixels, 100);
  // "Tip trajectory" is less than half as wide as "Tip trajectory and magnetic force", and "Rod
  // snapshots" than "Rod snapshots and contact forces".
  EXPECT_LT(pushed_plots.trajectory.title_width, steered.trajectory.title_width / 2)
      << "the title names a magnetic force not drawn";
  EXPECT_LT(pushed_plots.snapshots.title_width, steered.snapshots.title_width / 2)
      << "the title names contact forces not drawn";

  LogMetadata no_path = synthetic_metadata(pushed);
  no_path.path.clear();
  const std::string free_rod = dir / "free_rod";
  std::filesystem::create_directories(free_rod);
  write_synthetic_log(free_rod + "/frames.vlog", pushed, no_path);
  const RunPlots free_plots = plots_of(dir, free_rod);
  EXPECT_EQ(free_plots.trajectory.path_pixels, 0) << "a reference path in the legend of a run without one";
  EXPECT_EQ(free_plots.trajectory.title_width, pushed_plots.trajectory.title_width);
}

}  // namespace
}  // namespace vascsim::render

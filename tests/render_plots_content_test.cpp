// A run's plots are of what its log has, and say only what they draw. Which plots: a free rod's
// run got empty magnetic force, tracking error and contact plots ("no ... in this log"). What
// they say: the tip trajectory and snapshot plots a free rod's run (no path)
// listed a "reference path" in its legend, a run without magnetic force (only pushed from its
// root, or a free rod) was titled "Tip trajectory and magnetic force", and one without contact
// "Rod snapshots and contact forces". Checked by colour: the path's blue anywhere in the plot,
// and the width of the title's ink.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "render/frame_source.h"
#include "render/plots.h"
#include "render/synthetic_log.h"
#include "render_test_util.h"
#include "sim/io/png_file.h"
#include "sim/scene/input_error.h"

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

TEST(RenderPlotsContent, ExplainsOnlyWhatItDraws) {
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

std::vector<std::string> file_names(const std::vector<std::string>& paths) {
  std::vector<std::string> names;
  for (const auto& path : paths) names.push_back(std::filesystem::path(path).filename().string());
  return names;
}

TEST(RenderPlotsContent, APlotIsWrittenOnlyForWhatTheLogHas) {
  ScratchDir dir("plots_content");
  using Names = std::vector<std::string>;
  const std::string steered = testing::make_run(dir, SyntheticLogSpec{}, "steered");
  EXPECT_EQ(file_names(write_plots(FrameSource(steered), dir / "steered_plots", false)),
            (Names{"tip_trajectory.png", "actuation_force.png", "snapshots.png", "tracking_error.png", "contact_force.png"}));

  SyntheticLogSpec pushed;  // along a path, no target, no magnetic or contact force
  pushed.forces = false;
  pushed.reference = false;
  pushed.feed = true;
  EXPECT_EQ(file_names(write_plots(FrameSource(testing::make_run(dir, pushed, "pushed")), dir / "pushed_plots", false)),
            (Names{"tip_trajectory.png", "snapshots.png", "tracking_error.png", "feed_force.png"}));

  SyntheticLogSpec free_spec = pushed;
  free_spec.feed = false;
  LogMetadata no_path = synthetic_metadata(free_spec);
  no_path.path.clear();
  const std::string free_rod = dir / "free_rod";
  std::filesystem::create_directories(free_rod);
  write_synthetic_log(free_rod + "/frames.vlog", free_spec, no_path);
  const std::string plots = dir / "plots";
  EXPECT_EQ(file_names(write_plots(FrameSource(free_rod), plots, false)), (Names{"tip_trajectory.png", "snapshots.png"}));

  // Replacing another run's plots: refused without force; with it, the other run's plots that
  // this one has none of go (they would pass for its own), and a file of another name stays.
  write_plots(FrameSource(steered), plots, true);
  testing::write_bytes(plots + "/notes.png", "mine");
  EXPECT_THROW(write_plots(FrameSource(free_rod), plots, false), InputError);
  EXPECT_TRUE(std::filesystem::exists(plots + "/contact_force.png")) << "a refused render changed the directory";
  write_plots(FrameSource(free_rod), plots, true);
  Names left;
  for (const auto& entry : std::filesystem::directory_iterator(plots)) left.push_back(entry.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (Names{"notes.png", "snapshots.png", "tip_trajectory.png"}));
}

}  // namespace
}  // namespace vascsim::render

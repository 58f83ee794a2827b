// `vascsim render --plots` with --from/--to plots the logged frames of that range: the same
// pixels as the plots of a log holding only those frames. (Before, the range moved the video
// and left the plots on the whole run, silently.)
#include <gtest/gtest.h>

#include <vector>

#include "render/frame_source.h"
#include "render/plots.h"
#include "render/render_run.h"
#include "render_test_util.h"
#include "sim/io/run_files.h"
#include "sim/log/frame_log.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;
namespace fs = std::filesystem;

// A run directory whose log holds frames first..last of `source`, with its header and metadata.
std::string cut_run(const ScratchDir& dir, const FrameSource& source, std::size_t first, std::size_t last) {
  const std::string run = dir / "cut";
  fs::create_directories(run);
  FrameLogWriter writer(run + "/frames.vlog", source.header());
  std::vector<double> record;
  for (std::size_t i = first; i <= last; ++i) {
    source.record(i, record);
    writer.append(record[0], std::vector<double>(record.begin() + 1, record.end()));
  }
  writer.close();
  return run;
}

RenderOptions plots_only(const std::string& dir) {
  RenderOptions o;
  o.plots_dir = dir;
  return o;
}

TEST(RenderPlotsRange, PlotsOfARangeAreThePlotsOfItsFramesAlone) {
  ScratchDir dir("plots_range");
  SyntheticLogSpec spec;
  spec.frames = 60;
  spec.duration = 5.9;  // a frame every 0.1 s
  const std::string run = testing::make_run(dir, spec);
  const FrameSource source(run);
  // From between frames 11 and 12 (the first plotted is 12) to frame 40 exactly.
  RenderOptions ranged = plots_only(dir / "ranged");
  ranged.from = 0.5 * (source.time_of(11) + source.time_of(12));
  ranged.to = source.time_of(40);
  render_run(run, ranged);
  render_run(cut_run(dir, source, 12, 40), plots_only(dir / "cut_plots"));
  render_run(run, plots_only(dir / "whole"));
  for (const char* name : kRunPlotFiles) {
    const auto png = [&](const char* plots) { return testing::read_bytes(dir / (std::string(plots) + "/" + name)); };
    ASSERT_FALSE(png("ranged").empty()) << name;
    EXPECT_EQ(png("ranged"), png("cut_plots")) << name << ": not the plot of frames 12..40 alone";
    EXPECT_NE(png("ranged"), png("whole")) << name << ": the range changed nothing";
  }
}

TEST(RenderPlotsRange, ARangeBetweenTwoFramesIsRefusedNamingTheOptions) {
  ScratchDir dir("plots_range_empty");
  SyntheticLogSpec spec;
  spec.frames = 11;
  spec.duration = 1.0;
  const std::string run = testing::make_run(dir, spec);
  RenderOptions o = plots_only(dir / "plots");
  o.from = 0.42;
  o.to = 0.47;
  try {
    render_run(run, o);
    ADD_FAILURE() << "plots of a range without a logged frame were written";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("--plots: no logged frame from 0.42 to 0.47 s"), std::string::npos) << what;
    EXPECT_NE(what.find("--from/--to"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(dir / "plots")) << "a refused --plots left a directory";
}

}  // namespace
}  // namespace vascsim::render

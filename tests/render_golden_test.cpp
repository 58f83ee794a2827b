// Golden images: small frames and a plot of fixed synthetic runs, compared with tests/golden/
// through the same diff code as `vascsim diff`. Regenerate on purpose with scripts/update-goldens.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "render/plots.h"
#include "render/png_writer.h"
#include "render/render_run.h"
#include "render_test_util.h"
#include "sim/io/run_files.h"
#include "sim/io/run_log.h"
#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/run/run.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;
namespace fs = std::filesystem;

// One 320x240 frame of `run` (a run directory or a log) at time t (s), the fit camera unless
// `view` says otherwise, compared with tests/golden/`golden`.
void expect_frame_matches(const ScratchDir& dir, const std::string& run, double t, const std::string& golden,
                          const std::function<void(View&)>& view = nullptr) {
  RenderOptions o;
  o.png_dir = dir / "png";
  o.view.width = 320;
  o.view.height = 240;
  if (view) view(o.view);
  o.from = t;
  o.to = t;
  const RenderReport r = render_run(run, o);
  ASSERT_EQ(r.frames, 1u);
  testing::expect_matches_golden(png_frame_path(o.png_dir, 0), golden);
}

TEST(RenderGolden, FitFrameOfSerpentineMaze) {
  ScratchDir dir("golden_fit");
  expect_frame_matches(dir, testing::make_run(dir, SyntheticLogSpec{}), 0.5, "frame_fit_320x240.png");
}

TEST(RenderGolden, FollowCameraZoomedOnTip) {
  ScratchDir dir("golden_follow");
  expect_frame_matches(dir, testing::make_run(dir, SyntheticLogSpec{}), 1.0, "frame_follow_320x240.png", [](View& v) {
    v.camera = CameraMode::kFollow;
    v.zoom = 2.5;
  });
}

// A vessel network's look: the lumen filled between its rings (a ring-shaped vessel around a
// hole), its walls, path and rod.
TEST(RenderGolden, FitFrameOfARingVessel) {
  ScratchDir dir("golden_vessel");
  expect_frame_matches(dir, testing::write_log(dir, "ring", testing::annulus_metadata()), 0.5, "frame_vessel_320x240.png");
}

// A shipped vessel scene's network as the simulator compiles it (junctions and Murray's-law
// radii, an aneurysm's sac on a bend, a lumen traced from an image mask), with the synthetic rod
// sliding 0.2 m along its route: a change to the vessel geometry or to how it is drawn shows here.
// Provenance is cleared, so a new commit alone does not change the frame.
std::string write_shipped_vessel_log(const ScratchDir& dir, const std::string& scene_name) {
  const Scene scene = read_scene_file(std::string(VASCSIM_SOURCE_DIR) + "/scenes/" + scene_name + ".json");
  const Run run(compile(scene));
  LogMetadata m = run_log_metadata(run);
  m.scene_json.clear();
  m.vascsim_version.clear();
  m.commit.clear();
  m.scene_hash.clear();
  SyntheticLogSpec spec;
  spec.nodes = scene.rod.nodes;
  spec.rod_length = scene.rod.length;
  spec.rod_radius = scene.rod.outer_radius;
  spec.cell = m.lumen_width;
  spec.speed = 0.2;
  spec.contact_nodes = {scene.rod.nodes / 4, scene.rod.nodes / 2};
  const std::string path = dir / (scene_name + ".vlog");
  write_synthetic_log(path, spec, m);
  return path;
}

class ShippedVesselGolden : public ::testing::TestWithParam<const char*> {};

TEST_P(ShippedVesselGolden, FitFrameMatches) {
  const std::string name = GetParam();
  ScratchDir dir("golden_" + name);
  expect_frame_matches(dir, write_shipped_vessel_log(dir, name), 1.0, "frame_" + name + "_320x240.png");
}

INSTANTIATE_TEST_SUITE_P(RenderGolden, ShippedVesselGolden, ::testing::Values("vessel_tree", "aneurysm", "vessel_mask"),
                         [](const auto& info) { return std::string(info.param); });

TEST(RenderGolden, TipTrajectoryPlot) {
  ScratchDir dir("golden_plot");
  SyntheticLogSpec spec;
  spec.frames = 30;
  spec.duration = 3.0;
  const std::string run = testing::make_run(dir, spec);
  FrameSource source(run);
  const auto written = write_plots(source, dir / "plots", false, {}, 480, 320);
  // What `run --force` removes of an earlier run is what was drawn.
  std::vector<std::string> names;
  for (const auto& path : written) names.push_back(std::filesystem::path(path).filename().string());
  ASSERT_EQ(names, std::vector<std::string>(std::begin(kRunPlotFiles), std::end(kRunPlotFiles)));
  testing::expect_matches_golden(dir / "plots/tip_trajectory.png", "plot_tip_trajectory_480x320.png");
  testing::expect_matches_golden(dir / "plots/actuation_force.png", "plot_actuation_force_480x320.png");
}

TEST(RenderGolden, DiffDetectsAChangedFrame) {
  // The golden check must be able to fail: a frame at another time differs from the golden.
  ScratchDir dir("golden_negative");
  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  RenderOptions o;
  o.png_dir = dir / "png";
  o.view.width = 320;
  o.view.height = 240;
  o.from = 0.9;
  o.to = 0.9;
  render_run(run, o);
  const Image a = load_png(png_frame_path(o.png_dir, 0));
  const Image b = load_png(std::string(VASCSIM_SOURCE_DIR) + "/tests/golden/frame_fit_320x240.png");
  EXPECT_GT(diff_images(a, b, 24, nullptr).pixels_over, 100);
}

}  // namespace
}  // namespace vascsim::render

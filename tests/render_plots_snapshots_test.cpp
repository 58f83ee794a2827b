// The snapshot plot (paper Fig. 14) shows each snapshot's whole rod: a catheter reaches back out
// of the vessel through its inlet, past the walls and the path, and the default maze's first
// snapshot was cut off at the top of the axes.
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

namespace vascsim::render {
namespace {

using testing::ScratchDir;
namespace fs = std::filesystem;

TEST(RenderPlotsSnapshots, EverySnapshotsWholeRodIsInThePicture) {
  ScratchDir dir("plots_snapshots");
  // A straight vessel from x = 20 to 60 mm; the rod (40 mm) is pulled back out of it, so its
  // proximal end leaves the vessel: at the last frame it reaches back to x = 0.
  SyntheticLogSpec spec;
  spec.rod_length = 0.04;
  spec.speed = -0.02;
  spec.duration = 1;
  spec.frames = 11;
  spec.cell = 0.01;
  LogMetadata m = synthetic_metadata(spec);
  m.walls = {{{0.02, -0.005}, {0.06, -0.005}, 0.001}, {{0.02, 0.005}, {0.06, 0.005}, 0.001}};
  m.lumen.clear();
  m.path = {{0.02, 0.0}, {0.06, 0.0}};
  m.bounds = {{0.02, -0.0055}, {0.06, 0.0055}};
  m.start = m.path.front();
  m.goal = m.path.back();
  const std::string run = dir / "run";
  fs::create_directories(run);
  write_synthetic_log(run + "/frames.vlog", spec, m);
  write_plots(FrameSource(run), dir / "plots", false);
  const io::PngPixels image = io::read_png(dir / "plots/snapshots.png", 3);

  // The walls' horizontal extent in pixels (#C3CAD2), and the rods' (blue: the darker, the later).
  int wall_left = image.width, wall_right = -1, rod_left = image.width;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = &image.data[(static_cast<std::size_t>(y) * image.width + x) * 3];
      if (std::abs(p[0] - 0xC3) < 4 && std::abs(p[1] - 0xCA) < 4 && std::abs(p[2] - 0xD2) < 4)
        wall_left = std::min(wall_left, x), wall_right = std::max(wall_right, x);
    }
  ASSERT_LT(wall_left, wall_right);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < wall_right; ++x) {
      const std::uint8_t* p = &image.data[(static_cast<std::size_t>(y) * image.width + x) * 3];
      if (p[2] - p[0] > 60 && p[2] - p[1] > 25) rod_left = std::min(rod_left, x);
    }
  // The rod reaches 20 mm left of the walls, half their 40 mm length.
  const double walls_px = wall_right - wall_left;
  EXPECT_LT(rod_left, wall_left - 0.4 * walls_px) << "rod from " << rod_left << " px, walls " << wall_left << ".." << wall_right;
}

}  // namespace
}  // namespace vascsim::render

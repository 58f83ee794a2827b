// The sweep figure's run dots stay by their value: with two values far apart on a numeric axis,
// dots spread over 40 % of the gap between them sat a fifth of the axis from their value, where
// the ticks read other values (kp 0.5 and 2: dots at 0.2 and 0.8 of the gap).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "render/sweep_plot.h"
#include "render_test_util.h"
#include "sim/io/png_file.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;

// The columns (px) holding the run dots' blue (#4C6EF5 at 55 % on white) in [x0, x1).
std::vector<int> blue_columns(const std::vector<std::uint8_t>& rgb, int width, int height, int channels, int x0,
                              int x1) {
  std::vector<int> columns;
  for (int x = x0; x < x1; ++x)
    for (int y = 0; y < height; ++y) {
      const std::uint8_t* p = &rgb[(static_cast<std::size_t>(y) * width + x) * channels];
      if (p[2] > p[0] + 60 && p[2] > p[1] + 40) {
        columns.push_back(x);
        break;
      }
    }
  return columns;
}

TEST(RenderSweepPlot, TheRunDotsOfAValueStayCloseToIt) {
  ScratchDir dir("sweep_plot_dots");
  SweepFigure figure;
  figure.xlabel = "/control/kp";
  figure.x = {0.5, 2.0};
  SweepPanel panel;
  panel.title = "tip error RMS";
  panel.ylabel = "tip error RMS (mm)";
  // Eleven runs per value (eleven seeds), each at its own height so every dot shows.
  for (int j = 0; j < 2; ++j) {
    panel.values.emplace_back();
    for (int k = 0; k < 11; ++k) panel.values.back().push_back(0.2 + 0.1 * k + 0.05 * j);
  }
  panel.failed = {0, 0};
  panel.unknown = {0, 0};
  figure.panels = {panel};
  const std::string path = dir / "kp.png";
  const int width = 1200, height = 900;
  write_sweep_figure(figure, path, width, height);
  const io::PngPixels image = io::read_png(path, 3);
  ASSERT_EQ(image.width, width);
  // Each value's dots lie on one side of the figure's middle (the values are a gap apart).
  const std::vector<int> left = blue_columns(image.data, width, image.height, 3, 0, width / 2);
  const std::vector<int> right = blue_columns(image.data, width, image.height, 3, width / 2, width);
  ASSERT_FALSE(left.empty());
  ASSERT_FALSE(right.empty());
  const double left_centre = 0.5 * (left.front() + left.back()), right_centre = 0.5 * (right.front() + right.back());
  const double gap = right_centre - left_centre;
  ASSERT_GT(gap, 0.2 * width);
  // A dot is 8 px across: the dots of a value span at most 48 px, a small share of the gap.
  EXPECT_LE(left.back() - left.front(), 50) << "gap " << gap << " px";
  EXPECT_LE(right.back() - right.front(), 50) << "gap " << gap << " px";
  EXPECT_LT(left.back() - left.front(), 0.2 * gap);
  // And they still spread: eleven runs are not one column.
  EXPECT_GE(left.back() - left.front(), 20);
}

}  // namespace
}  // namespace vascsim::render

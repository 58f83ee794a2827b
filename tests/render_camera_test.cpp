// The fit camera shows the whole environment: a thick outer wall reaches half its thickness
// beyond the maze bounds, and at every frame size (side panel or not) all four outer walls must
// be on screen and not under the panel. A 640x480 frame once lost the right wall this way.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "render/canvas.h"
#include "render/frame_painter.h"
#include "render/palette.h"

namespace vascsim::render {
namespace {

constexpr Rgba kWallColour = hex(0x3C4650);

LogMetadata boxed_maze() {
  LogMetadata m;
  m.bounds = {Vec2(0, 0), Vec2(1, 1)};
  const double t = 0.1;  // m, the default maze's wall thickness
  m.walls = {{Vec2(0, 0), Vec2(1, 0), t}, {Vec2(1, 0), Vec2(1, 1), t}, {Vec2(1, 1), Vec2(0, 1), t},
             {Vec2(0, 1), Vec2(0, 0), t}};
  m.rod_outer_radius = 0.002;
  return m;
}

bool is_wall(const std::vector<std::uint8_t>& rgba, int width, int height, glm::dvec2 p) {
  const int x = static_cast<int>(std::floor(p.x)), y = static_cast<int>(std::floor(p.y));
  if (x < 0 || y < 0 || x >= width || y >= height) return false;
  const std::uint8_t* c = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
  return std::abs(c[0] - kWallColour.r * 255) < 4 && std::abs(c[1] - kWallColour.g * 255) < 4 &&
         std::abs(c[2] - kWallColour.b * 255) < 4;
}

TEST(RenderCamera, FitShowsEveryThickOuterWallAtEveryFrameSize) {
  const LogMetadata meta = boxed_maze();
  FrameState frame;
  frame.position = {0.4, 0.5, 0.5, 0.5, 0.6, 0.5};
  const int sizes[][2] = {{640, 480}, {1280, 720}, {1920, 1080}, {480, 640}, {400, 400}};
  for (const auto& size : sizes) {
    View view;
    view.width = size[0];
    view.height = size[1];
    FramePainter painter(meta, view, ForceScales{}, frame);
    Canvas canvas(view.width, view.height, AntiAliasing::kNone);
    painter.paint(canvas, frame, {});
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(view.width) * view.height * 4);
    canvas.finish(rgba.data());
    // Just inside each wall's outer face, at the middle of the wall.
    const double inset = 0.05 - 3.0 / painter.pixels_per_metre();
    const Vec2 probes[] = {{0.5, -inset}, {1 + inset, 0.5}, {0.5, 1 + inset}, {-inset, 0.5}};
    for (const Vec2& p : probes)
      EXPECT_TRUE(is_wall(rgba, view.width, view.height, painter.to_pixel(frame, p)))
          << view.width << "x" << view.height << ": outer wall not visible at (" << p.x() << ", " << p.y() << ")";
  }
}

// Thumbnails: at 100x100 and 16x16 the panel's card and bands were taller than the frame, the map
// got a negative height and was drawn mirrored out of sight. The map must keep a positive scale
// and the whole maze in the frame.
TEST(RenderCamera, TinyFramesStillShowTheMap) {
  const LogMetadata meta = boxed_maze();
  FrameState frame;
  frame.position = {0.4, 0.5, 0.5, 0.5, 0.6, 0.5};
  const int sizes[][2] = {{100, 100}, {16, 16}, {40, 16}, {160, 100}};
  for (const auto& size : sizes) {
    View view;
    view.width = size[0];
    view.height = size[1];
    FramePainter painter(meta, view, ForceScales{}, frame);
    EXPECT_GT(painter.pixels_per_metre(), 0.0) << view.width << "x" << view.height;
    for (const Vec2& corner : {Vec2(0, 0), Vec2(1, 1)}) {
      const glm::dvec2 p = painter.to_pixel(frame, corner);
      EXPECT_TRUE(p.x >= 0 && p.x <= view.width && p.y >= 0 && p.y <= view.height)
          << view.width << "x" << view.height << ": corner (" << corner.x() << ", " << corner.y() << ") at " << p.x << ", " << p.y;
    }
  }
}

// Frames without a side panel still explain the arrows: a band below the map carries the two
// force arrows of the legend, and nothing of them lies on the map.
TEST(RenderCamera, NarrowFramesShowTheArrowLegendBelowTheMap) {
  const LogMetadata meta = boxed_maze();
  FrameState frame;
  frame.position = {0.4, 0.5, 0.5, 0.5, 0.6, 0.5};
  ForceScales scales;
  scales.actuation_px_per_newton = 2e4;  // 2 mN draws 40 px
  scales.actuation_reference = 2e-3;
  scales.contact_px_per_newton = 2e4;
  scales.contact_reference = 1e-3;
  for (const auto& size : {std::array<int, 2>{480, 640}, std::array<int, 2>{400, 400}}) {
    View view;
    view.width = size[0];
    view.height = size[1];
    FramePainter painter(meta, view, scales, frame);
    Canvas canvas(view.width, view.height, AntiAliasing::kNone);
    painter.paint(canvas, frame, {});
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(view.width) * view.height * 4);
    canvas.finish(rgba.data());
    const int map_bottom = static_cast<int>(std::ceil(painter.to_pixel(frame, Vec2(0.5, -0.05)).y));
    auto count = [&](Rgba colour, int y0, int y1) {
      int n = 0;
      for (int y = std::max(0, y0); y < std::min(view.height, y1); ++y)
        for (int x = 0; x < view.width; ++x) {
          const std::uint8_t* c = &rgba[(static_cast<std::size_t>(y) * view.width + x) * 4];
          n += std::abs(c[0] - colour.r * 255) < 4 && std::abs(c[1] - colour.g * 255) < 4 &&
               std::abs(c[2] - colour.b * 255) < 4;
        }
      return n;
    };
    const std::string where = std::to_string(view.width) + "x" + std::to_string(view.height);
    EXPECT_GT(count(palette::kActuation, map_bottom, view.height), 40) << where << ": magnetic arrow in the band";
    EXPECT_GT(count(palette::kContact, map_bottom, view.height), 20) << where << ": contact arrow in the band";
    EXPECT_EQ(count(palette::kActuation, 0, map_bottom), 0) << where << ": no arrows were drawn on the map";
  }
}

// A legend arrow means what its label says: where the reference force (2 mN at 100 px/mN, 200 px)
// does not fit a narrow band, a smaller round value is drawn at its true length instead of
// squeezing the 2 mN arrow.
TEST(RenderCamera, LegendArrowThatDoesNotFitShowsARoundValueAtItsTrueLength) {
  const LogMetadata meta = boxed_maze();
  FrameState frame;
  frame.position = {0.4, 0.5, 0.5, 0.5, 0.6, 0.5};
  ForceScales scales;
  scales.actuation_px_per_newton = 1e5;
  scales.actuation_reference = 2e-3;
  View view;
  view.width = 360;
  view.height = 640;
  FramePainter painter(meta, view, scales, frame);
  Canvas canvas(view.width, view.height, AntiAliasing::kNone);
  painter.paint(canvas, frame, {});
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(view.width) * view.height * 4);
  canvas.finish(rgba.data());
  const int map_bottom = static_cast<int>(std::ceil(painter.to_pixel(frame, Vec2(0.5, -0.05)).y));
  int first = view.width, last = -1;
  for (int y = map_bottom; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x) {
      const std::uint8_t* c = &rgba[(static_cast<std::size_t>(y) * view.width + x) * 4];
      if (std::abs(c[0] - palette::kActuation.r * 255) < 4 && std::abs(c[1] - palette::kActuation.g * 255) < 4 &&
          std::abs(c[2] - palette::kActuation.b * 255) < 4)
        first = std::min(first, x), last = std::max(last, x);
    }
  ASSERT_GE(last, first) << "the magnetic legend arrow is drawn";
  const double length_px = last - first + 1;
  ASSERT_LT(length_px, 180.0) << "200 px cannot fit in half of a 360 px band";
  // The drawn force, 1 / 100 mN per px, is one of 1, 2, 5 x 10^k mN (within the 2 px of the
  // arrow's rasterised ends).
  const double drawn_mn = length_px / 100.0;
  const double decade = std::pow(10.0, std::floor(std::log10(drawn_mn * 1.05)));
  bool round = false;
  for (const double m : {1.0, 2.0, 5.0, 10.0}) round |= std::abs(drawn_mn - m * decade) * 100.0 <= 2.0;
  EXPECT_TRUE(round) << "drawn arrow of " << length_px << " px is " << drawn_mn << " mN, not a round value";
}

}  // namespace
}  // namespace vascsim::render

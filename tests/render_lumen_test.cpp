// The lumen as the log's rings draw it: an annulus (a ring-shaped vessel around a hole) is filled
// in the lumen colour with no seam anywhere inside, its hole and the outside are not, the walls
// drawn on top cover its edge, the fit camera shows the rings; a maze's lumen (its bounds as one
// rectangle) draws exactly the picture of a log without rings; and Canvas::region draws every
// pixel once, so even a translucent fill is flat, in every anti-aliasing mode.
#include <gtest/gtest.h>

#include <cmath>

#include "render/canvas.h"
#include "render/frame_painter.h"
#include "render/frame_source.h"
#include "render/polygon_fill.h"
#include "render/view_frame.h"
#include "render_test_util.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;

constexpr double kPi = 3.14159265358979323846;
constexpr Rgba kLumenColour = hex(0xFCEFEA);  // frame_painter.cpp's kLumen
constexpr Rgba kWallColour = hex(0x3C4650);

using testing::annulus_metadata;
using testing::circle;
using testing::kCentre;
using testing::kInner;
using testing::kOuter;

struct Picture {
  std::vector<std::uint8_t> rgba;
  ViewTransform camera;
  int width = 0, height = 0;
  const std::uint8_t* at(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
  // World point (m) of pixel (x, y)'s centre.
  Vec2 world(int x, int y) const {
    return {(x + 0.5 - camera.ox) / camera.scale, (camera.oy - (y + 0.5)) / camera.scale};
  }
};

Picture render(const std::string& run, View view, double t = 0.5) {
  FrameSource source(run);
  ViewFrameInputs in;
  in.source = &source;
  in.peaks = measure_force_peaks(source);
  Canvas canvas(view.width, view.height);
  Picture p;
  p.width = view.width;
  p.height = view.height;
  p.camera = render_view_frame(canvas, in, view, t, p.rgba).transform;
  return p;
}

int difference(const std::uint8_t* px, Rgba c) {
  return std::max({std::abs(px[0] - static_cast<int>(std::lround(c.r * 255))),
                   std::abs(px[1] - static_cast<int>(std::lround(c.g * 255))),
                   std::abs(px[2] - static_cast<int>(std::lround(c.b * 255)))});
}

using testing::write_log;

TEST(RenderLumen, AnnulusIsFilledWithoutSeams) {
  ScratchDir dir("lumen_annulus");
  const std::string log = write_log(dir, "annulus", annulus_metadata());
  View view;
  view.width = 480;
  view.height = 360;
  view.layers = LayerSet::none();
  view.layers.set(Layer::kLumen, true);
  const Picture p = render(log, view);
  const double margin = 1.5 / p.camera.scale;  // m: beyond the edge's anti-aliasing
  int lumen = 0, hole = 0, outside = 0;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      const double r = (p.world(x, y) - kCentre).norm();
      const int d = difference(p.at(x, y), kLumenColour);
      if (r > kInner + margin && r < kOuter - margin) {
        ++lumen;
        // Every pixel of the lumen, so every row through it too: a seam shows as any other value.
        if (d > 1) ADD_FAILURE() << "pixel (" << x << ", " << y << ") in the lumen is off by " << d;
      } else if (r < kInner - margin) {
        ++hole;
        EXPECT_GT(d, 8) << "pixel (" << x << ", " << y << ") in the hole has the lumen colour";
      } else if (r > kOuter + margin) {
        ++outside;
        EXPECT_GT(d, 8) << "pixel (" << x << ", " << y << ") outside the ring has the lumen colour";
      }
      if (::testing::Test::HasFailure()) return;
    }
  EXPECT_GT(lumen, 20000);
  EXPECT_GT(hole, 5000);
  EXPECT_GT(outside, 20000);
  // One row through the middle, explicitly: across both sides of the ring, nothing but lumen.
  const int row = static_cast<int>(std::floor(p.camera.oy - kCentre.y() * p.camera.scale));
  int checked = 0;
  for (int x = 0; x < p.width; ++x) {
    const double r = std::abs(p.world(x, row).x() - kCentre.x());
    if (r > kInner + margin && r < kOuter - margin) {
      EXPECT_LE(difference(p.at(x, row), kLumenColour), 1) << "row " << row << ", x " << x;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(RenderLumen, WallsCoverTheLumenEdge) {
  ScratchDir dir("lumen_walls");
  const std::string log = write_log(dir, "annulus", annulus_metadata());
  View view;
  view.width = 480;
  view.height = 360;
  view.layers = LayerSet::none();
  view.layers.set(Layer::kLumen, true);
  view.layers.set(Layer::kWalls, true);
  const Picture p = render(log, view);
  // On both outlines at 200 angles the pixel is wall, and 2.5 px outside the outer one the
  // lumen's anti-aliasing has faded out.
  for (int i = 0; i < 200; ++i) {
    const double a = 2 * kPi * i / 200;
    for (const double r : {kInner, kOuter}) {
      const Vec2 w = kCentre + r * Vec2(std::cos(a), std::sin(a));
      const int x = static_cast<int>(std::floor(p.camera.ox + w.x() * p.camera.scale));
      const int y = static_cast<int>(std::floor(p.camera.oy - w.y() * p.camera.scale));
      EXPECT_LE(difference(p.at(x, y), kWallColour), 40) << "no wall at radius " << r << ", angle " << a;
    }
    const Vec2 w = kCentre + (kOuter + 2.5 / p.camera.scale) * Vec2(std::cos(a), std::sin(a));
    const int x = static_cast<int>(std::floor(p.camera.ox + w.x() * p.camera.scale));
    const int y = static_cast<int>(std::floor(p.camera.oy - w.y() * p.camera.scale));
    EXPECT_GT(difference(p.at(x, y), kLumenColour), 8) << "lumen colour outside the wall at angle " << a;
  }
}

TEST(RenderLumen, FitCameraShowsTheRings) {
  // No bounds: the fit camera frames the rings (and the path and rod), all of them on the map.
  LogMetadata m = annulus_metadata();
  m.bounds = {};
  m.lumen[0] = circle(kCentre + Vec2(0.01, 0), 0.03, 120);  // reaches beyond everything else
  FrameState frame;
  frame.position = {0.025, 0.01, 0.026, 0.01};
  View view;
  view.width = 640;
  view.height = 480;
  view.layers.set(Layer::kHud, false);
  view.layers.set(Layer::kLegend, false);  // no panel: the map is the whole frame
  FramePainter painter(m, view, ForceScales{}, frame);
  for (const auto& ring : m.lumen)
    for (const Vec2& w : ring) {
      const glm::dvec2 px = painter.to_pixel(frame, w);
      EXPECT_TRUE(px.x >= 0 && px.y >= 0 && px.x < view.width && px.y < view.height)
          << "lumen point (" << w.x() << ", " << w.y() << ") at pixel (" << px.x << ", " << px.y << ")";
    }
}

TEST(RenderLumen, MazeRectangleDrawsThePictureOfALogWithout) {
  ScratchDir dir("lumen_maze");
  const SyntheticLogSpec spec;
  const LogMetadata plain = synthetic_metadata(spec);
  const Vec2 lo = plain.bounds.min, hi = plain.bounds.max;
  View view;
  view.width = 320;
  view.height = 240;
  const Picture reference = render(write_log(dir, "plain", plain), view);
  // As navigation logs it (counter-clockwise from the lower left), and two other ways to write it.
  const std::vector<Polyline> rings = {{lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}},
                                       {hi, {hi.x(), lo.y()}, lo, {lo.x(), hi.y()}, hi},
                                       {{lo.x(), hi.y()}, lo, {hi.x(), lo.y()}, hi}};
  for (std::size_t i = 0; i < rings.size(); ++i) {
    LogMetadata m = plain;
    m.lumen = {rings[i]};
    const Picture p = render(write_log(dir, "ring" + std::to_string(i), m), view);
    EXPECT_TRUE(p.rgba == reference.rgba) << "ring " << i << " changed the maze picture";
  }
  // The render test's fixture: a lumen that is not the bounds does change it.
  LogMetadata m = plain;
  m.lumen = {circle(0.5 * (lo + hi), 0.4 * (hi - lo).x(), 64)};
  EXPECT_FALSE(render(write_log(dir, "round", m), view).rgba == reference.rgba);
}

TEST(RenderLumen, RegionDrawsEachPixelOnce) {
  // A translucent annulus over white: overlapping triangles would show darker lines.
  const int size = 200;
  const std::vector<Triangle> ts =
      triangulate_even_odd({circle(Vec2(100, 100), 90, 150, 0.1), circle(Vec2(95, 100), 40, 90, 0.2)});
  std::vector<glm::vec2> tri;
  for (const auto& t : ts)
    for (const Vec2* v : {&t.a, &t.b, &t.c}) tri.push_back({static_cast<float>(v->x()), static_cast<float>(v->y())});
  for (const AntiAliasing aa : {AntiAliasing::kAnalytic, AntiAliasing::kMsaa4, AntiAliasing::kNone}) {
    Canvas c(size, size, aa);
    c.clear(hex(0xFFFFFF));
    c.region(tri, {}, hex(0x1B3A5C, 0.5f));
    std::vector<std::uint8_t> rgba(size * size * 4);
    c.finish(rgba.data());
    const std::uint8_t* first = nullptr;
    int inside = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const Vec2 p(x + 0.5, y + 0.5);
        if ((p - Vec2(100, 100)).norm() > 89 || (p - Vec2(95, 100)).norm() < 41) continue;
        const std::uint8_t* px = &rgba[(static_cast<std::size_t>(y) * size + x) * 4];
        if (!first) first = px;
        ++inside;
        ASSERT_TRUE(std::equal(px, px + 3, first))
            << "aa " << static_cast<int>(aa) << ": pixel (" << x << ", " << y << ") is " << int(px[0]) << ","
            << int(px[1]) << "," << int(px[2]) << ", the first inside " << int(first[0]) << "," << int(first[1])
            << "," << int(first[2]);
      }
    EXPECT_GT(inside, 15000);
    ASSERT_TRUE(first);
    EXPECT_NEAR(first[0], 0.5 * 255 + 0.5 * 0x1B, 1.5) << "drawn once: half way from white to the colour";
  }
}

}  // namespace
}  // namespace vascsim::render

// Geometry far off the canvas (a log with a path point 10^12 m away, a view zoomed a thousand
// times) must cost what the canvas shows, not what the geometry spans: found by the frame-log
// fuzz harness, a dashed path segment queued one dash per 7 px of its length until memory ran
// out (tests/fuzz/regressions/frame_log/). And plot ticks for ranges no double can step through.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "render/canvas.h"
#include "render/number_format.h"

namespace vascsim::render {
namespace {

constexpr int kW = 64, kH = 40;

TEST(FarGeometry, DashedSegmentFarLongerThanTheCanvasQueuesOnlyTheVisibleDashes) {
  Canvas canvas(kW, kH, AntiAliasing::kNone);
  canvas.dashed_polyline({{-1e9f, 20}, {1e9f, 20}, {1e9f, -3e9f}, {30, 1e12f}}, 2, 4, 3, hex(0x000000));
  // Two crossings of the canvas at 7 px per dash, plus a few at the edges.
  EXPECT_LE(canvas.queued_shapes(), 2u * (kW + kH) / 7 + 8);
  EXPECT_GE(canvas.queued_shapes(), 6u) << "the visible stretches are still dashed";
  std::vector<std::uint8_t> rgba(kW * kH * 4);
  canvas.finish(rgba.data());
}

TEST(FarGeometry, DashPatternKeepsItsPhaseAcrossTheInvisiblePart) {
  // A 1 px line from x = -1000 to the right edge: dash 4, gap 3, so the pixel column whose
  // centre is at x is inked when (x + 1000) mod 7 < 4 (away from the dash ends).
  Canvas canvas(kW, kH, AntiAliasing::kNone);
  canvas.clear(hex(0xFFFFFF));
  canvas.dashed_polyline({{-1000, 20.5f}, {kW, 20.5f}}, 1, 4, 3, hex(0x000000));
  std::vector<std::uint8_t> rgba(kW * kH * 4);
  canvas.finish(rgba.data());
  int checked = 0;
  for (int col = 0; col < kW; ++col) {
    const double u = std::fmod(col + 0.5 + 1000, 7.0);
    const bool ink = rgba[(20 * kW + col) * 4] < 128;
    if (u > 1 && u < 3) {
      EXPECT_TRUE(ink) << "column " << col << " should be inside a dash";
    }
    if (u > 4.5 && u < 6.5) {
      EXPECT_FALSE(ink) << "column " << col << " should be inside a gap";
    }
    checked += (u > 1 && u < 3) || (u > 4.5 && u < 6.5);
  }
  EXPECT_GT(checked, 20);
}

TEST(FarGeometry, AFrameQueuesAtMostTheCanvasLimitsAndCountsWhatItDrops) {
  // A path of more visible points than the limit (a log with millions of path points winding
  // over the map): memory stays bounded, the frame still draws, and the drop is counted.
  Canvas canvas(kW, kH, AntiAliasing::kNone);
  std::vector<glm::vec2> zigzag(Canvas::kMaxShapes + 1000);
  for (std::size_t k = 0; k < zigzag.size(); ++k) zigzag[k] = {float(k % kW), float(k % 2 ? 5 : 35)};
  canvas.polyline(zigzag, 1, hex(0x000000));
  EXPECT_EQ(canvas.queued_shapes(), Canvas::kMaxShapes);
  EXPECT_EQ(canvas.dropped(), zigzag.size() - 1 - Canvas::kMaxShapes);
  canvas.dashed_polyline({{0, 1}, {float(kW), 1}}, 1, 4, 3, hex(0x000000));  // nothing more fits
  EXPECT_EQ(canvas.queued_shapes(), Canvas::kMaxShapes);
  const std::size_t before = canvas.dropped();
  canvas.text(std::string(Canvas::kMaxVertices / 6 + 1, 'x'), {0, 20}, 12, hex(0x000000));
  EXPECT_GT(canvas.dropped(), before) << "a text of more glyphs than the vertex limit is dropped";
  std::vector<std::uint8_t> rgba(kW * kH * 4);
  canvas.finish(rgba.data());
  EXPECT_EQ(canvas.queued_shapes(), 0u);
}

TEST(FarGeometry, TicksOfRangesNoDoubleCanStepThroughAreTheEnds) {
  EXPECT_EQ(nice_ticks(-1e308, 1e308, 8), (std::vector<double>{-1e308, 1e308}));  // hi - lo overflows
  EXPECT_EQ(nice_ticks(1e17, 1e17 + 64, 8), (std::vector<double>{1e17, 1e17 + 64}));  // step < ulp
  const std::vector<double> ordinary = nice_ticks(0, 1, 5);  // unchanged: 0, 0.2, ..., 1
  ASSERT_EQ(ordinary.size(), 6u);
  for (std::size_t k = 0; k < ordinary.size(); ++k) EXPECT_NEAR(ordinary[k], 0.2 * k, 1e-12);
}

}  // namespace
}  // namespace vascsim::render

// Force arrows point the right way and scale right: a straight rod with a known magnetic force
// on the tip and known contact forces on two nodes, drawn without anti-aliasing at an explicit
// px-per-newton scale, then found again by colour in the pixels.
#include <gtest/gtest.h>

#include <cmath>

#include "render/canvas.h"
#include "render/frame_painter.h"
#include "render/frame_source.h"
#include "render_test_util.h"
#include "sim/log/frame_log.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;
namespace fs = std::filesystem;

constexpr int kW = 320, kH = 240;
constexpr int kNodes = 11;

// Rod along +x at y = 20 mm from x = 10 to 30 mm. Magnetic force +x 1 mN on the tip (and
// `tip_force_y` N along +y); contact +y 2 mN on node 3 (world up) and -y 1 mN on node 7.
std::string write_log(const ScratchDir& dir, double tip_force_y = 0) {
  LogMetadata m;
  m.bounds = {Vec2(0, 0), Vec2(0.04, 0.04)};
  m.rod_outer_radius = 0.0003;
  FrameLogHeader h;
  h.node_count = kNodes;
  h.channels = {{channel::kPosition, "m", ChannelLayout::kNodeVectors, 2 * kNodes},
                {channel::kActuationForce, "N", ChannelLayout::kNodeVectors, 2 * kNodes},
                {channel::kContactForce, "N", ChannelLayout::kNodeVectors, 2 * kNodes}};
  h.metadata = write_log_metadata(m);
  const std::string path = dir / (tip_force_y == 0 ? "arrows.vlog" : "arrows_diagonal.vlog");
  FrameLogWriter w(path, h);
  std::vector<double> v(6 * kNodes, 0.0);
  for (int i = 0; i < kNodes; ++i) {
    v[2 * i] = 0.010 + 0.002 * i;
    v[2 * i + 1] = 0.020;
  }
  v[2 * kNodes + 2 * (kNodes - 1)] = 1e-3;
  v[2 * kNodes + 2 * (kNodes - 1) + 1] = tip_force_y;
  v[4 * kNodes + 2 * 3 + 1] = 2e-3;
  v[4 * kNodes + 2 * 7 + 1] = -1e-3;
  w.append(0.0, v);
  w.close();
  return path;
}

struct Picture {
  std::vector<std::uint8_t> rgba = std::vector<std::uint8_t>(kW * kH * 4);
  bool is(int x, int y, Rgba c) const {
    if (x < 0 || y < 0 || x >= kW || y >= kH) return false;
    const std::uint8_t* p = &rgba[(y * kW + x) * 4];
    return std::abs(p[0] - c.r * 255) < 4 && std::abs(p[1] - c.g * 255) < 4 && std::abs(p[2] - c.b * 255) < 4;
  }
};

constexpr Rgba kActuationColour = hex(0xAE3EC9), kContactColour = hex(0xE8590C);

// Steps from `from` along (dx, dy) and returns the last step (px) still showing `c`.
int extent(const Picture& p, glm::dvec2 from, int dx, int dy, Rgba c) {
  int last = -1;
  for (int s = 0; s < 200; ++s)
    if (p.is(static_cast<int>(std::floor(from.x)) + dx * s, static_cast<int>(std::floor(from.y)) + dy * s, c)) last = s;
  return last;
}

void draw(const std::string& log, double act_scale, double con_scale, Picture& pic, FramePainter** painter_out,
          FrameState& state, AntiAliasing aa = AntiAliasing::kNone) {
  FrameSource source(log);
  View view;
  view.width = kW;
  view.height = kH;
  view.layers.set(Layer::kHud, false).set(Layer::kLegend, false);
  view.actuation_px_per_newton = act_scale;
  view.contact_px_per_newton = con_scale;
  source.frame(0, state);
  const ForceScales scales = choose_force_scales(source, view);
  static std::unique_ptr<FramePainter> painter;
  painter = std::make_unique<FramePainter>(source.metadata(), view, scales, state);
  Canvas canvas(kW, kH, aa);
  painter->paint(canvas, state, {});
  canvas.finish(pic.rgba.data());
  *painter_out = painter.get();
}

TEST(RenderArrows, PointAlongTheForceAndScaleWithIt) {
  ScratchDir dir("arrows");
  const std::string log = write_log(dir);
  Picture pic;
  FramePainter* painter = nullptr;
  FrameState state;
  draw(log, 40000.0, 20000.0, pic, &painter, state);  // 1 mN -> 40 px; 2 mN contact -> 40 px

  const glm::dvec2 tip = painter->to_pixel(state, state.tip());
  EXPECT_NEAR(extent(pic, tip, +1, 0, kActuationColour), 40, 2) << "magnetic arrow: +x, 40 px";
  EXPECT_LT(extent(pic, tip, -1, 0, kActuationColour), 3) << "nothing magnetic behind the tip";

  const glm::dvec2 n3 = painter->to_pixel(state, state.node(3)), n7 = painter->to_pixel(state, state.node(7));
  EXPECT_NEAR(extent(pic, n3, 0, -1, kContactColour), 40, 2) << "node 3: +y in the world is up on screen";
  EXPECT_LT(extent(pic, n3, 0, +1, kContactColour), 3);
  EXPECT_NEAR(extent(pic, n7, 0, +1, kContactColour), 20, 2) << "node 7: -y, half the force, half the length";
  EXPECT_LT(extent(pic, n7, 0, -1, kContactColour), 3);
  // No arrow at a node without contact.
  EXPECT_LT(extent(pic, painter->to_pixel(state, state.node(5)), 0, -1, kContactColour), 0);

  // Doubling the scale doubles the length.
  Picture twice;
  draw(log, 80000.0, 20000.0, twice, &painter, state);
  EXPECT_NEAR(extent(twice, tip, +1, 0, kActuationColour), 80, 2);

  // A scale that takes arrows far off the frame draws them to its edge (at 1e12 px/N and more
  // they were not drawn at all: a slanting arrow's width was lost to float precision in the
  // analytic anti-aliasing's shader).
  const std::string diagonal = write_log(dir, 1e-3);
  for (const double huge : {1e12, 1e15}) {
    Picture off;
    draw(diagonal, huge, huge, off, &painter, state, AntiAliasing::kAnalytic);
    const int to_edge = std::min({199, kW - 1 - static_cast<int>(tip.x), static_cast<int>(tip.y)});
    EXPECT_GE(extent(off, tip, +1, -1, kActuationColour), to_edge - 2) << huge;
    EXPECT_GE(extent(off, n3, 0, -1, kContactColour), std::min(199, static_cast<int>(n3.y))) << huge;
  }
}

TEST(RenderArrows, AutomaticScaleKeepsTheLargestArrowOnScreen) {
  ScratchDir dir("arrows_auto");
  const std::string log = write_log(dir);
  Picture pic;
  FramePainter* painter = nullptr;
  FrameState state;
  draw(log, 0, 0, pic, &painter, state);
  const glm::dvec2 tip = painter->to_pixel(state, state.tip());
  const int len = extent(pic, tip, +1, 0, kActuationColour);
  EXPECT_GT(len, 15);
  EXPECT_LT(len, kH / 3);
}

}  // namespace
}  // namespace vascsim::render

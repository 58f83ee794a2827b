// The `supports` layer draws how the scene holds the rod, where it holds it: a clamp's wall across
// the root with hatching behind it and nothing ahead; a pin's triangle under its node; a roller's
// under its node (it holds y), a slider's to the left of its node (it holds x); a ring round a node
// moved kinematically. Checked by where ink lands around each held node, so a symbol drawn at the
// wrong node or facing the wrong way fails; and a log that holds nothing draws nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "render/canvas.h"
#include "render/frame_painter.h"

namespace vascsim::render {
namespace {

constexpr int kWidth = 640, kHeight = 480;
constexpr int kNodes = 9;

// A straight rod from (0.2, 0.5) to (0.8, 0.5) m in a free rod's bounds, nothing but the supports
// layer on, drawn with hard edges.
struct Picture {
  std::vector<std::uint8_t> rgba;
  std::vector<glm::dvec2> node_px;
  double rod_px = 0;  // the rod's drawn radius
  std::vector<FramePainter::PanelItem> panel;

  // Pixels of ink (every channel darker than the light page) in the box [x0, x1) x [y0, y1),
  // offsets in rod radii from node `node`'s pixel.
  int ink(glm::dvec2 at, double x0, double x1, double y0, double y1) const {
    int n = 0;
    for (int y = static_cast<int>(std::floor(at.y + y0 * rod_px)); y < static_cast<int>(std::ceil(at.y + y1 * rod_px)); ++y)
      for (int x = static_cast<int>(std::floor(at.x + x0 * rod_px)); x < static_cast<int>(std::ceil(at.x + x1 * rod_px)); ++x) {
        if (x < 0 || y < 0 || x >= kWidth || y >= kHeight) continue;
        const std::uint8_t* c = &rgba[(static_cast<std::size_t>(y) * kWidth + x) * 4];
        if (std::max({c[0], c[1], c[2]}) < 110) ++n;
      }
    return n;
  }
  int ink_at_node(int node, double x0, double x1, double y0, double y1) const {
    return ink(node_px[static_cast<std::size_t>(node)], x0, x1, y0, y1);
  }
};

Picture paint(const BoundarySpec& holds, LayerSet layers = LayerSet::none().set(Layer::kSupports, true)) {
  LogMetadata meta;
  meta.bounds = {Vec2(0, 0), Vec2(1, 1)};
  meta.boundary = holds;
  FrameState frame;
  for (int i = 0; i < kNodes; ++i) {
    frame.position.push_back(0.2 + 0.6 * i / (kNodes - 1));
    frame.position.push_back(0.5);
  }
  View view;
  view.width = kWidth;
  view.height = kHeight;
  view.layers = layers;
  // A rod 4 px in radius: the symbols, a few rod widths across, stay apart at 34 px per edge.
  meta.rod_outer_radius = 4.0 / FramePainter(meta, view, ForceScales{}, frame).pixels_per_metre();
  FramePainter painter(meta, view, ForceScales{}, frame);
  Canvas canvas(kWidth, kHeight, AntiAliasing::kNone);
  painter.paint(canvas, frame, {});
  Picture p;
  p.rgba.resize(static_cast<std::size_t>(kWidth) * kHeight * 4);
  canvas.finish(p.rgba.data());
  for (int i = 0; i < kNodes; ++i) p.node_px.push_back(painter.to_pixel(frame, frame.node(static_cast<std::size_t>(i))));
  p.rod_px = meta.rod_outer_radius * painter.pixels_per_metre();
  p.panel = painter.panel_items();
  EXPECT_NEAR(p.rod_px, 4.0, 1e-9);
  return p;
}

TEST(RenderSupports, EachSymbolIsDrawnAtItsNodeFacingTheWayItHolds) {
  BoundarySpec holds;
  holds.clamp = ClampKind::kFirstEdge;
  holds.pinned = {4};
  holds.supports = {{6, SupportAxis::kY}, {8, SupportAxis::kX}};
  holds.prescribed = {{2, Vec2(0.01, 0), Vec2::Zero(), 0.0}};
  const Picture p = paint(holds);

  // Clamp at node 0 (screen y grows downwards): its wall runs across the rod, above and below the
  // root; its hatching lies behind the root; nothing ahead of it, where the rod goes.
  EXPECT_GT(p.ink_at_node(0, -0.5, 0.5, -4, -1.5), 0) << "the clamp's wall above the root";
  EXPECT_GT(p.ink_at_node(0, -0.5, 0.5, 1.5, 4), 0) << "the clamp's wall below the root";
  EXPECT_GT(p.ink_at_node(0, -3, -0.6, -3, 3), 0) << "the hatching behind the clamp";
  EXPECT_EQ(p.ink_at_node(0, 1.5, 5, -3, 3), 0) << "ink ahead of the clamp, along the rod";

  // Pin at node 4: a triangle under the node, nothing above; its hinge a light dot at the node.
  EXPECT_GT(p.ink_at_node(4, -1, 1, 1.5, 3), 0) << "the pin's triangle under its node";
  EXPECT_EQ(p.ink_at_node(4, -3, 3, -6, -1.5), 0) << "ink above the pin";
  EXPECT_EQ(p.ink_at_node(4, -0.2, 0.2, -0.2, 0.2), 0) << "the pin's hinge is not light";

  // The roller at node 6 (holds y) stands under its node; the slider at node 8 (holds x) to its left.
  EXPECT_GT(p.ink_at_node(6, -1, 1, 1.5, 3), 0) << "the roller's triangle under its node";
  EXPECT_EQ(p.ink_at_node(6, -3, 3, -6, -1.5), 0) << "ink above the roller";
  EXPECT_GT(p.ink_at_node(8, -3, -1.5, -1, 1), 0) << "the slider's triangle left of its node";
  EXPECT_EQ(p.ink_at_node(8, 1.5, 6, -3, 3), 0) << "ink right of the slider";
  EXPECT_EQ(p.ink_at_node(8, -1, 1, 1.5, 6), 0) << "ink under the slider";
  // Rollers make the supports deeper than the pin: ink further down under node 6 than under node 4.
  const auto depth = [&](int node) {
    double deepest = 0;
    for (double y = 0; y < 12; y += 0.25)
      if (p.ink_at_node(node, -3, 3, y, y + 0.25) > 0) deepest = y;
    return deepest;
  };
  EXPECT_GT(depth(6), depth(4) + 0.5) << "the roller has no rollers under its triangle";

  // The kinematically moved node 2: a ring round it, light inside.
  for (const auto& [x0, x1, y0, y1] : {std::array<double, 4>{1.2, 2.8, -0.3, 0.3}, {-2.8, -1.2, -0.3, 0.3},
                                      {-0.3, 0.3, 1.2, 2.8}, {-0.3, 0.3, -2.8, -1.2}})
    EXPECT_GT(p.ink_at_node(2, x0, x1, y0, y1), 0) << "no ring round the moved node at " << x0 << ", " << y0;
  EXPECT_EQ(p.ink_at_node(2, -0.8, 0.8, -0.8, 0.8), 0) << "the ring is filled";

  // Nodes nothing holds have no symbol.
  for (int free_node : {1, 3, 5, 7})
    EXPECT_EQ(p.ink_at_node(free_node, -1, 1, -6, -1.5), 0) << "ink above node " << free_node;
}

TEST(RenderSupports, ACentredClampStandsBetweenTheFirstTwoNodes) {
  BoundarySpec holds;
  holds.clamp = ClampKind::kCentred;
  const Picture p = paint(holds);
  const glm::dvec2 root = 0.5 * (p.node_px[0] + p.node_px[1]);
  EXPECT_GT(p.ink(root, -0.5, 0.5, -4, -1.5), 0) << "the wall above the clamp's centre";
  EXPECT_EQ(p.ink_at_node(0, -0.5, 0.5, -4, -1.5), 0) << "a wall at node 0";
  EXPECT_EQ(p.ink_at_node(1, -0.5, 0.5, -4, -1.5), 0) << "a wall at node 1";
}

TEST(RenderSupports, NothingIsDrawnForARodHeldByNothingOrByNodesOutsideIt) {
  EXPECT_EQ(paint(BoundarySpec{}).ink(glm::dvec2(0, 0), 0, kWidth / 4.0, 0, kHeight / 4.0), 0);
  BoundarySpec past_the_end;  // a hand-edited log
  past_the_end.pinned = {kNodes, -1};
  past_the_end.supports = {{kNodes + 5, SupportAxis::kX}};
  past_the_end.prescribed = {{1000000, Vec2::Zero(), Vec2::Zero(), 0.0}};
  EXPECT_EQ(paint(past_the_end).ink(glm::dvec2(0, 0), 0, kWidth / 4.0, 0, kHeight / 4.0), 0);
}

// The legend names each kind of support the map draws, once, with its symbol in the entry's row in
// the map's ink; not a kind held only at nodes outside the rod, and nothing with the layer off.
TEST(RenderSupports, TheLegendNamesEachKindTheMapDrawsWithItsSymbol) {
  BoundarySpec holds;
  holds.clamp = ClampKind::kFirstEdge;
  holds.pinned = {4, 5, kNodes};
  holds.supports = {{8, SupportAxis::kX}};
  holds.prescribed = {{1000000, Vec2::Zero(), Vec2::Zero(), 0.0}};
  const LayerSet with_legend = LayerSet::none().set(Layer::kSupports, true).set(Layer::kLegend, true);
  const Picture p = paint(holds, with_legend);
  std::vector<std::string> labels;
  for (const auto& item : p.panel) {
    if (std::string(item.what) != "legend" || item.label.rfind("catheter", 0) == 0) continue;
    labels.push_back(item.label);
    // The symbol's column: left of the text, which starts 2.8 font sizes in (an entry's box is
    // 1.35 font sizes high).
    const double symbol_right = item.left + 2.5 / 1.35 * (item.bottom - item.top);
    int ink = 0;
    for (int y = static_cast<int>(item.top); y < static_cast<int>(item.bottom); ++y)
      for (int x = static_cast<int>(item.left); x < static_cast<int>(symbol_right); ++x) {
        const std::uint8_t* c = &p.rgba[(static_cast<std::size_t>(y) * kWidth + x) * 4];
        if (c[0] == 0x34 && c[1] == 0x3A && c[2] == 0x40) ++ink;  // the supports' ink (palette kSupport)
      }
    EXPECT_GT(ink, 10) << "no symbol beside \"" << item.label << "\"";
  }
  EXPECT_EQ(labels, (std::vector<std::string>{"clamped root", "pinned node", "held in x, slides in y"}));

  holds.supports = {{1, SupportAxis::kY}};
  holds.prescribed = {{2, Vec2(0.01, 0), Vec2::Zero(), 0.0}};
  labels.clear();
  for (const auto& item : paint(holds, with_legend).panel)
    if (std::string(item.what) == "legend" && item.label.rfind("catheter", 0) != 0) labels.push_back(item.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"clamped root", "pinned node", "held in y, slides in x", "prescribed motion"}));

  for (const auto& item : paint(holds, LayerSet::none().set(Layer::kLegend, true)).panel)
    EXPECT_TRUE(std::string(item.what) != "legend" || item.label.rfind("catheter", 0) == 0)
        << "\"" << item.label << "\" in the legend of a map without supports";
}

}  // namespace
}  // namespace vascsim::render

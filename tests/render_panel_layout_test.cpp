// The frame's panel at any size: the HUD, the legend entries and the scale bar never overlap
// one another and stay inside the frame (a 320 x 180 thumbnail drew "start, goal" over the
// scale bar; a 160 x 120 one drew the HUD's values over the map without their labels). What
// does not fit is left out, the force arrows last among the legend entries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "render/canvas.h"
#include "render/frame_painter.h"
#include "render/frame_source.h"
#include "render_test_util.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;

std::vector<FramePainter::PanelItem> panel_at(const std::string& run, int width, int height) {
  return testing::paint_last_frame(run, width, height).items;
}

std::size_t count(const std::vector<FramePainter::PanelItem>& items, const std::string& what) {
  std::size_t n = 0;
  for (const auto& item : items) n += what == item.what;
  return n;
}

TEST(RenderPanelLayout, NothingOverlapsOrLeavesTheFrameAtAnySize) {
  ScratchDir dir("panel_layout");
  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  // A failed run's HUD has a row more (render_failed_run_test.cpp).
  const std::string failed = testing::make_run(dir, SyntheticLogSpec{}, "failed");
  testing::write_bytes(failed + "/summary.json",
                       R"({"ok": false, "failure": "Newton did not converge", "frames": 10, "simulated_time": 1.04})");
  // A fed run's HUD has two rows more (the feed's push and length).
  SyntheticLogSpec fed_spec;
  fed_spec.feed = true;
  const std::string fed = testing::make_run(dir, fed_spec, "fed");
  // A rod held every way has five legend entries more (its supports).
  const std::string held = dir / "held";
  std::filesystem::create_directories(held);
  LogMetadata held_metadata = synthetic_metadata(SyntheticLogSpec{});
  held_metadata.boundary.clamp = ClampKind::kFirstEdge;
  held_metadata.boundary.pinned = {10};
  held_metadata.boundary.supports = {{20, SupportAxis::kY}, {39, SupportAxis::kX}};
  held_metadata.boundary.prescribed = {{30, Vec2(0.01, 0), Vec2::Zero(), 0.0}};
  write_synthetic_log(held + "/frames.vlog", SyntheticLogSpec{}, held_metadata);
  ASSERT_EQ(count(panel_at(held, 1280, 720), "legend"), count(panel_at(run, 1280, 720), "legend") + 5);
  const auto hud_rows = [&](const std::string& path) { return path == failed ? 5u : path == fed ? 6u : 4u; };
  const auto name = [&](const std::string& path) {
    return path == failed ? " (failed run)" : path == fed ? " (fed run)" : path == held ? " (held rod)" : "";
  };
  const std::vector<std::pair<int, int>> sizes = {{1280, 720}, {640, 360}, {480, 270}, {320, 180}, {320, 240},
                                                  {640, 120}, {1200, 100}, {160, 120}, {240, 320}, {120, 90}};
  for (const std::string& path : {run, failed, fed, held})
  for (const auto& [w, h] : sizes) {
    const auto items = panel_at(path, w, h);
    const std::string size = std::to_string(w) + " x " + std::to_string(h) + name(path);
    ASSERT_FALSE(items.empty()) << size;
    EXPECT_STREQ(items.front().what, "hud") << size;
    for (std::size_t k = 0; k < items.size(); ++k) {
      EXPECT_GE(items[k].top, 0.0f) << size << ": " << items[k].what;
      EXPECT_LE(items[k].bottom, static_cast<float>(h)) << size << ": " << items[k].what;
      EXPECT_GE(items[k].left, 0.0f) << size << ": " << items[k].what;
      EXPECT_LE(items[k].right, static_cast<float>(w)) << size << ": " << items[k].what;
      EXPECT_LT(items[k].left, items[k].right) << size << ": " << items[k].what;
      if (k > 0) {
        EXPECT_LE(items[k - 1].bottom, items[k].top) << size << ": " << items[k - 1].what << " over " << items[k].what;
      }
    }
  }
  // The HUD's labels and values never run into each other: a 200 x 600 portrait frame wrote
  // "Magnetic forc1.88 mN"; narrow cards shorten the labels, and drop them only when nothing fits.
  for (const std::string& path : {run, failed, fed})
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{1280, 720}, {200, 600}, {120, 400}, {160, 120}, {60, 400}}) {
    const std::string size = std::to_string(w) + " x " + std::to_string(h) + name(path);
    const auto hud = testing::paint_last_frame(path, w, h).hud;
    ASSERT_EQ(hud.size(), hud_rows(path)) << size;
    for (const auto& field : hud) {
      EXPECT_GE(field.value_left, 0.0f) << size;
      if (*field.label) {
        EXPECT_LT(field.label_right, field.value_left) << size << ": " << field.label;
      } else {
        EXPECT_LT(w, 120) << size << ": a row without its label";
      }
    }
    if (w >= 640) {
      EXPECT_STREQ(hud[2].label, "Magnetic force") << size << ": a frame with room shortens nothing";
    }
  }
  // A frame with room shows the whole legend (two force arrows and four symbols) and the scale bar.
  const auto full = panel_at(run, 1280, 720);
  EXPECT_EQ(count(full, "legend"), 6u);
  EXPECT_EQ(count(full, "scale bar"), 1u);
  // A thumbnail keeps the arrows and the scale bar and leaves symbols out.
  const auto thumbnail = panel_at(run, 320, 180);
  EXPECT_GE(count(thumbnail, "legend"), 2u);
  EXPECT_LT(count(thumbnail, "legend"), 6u);
  EXPECT_EQ(count(thumbnail, "scale bar"), 1u);
}

// The most rows a HUD has: a fed, steered run compared with another, both ended early (time, tip
// error, magnetic force, feed force, fed length, contact, and a line for each end). In frames as
// short as 100 px (by the layout's arithmetic, 110 px at the smallest font) the rows close up
// rather than leave the frame or run into the legend.
TEST(RenderPanelLayout, EightHudRowsStayInsideAShortFrame) {
  ScratchDir dir("panel_eight_rows");
  SyntheticLogSpec spec;
  spec.feed = true;
  FrameSource source(testing::make_run(dir, spec));
  FrameState state;
  source.frame(source.frame_count() - 1, state);
  EarlyEnd failed, stopped;
  failed.how = EarlyEnd::How::kFailed, failed.at = 0.9;
  stopped.how = EarlyEnd::How::kStopped, stopped.at = 0.5;
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{1280, 720}, {1200, 100}, {640, 120}, {320, 180}, {160, 120}}) {
    const std::string size = std::to_string(w) + " x " + std::to_string(h);
    View view;
    view.width = w;
    view.height = h;
    FramePainter painter(source.metadata(), view, choose_force_scales(source, view), state, {failed, stopped});
    Canvas canvas(w, h);
    painter.paint(canvas, state, {});
    ASSERT_EQ(painter.hud_fields().size(), 8u) << size;
    const auto& items = painter.panel_items();
    ASSERT_FALSE(items.empty()) << size;
    for (std::size_t k = 0; k < items.size(); ++k) {
      EXPECT_GE(items[k].top, 0.0f) << size << ": " << items[k].what;
      EXPECT_LE(items[k].bottom, static_cast<float>(h)) << size << ": " << items[k].what;
      if (k > 0) {
        EXPECT_LE(items[k - 1].bottom, items[k].top) << size << ": " << items[k - 1].what << " over " << items[k].what;
      }
    }
  }
}

// The HUD shows what the log records: a catheter only pushed from its root (control.mode
// "none") showed a "Tip error" of 95 mm to a target nothing followed and a magnetic force of
// zero, and not the drive's push; a free rod's showed three rows of "n/a".
// Zoomed in, the rod is drawn tens of pixels thick; its legend symbol stays within its own row
// (at its true width it was a disc over the rule above and the trail entry below).
TEST(RenderPanelLayout, TheRodsLegendSymbolStaysInItsRowWhenZoomedIn) {
  ScratchDir dir("panel_zoomed");
  SyntheticLogSpec spec;
  spec.rod_radius = 0.002;
  FrameSource source(testing::make_run(dir, spec));
  FrameState state;
  source.frame(source.frame_count() - 1, state);
  for (const double zoom : {1.0, 8.0, 40.0}) {
    View view;
    view.camera = CameraMode::kFollow;
    view.zoom = zoom;
    FramePainter painter(source.metadata(), view, choose_force_scales(source, view), state);
    Canvas canvas(view.width, view.height);
    painter.paint(canvas, state, {});
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(view.width) * view.height * 4);
    canvas.finish(rgba.data());
    const FramePainter::PanelItem* rod = nullptr;
    for (const auto& item : painter.panel_items())
      if (item.label.rfind("catheter", 0) == 0) rod = &item;
    ASSERT_NE(rod, nullptr) << "zoom " << zoom;
    // The rod's fill colour (palette kRod) anywhere in the panel's column of symbols.
    int top = view.height, bottom = -1;
    for (int y = 0; y < view.height; ++y)
      for (int x = static_cast<int>(rod->left); x < static_cast<int>(rod->left) + 40 && x < view.width; ++x) {
        const std::uint8_t* c = &rgba[(static_cast<std::size_t>(y) * view.width + x) * 4];
        if (std::abs(c[0] - 0x1B) < 3 && std::abs(c[1] - 0x3A) < 3 && std::abs(c[2] - 0x5C) < 3) {
          top = std::min(top, y);
          bottom = std::max(bottom, y);
        }
      }
    ASSERT_GE(bottom, 0) << "zoom " << zoom << ": no rod symbol in the legend";
    EXPECT_GE(top, static_cast<int>(std::floor(rod->top))) << "zoom " << zoom;
    EXPECT_LE(bottom, static_cast<int>(std::ceil(rod->bottom))) << "zoom " << zoom;
  }
}

TEST(RenderPanelLayout, TheHudShowsWhatTheLogRecords) {
  ScratchDir dir("panel_hud_rows");
  const auto hud_of = [&](const SyntheticLogSpec& spec, const std::string& name) {
    const auto fields = testing::paint_last_frame(testing::make_run(dir, spec, name), 1280, 720).hud;
    std::vector<std::string> rows;
    for (const auto& field : fields) rows.push_back(std::string(field.label) + ": " + field.value);
    return rows;
  };
  using Rows = std::vector<std::string>;
  SyntheticLogSpec steered;  // the synthetic tip moves 20 mm in the 1 s of the log
  EXPECT_EQ(hud_of(steered, "steered"),
            (Rows{"Time: 1.000 s", "Tip error: 2.00 mm", "Magnetic force: 2.00 mN", "Max contact: 1.00 mN"}));
  SyntheticLogSpec steered_and_fed = steered;
  steered_and_fed.feed = true;  // the push rises to 5 mN at the last frame; the root is fed at the tip's speed
  EXPECT_EQ(hud_of(steered_and_fed, "steered_and_fed"),
            (Rows{"Time: 1.000 s", "Tip error: 2.00 mm", "Magnetic force: 2.00 mN", "Feed force: 5.00 mN",
                  "Fed length: 20.0 mm", "Max contact: 1.00 mN"}));
  SyntheticLogSpec pushed = steered_and_fed;
  pushed.reference = false;
  pushed.forces = false;
  EXPECT_EQ(hud_of(pushed, "pushed"), (Rows{"Time: 1.000 s", "Feed force: 5.00 mN", "Fed length: 20.0 mm"}));
  SyntheticLogSpec pulled = pushed;
  pulled.feed_force = -3e-3;
  EXPECT_EQ(hud_of(pulled, "pulled"), (Rows{"Time: 1.000 s", "Feed force: -3.00 mN", "Fed length: 20.0 mm"}));
  SyntheticLogSpec free_rod = pushed;
  free_rod.feed = false;
  EXPECT_EQ(hud_of(free_rod, "free_rod"), (Rows{"Time: 1.000 s"}));
}

// The legend explains what the map draws, and nothing else: a free rod's run (no path, start or
// goal) listed "reference path" and "start, goal", and a layer turned off kept its entry.
TEST(RenderPanelLayout, TheLegendListsOnlyWhatTheMapDraws) {
  ScratchDir dir("panel_legend");
  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  FrameSource source(run);
  FrameState state;
  source.frame(source.frame_count() - 1, state);
  const auto legend_of = [&](const LogMetadata& metadata, const LayerSet& layers) {
    View view;
    view.width = 1280;
    view.height = 720;
    view.layers = layers;
    FramePainter painter(metadata, view, choose_force_scales(source, view), state);
    Canvas canvas(view.width, view.height);
    painter.paint(canvas, state, {});
    std::vector<std::string> labels;
    for (const auto& item : painter.panel_items())
      if (std::string(item.what) == "legend") labels.push_back(item.label.substr(0, item.label.find(" \xC3\x98")));
    return labels;
  };
  using Labels = std::vector<std::string>;
  EXPECT_EQ(legend_of(source.metadata(), LayerSet::defaults()),
            (Labels{"Magnetic force", "Contact force", "catheter", "reference path", "tip trail", "start, goal"}));
  LayerSet fewer = LayerSet::defaults();
  for (const Layer off : {Layer::kMagnetic, Layer::kPath, Layer::kTrail, Layer::kStartGoal}) fewer.set(off, false);
  EXPECT_EQ(legend_of(source.metadata(), fewer), (Labels{"Contact force", "catheter"}));
  LayerSet more = LayerSet::defaults();
  more.set(Layer::kFriction, true);  // the synthetic run logs no friction: nothing to explain
  EXPECT_EQ(legend_of(source.metadata(), more), legend_of(source.metadata(), LayerSet::defaults()));
  LogMetadata free_rod = source.metadata();
  free_rod.path.clear();
  free_rod.goal = free_rod.start;
  EXPECT_EQ(legend_of(free_rod, LayerSet::defaults()), (Labels{"Magnetic force", "Contact force", "catheter", "tip trail"}));
}

}  // namespace
}  // namespace vascsim::render

// A picture of a failed run says so: its HUD ends with a red "Run failed" row giving the time the
// run had reached (its summary.json's /simulated_time), on every frame, so a reviewer who sees a
// video or a still without the warnings `vascsim render` printed does not take its last frame
// for where the run ended of its own accord. The rest of the picture is the same as a finished
// run's. A run stopped by a signal (Ctrl-C, a job's time limit: its summary's /stopped_by) says
// "Run stopped" instead.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "render/canvas.h"
#include "render/frame_painter.h"
#include "render/frame_source.h"
#include "render/plots.h"
#include "render/view_frame.h"
#include "sim/io/output_file.h"
#include "sim/io/png_file.h"
#include "render_test_util.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;

// The summary `vascsim run` writes, reduced to what a reader checks; `ok` and the time reached as
// given ("" leaves the time out, as a hand-edited summary may); `stopped_by` names the signal that
// stopped the run, or is empty.
void write_summary(const std::string& run, int frames, bool ok, const std::string& simulated_time,
                   const std::string& stopped_by = "") {
  std::string summary = R"({"format": "vascsim-summary/1", "ok": )" + std::string(ok ? "true" : "false") +
                        R"(, "failure": )" + (ok ? "null" : R"("Newton did not converge")") +
                        ", \"frames\": " + std::to_string(frames);
  summary += ", \"stopped_by\": " + (stopped_by.empty() ? std::string("null") : "\"" + stopped_by + "\"");
  if (!simulated_time.empty()) summary += ", \"simulated_time\": " + simulated_time;
  testing::write_bytes(run + "/summary.json", summary + "}\n");
}

// Pixels of the failure row's red (#C92A2A, green and blue equal), alone or anti-aliased on the
// white panel, in a box; not the orange of contact arrows (#E8590C) nor grey text.
int red_pixels(const std::vector<std::uint8_t>& rgba, int width, float left, float right, float top, float bottom) {
  int n = 0;
  for (int y = std::max(0, static_cast<int>(top)); y < static_cast<int>(bottom); ++y)
    for (int x = std::max(0, static_cast<int>(left)); x < static_cast<int>(right); ++x) {
      const std::uint8_t* px = &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
      n += px[0] - std::max(px[1], px[2]) > 60 && std::abs(px[1] - px[2]) < 16;
    }
  return n;
}

TEST(RenderFailedRun, TheTimeTheRunReachedComesFromItsSummary) {
  ScratchDir dir("failed_run_source");
  SyntheticLogSpec spec;
  const std::string run = testing::make_run(dir, spec);
  EXPECT_FALSE(FrameSource(run).ended_early()) << "a run without a summary is not known to have failed";
  {  // ... unless it left its claim on the directory with no run holding it: killed (kill -9, a crash)
    RunDirectoryClaim claim(run);
    EXPECT_FALSE(FrameSource(run).ended_early()) << "a run still writing";
  }
  testing::write_bytes(run + "/" + RunDirectoryClaim::kFileName, "");
  ASSERT_TRUE(FrameSource(run).ended_early());
  EXPECT_EQ(FrameSource(run).ended_early()->how, EarlyEnd::How::kKilled);
  EXPECT_EQ(FrameSource(run).ended_early()->at, spec.duration) << "a killed run reached its last logged frame";
  write_summary(run, spec.frames, true, "1.0");
  EXPECT_FALSE(FrameSource(run).ended_early());
  write_summary(run, spec.frames, false, "1.0375");
  ASSERT_TRUE(FrameSource(run).ended_early());
  EXPECT_EQ(FrameSource(run).ended_early()->at, 1.0375);
  EXPECT_EQ(FrameSource(run).ended_early()->how, EarlyEnd::How::kFailed);
  write_summary(run, spec.frames, false, "1.0375", "SIGINT (Ctrl-C)");
  ASSERT_TRUE(FrameSource(run).ended_early());
  EXPECT_EQ(FrameSource(run).ended_early()->how, EarlyEnd::How::kStopped);
  // Without a time, or with one no run reaches (hand-edited), after its last logged frame.
  for (const std::string& reached : {std::string(""), std::string("-1"), std::string("\"soon\"")}) {
    write_summary(run, spec.frames, false, reached);
    ASSERT_TRUE(FrameSource(run).ended_early()) << reached;
    EXPECT_EQ(FrameSource(run).ended_early()->at, spec.duration) << reached;
  }
}

TEST(RenderFailedRun, TheHudSaysTheRunFailedAndNothingElseChanges) {
  ScratchDir dir("failed_run_hud");
  SyntheticLogSpec spec;
  const std::string run = testing::make_run(dir, spec);
  const int w = 1280, h = 720;
  write_summary(run, spec.frames, true, "1.0");
  const testing::PaintedFrame finished = testing::paint_last_frame(run, w, h);
  write_summary(run, spec.frames, false, "1.0375");
  const testing::PaintedFrame failed = testing::paint_last_frame(run, w, h);

  ASSERT_EQ(finished.hud.size(), 4u);
  ASSERT_EQ(failed.hud.size(), 5u);
  EXPECT_STREQ(failed.hud.back().label, "Run failed");
  write_summary(run, spec.frames, false, "1.0375", "SIGTERM");
  const testing::PaintedFrame stopped = testing::paint_last_frame(run, w, h);
  ASSERT_EQ(stopped.hud.size(), 5u);
  EXPECT_STREQ(stopped.hud.back().label, "Run stopped");
  // Killed with kill -9: no summary, and the run's claim on the directory left with no holder.
  std::filesystem::remove(run + "/summary.json");
  testing::write_bytes(run + "/" + RunDirectoryClaim::kFileName, "");
  const testing::PaintedFrame killed = testing::paint_last_frame(run, w, h);
  ASSERT_EQ(killed.hud.size(), 5u);
  EXPECT_STREQ(killed.hud.back().label, "Run killed");
  ASSERT_FALSE(failed.items.empty());
  ASSERT_STREQ(failed.items.front().what, "hud");
  ASSERT_STREQ(finished.items.front().what, "hud");
  const auto& hud = failed.items.front();
  // The HUD grew by its new row, and the row is red; the finished run's HUD has no red at all.
  EXPECT_GT(hud.bottom, finished.items.front().bottom + 0.5f * (finished.items.front().bottom - finished.items.front().top) / 4);
  const float row_top = hud.bottom - 0.3f * (hud.bottom - hud.top);
  EXPECT_GT(red_pixels(failed.rgba, w, hud.left, hud.right, row_top, hud.bottom), 50);
  const auto& plain = finished.items.front();
  EXPECT_EQ(red_pixels(finished.rgba, w, plain.left, plain.right, plain.top, plain.bottom), 0);
  // The map (left of the side panel's text) is the finished run's, pixel for pixel.
  const float panel_text_left = std::min(plain.left, hud.left);
  ASSERT_GT(panel_text_left, 0.5f * w);
  std::size_t differing = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < static_cast<int>(panel_text_left) - 2; ++x)
      for (int k = 0; k < 4; ++k) {
        const std::size_t i = (static_cast<std::size_t>(y) * w + x) * 4 + k;
        differing += failed.rgba[i] != finished.rgba[i];
      }
  EXPECT_EQ(differing, 0u);
}

// Narrow frames carry the HUD on a card above the map: the card grows by the row, so the row
// lies on the card and the map starts below it.
TEST(RenderFailedRun, TheNarrowFramesCardHoldsTheRow) {
  ScratchDir dir("failed_run_card");
  SyntheticLogSpec spec;
  const std::string run = testing::make_run(dir, spec);
  write_summary(run, spec.frames, false, "0.5");
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{480, 640}, {360, 360}, {160, 120}}) {
    const testing::PaintedFrame p = testing::paint_last_frame(run, w, h);
    const std::string size = std::to_string(w) + " x " + std::to_string(h);
    ASSERT_EQ(p.hud.size(), 5u) << size;
    ASSERT_FALSE(p.items.empty()) << size;
    const auto& hud = p.items.front();
    EXPECT_LE(hud.bottom, static_cast<float>(h)) << size;
    const float row_top = hud.bottom - 0.3f * (hud.bottom - hud.top);
    EXPECT_GT(red_pixels(p.rgba, w, hud.left, hud.right, row_top, hud.bottom), 5) << size;
  }
}

// The smallest frames (a thumbnail) of a compared pair that both ended early need two such rows:
// each is drawn, red, inside the frame (the card leaves out its title for them).
TEST(RenderFailedRun, AThumbnailOfTwoRunsThatEndedEarlyHoldsBothRows) {
  ScratchDir dir("failed_run_thumbnail");
  SyntheticLogSpec spec;
  const std::string a = testing::make_run(dir, spec, "a"), b = testing::make_run(dir, spec, "b");
  FrameSource run_a(a), run_b(b);
  FrameState state, other;
  run_a.frame(0, state);
  run_b.frame(0, other);
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{120, 90}, {160, 120}, {100, 100}}) {
    View view;
    view.width = w;
    view.height = h;
    FramePainter painter(run_a.metadata(), view, choose_force_scales(run_a, view), state,
                         {EarlyEnd{0.5, EarlyEnd::How::kFailed}, EarlyEnd{0.75, EarlyEnd::How::kStopped}});
    Canvas canvas(w, h);
    painter.paint(canvas, state, {}, &other);
    const std::string size = std::to_string(w) + " x " + std::to_string(h);
    ASSERT_EQ(painter.hud_fields().size(), 6u) << size;
    ASSERT_FALSE(painter.panel_items().empty()) << size;
    const auto& hud = painter.panel_items().front();
    EXPECT_LE(hud.bottom, static_cast<float>(h)) << size << ": the card's last row is cut off";
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * h * 4);
    canvas.finish(rgba.data());
    // Both rows are red, the lower one too: the last sixth of the card.
    EXPECT_GT(red_pixels(rgba, w, hud.left, hud.right, hud.bottom - (hud.bottom - hud.top) / 6, hud.bottom), 5) << size;
  }
}

// Compare mode: a compared run that failed stops moving over the map; the HUD says why.
TEST(RenderFailedRun, AComparedRunThatFailedIsSaidToHaveFailed) {
  ScratchDir dir("failed_run_overlay");
  SyntheticLogSpec spec;
  const std::string a = testing::make_run(dir, spec, "a"), b = testing::make_run(dir, spec, "b");
  write_summary(a, spec.frames, true, "1.0");
  const int w = 1280, h = 720;
  View view;
  view.width = w;
  view.height = h;
  Canvas canvas(w, h);
  const auto still_over = [&](std::vector<std::uint8_t>& rgba) {
    FrameSource run_a(a), run_b(b);
    ViewFrameInputs in;
    in.source = &run_a;
    in.peaks = measure_force_peaks(run_a);
    in.overlay = &run_b;
    render_view_frame(canvas, in, view, 0.5, rgba);
  };
  std::vector<std::uint8_t> over_finished, over_failed;
  write_summary(b, spec.frames, true, "1.0");
  still_over(over_finished);
  write_summary(b, spec.frames, false, "0.75");
  still_over(over_failed);
  // The two stills differ only in the side panel, where the failed one gained red text.
  int first_column = w;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < 4; ++k) {
        const std::size_t i = (static_cast<std::size_t>(y) * w + x) * 4 + k;
        if (over_failed[i] != over_finished[i]) first_column = std::min(first_column, x);
      }
  EXPECT_GT(first_column, w / 2) << "the map changed";
  EXPECT_LT(first_column, w) << "the picture did not change";
  EXPECT_EQ(red_pixels(over_finished, w, first_column, w, 0, h / 3.0f), 0);
  EXPECT_GT(red_pixels(over_failed, w, first_column, w, 0, h / 3.0f), 50);

  // The row's label names the compared run.
  FrameSource run_a(a);
  FrameState state, other;
  run_a.frame(0, state);
  FrameSource(b).at_time(0.5, other);
  for (const auto& [how, label] : {std::pair{EarlyEnd::How::kFailed, "Compared run failed"},
                                   {EarlyEnd::How::kStopped, "Compared run stopped"},
                                   {EarlyEnd::How::kKilled, "Compared run killed"}}) {
    FramePainter painter(run_a.metadata(), view, choose_force_scales(run_a, view), state, {std::nullopt, EarlyEnd{0.75, how}});
    painter.paint(canvas, state, {}, &other);
    ASSERT_EQ(painter.hud_fields().size(), 5u);
    EXPECT_STREQ(painter.hud_fields().back().label, label);
  }
}

// The plots of a failed run say so in red in their top margin; a finished run's have no red there.
TEST(RenderFailedRun, ThePlotsSayTheRunFailed) {
  ScratchDir dir("failed_run_plots");
  SyntheticLogSpec spec;
  const std::string run = testing::make_run(dir, spec);
  const int w = 1200, h = 800;
  const auto plots_of = [&](const std::string& name) {
    const auto paths = write_plots(FrameSource(run), dir / name, false);
    std::vector<io::PngPixels> images;
    for (const std::string& path : paths) images.push_back(io::read_png(path, 4));
    return images;
  };
  write_summary(run, spec.frames, true, "1.0");
  const auto finished = plots_of("finished");
  write_summary(run, spec.frames, false, "1.0375");
  const auto failed = plots_of("failed");
  ASSERT_EQ(finished.size(), failed.size());
  ASSERT_EQ(failed.size(), 5u);
  for (std::size_t i = 0; i < failed.size(); ++i) {
    ASSERT_EQ(failed[i].width, w);
    // The margin above the title (the upper half of the 9 % above the axes).
    EXPECT_EQ(red_pixels(finished[i].data, w, 0, w, 0, 0.045f * h), 0) << "plot " << i;
    EXPECT_GT(red_pixels(failed[i].data, w, 0, w, 0, 0.045f * h), 100) << "plot " << i;
  }
}

}  // namespace
}  // namespace vascsim::render

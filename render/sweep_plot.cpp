#include "render/sweep_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "render/canvas.h"
#include "render/number_format.h"
#include "render/palette.h"
#include "render/plots.h"
#include "render/png_writer.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {

namespace {

using palette::kFailure;  // failed or missing counts
using palette::kInk;

constexpr Rgba kWhite = hex(0xFFFFFF);
constexpr Rgba kGrid = hex(0xE3E6EA);
constexpr Rgba kRun = hex(0x4C6EF5, 0.55f);    // one run
constexpr Rgba kRange = hex(0x868E96);         // min-max bar
constexpr Rgba kMean = hex(0xF08C00);          // mean line
constexpr float kMaxDotSpreadPx = 40;          // the width a value's run dots spread over, at most

// The smallest gap between neighbouring positions: the axis's margins and the dots' spread.
double spacing_of(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  double gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < x.size(); ++i)
    if (x[i] > x[i - 1]) gap = std::min(gap, x[i] - x[i - 1]);
  return std::isfinite(gap) ? gap : 1.0;
}

void draw_panel(Canvas& c, const SweepFigure& f, const SweepPanel& p) {
  c.clear(kWhite);
  const float w = static_cast<float>(c.width()), h = static_cast<float>(c.height());
  Axes a;
  a.left = 0.15f * w, a.right = w - 0.04f * w, a.top = 0.12f * h, a.bottom = h - 0.2f * h;
  const double spacing = spacing_of(f.x);
  const auto [xlo, xhi] = std::minmax_element(f.x.begin(), f.x.end());
  a.xmin = *xlo - 0.5 * spacing, a.xmax = *xhi + 0.5 * spacing;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& vs : p.values)
    for (double v : vs) lo = std::min(lo, v), hi = std::max(hi, v);
  const bool any = hi >= lo;
  if (!any) lo = 0, hi = 1;
  // Figures here are sizes and counts: the axis starts at zero unless the data go below it.
  lo = std::min(lo, 0.0);
  if (!(hi > lo)) hi = lo + 1;
  a.ymin = lo - (lo < 0 ? 0.05 * (hi - lo) : 0.0);
  a.ymax = hi + 0.16 * (hi - lo);  // room for the counts of failed runs and runs without a value
  for (double y : nice_ticks(a.ymin, a.ymax, 6)) {
    const float py = a.map(a.xmin, y).y;
    c.box({a.left, py - 0.5f}, {a.right, py + 0.5f}, kGrid);
  }
  for (double x : f.x) {
    const float px = a.map(x, a.ymin).x;
    c.box({px - 0.5f, a.top}, {px + 0.5f, a.bottom}, kGrid);
  }
  const int font = std::max(10, static_cast<int>(std::lround(h / 34.0)));
  std::vector<glm::vec2> means;
  bool any_failed = false, any_unknown = false;
  for (std::size_t j = 0; j < f.x.size(); ++j) {
    const std::vector<double>& vs = j < p.values.size() ? p.values[j] : std::vector<double>();
    if (!vs.empty()) {
      const auto [mn, mx] = std::minmax_element(vs.begin(), vs.end());
      c.capsule(a.map(f.x[j], *mn), a.map(f.x[j], *mx), 1.5f, kRange);
      double sum = 0;
      // Spread sideways in run order (deterministic, and a stack of equal values still shows
      // how many runs it holds) over at most 40 px: spread over 40 % of the gap between values,
      // two values' dots reached a fifth of that gap from their value, where a numeric axis
      // reads other values.
      const float centre = a.map(f.x[j], a.ymin).x;
      const float spread = std::min(kMaxDotSpreadPx, 0.4f * (a.map(f.x[j] + spacing, a.ymin).x - centre));
      for (std::size_t k = 0; k < vs.size(); ++k) {
        const float dx = vs.size() > 1 ? (static_cast<float>(k) / static_cast<float>(vs.size() - 1) - 0.5f) * spread : 0.0f;
        c.disc({centre + dx, a.map(f.x[j], vs[k]).y}, 4.0f, kRun);
        sum += vs[k];
      }
      means.push_back(a.map(f.x[j], sum / static_cast<double>(vs.size())));
    }
    const std::size_t failed = j < p.failed.size() ? p.failed[j] : 0;
    const std::size_t unknown = j < p.unknown.size() ? p.unknown[j] : 0;
    // Counts only, so they fit however many values there are; the caption says what they count.
    float y = a.top + 1.3f * font;
    if (failed > 0) {
      c.text(std::to_string(failed), {a.map(f.x[j], a.ymax).x, y}, font, kFailure, TextAlign::kCenter);
      y += 1.2f * font;
      any_failed = true;
    }
    if (unknown > 0) {
      c.text(std::to_string(unknown), {a.map(f.x[j], a.ymax).x, y}, font, kRange, TextAlign::kCenter);
      any_unknown = true;
    }
  }
  if (means.size() > 1) c.polyline(means, 2.5f, kMean);
  for (const auto& m : means) c.disc(m, 5.0f, kMean);
  if (!any)
    c.text("no completed run reports this", {0.5f * (a.left + a.right), 0.5f * (a.top + a.bottom)}, font, kInk,
           TextAlign::kCenter);
  std::vector<std::pair<double, std::string>> ticks;
  for (std::size_t j = 0; j < f.x_labels.size() && j < f.x.size(); ++j) ticks.emplace_back(f.x[j], f.x_labels[j]);
  draw_frame(c, a, f.xlabel, p.ylabel, p.title, kWhite, ticks);
  std::string caption = "dots: runs   bar: min to max   line: mean";
  if (any_unknown) caption += "   grey: runs " + (p.unknown_label.empty() ? std::string("without a value") : p.unknown_label);
  const int small = static_cast<int>(0.8 * font);
  // Under the x label, clear of the title however long it gets.
  const float caption_y = a.bottom + 4.3f * font;
  c.text(caption, {a.right, caption_y}, small, kRange, TextAlign::kRight);
  if (any_failed) c.text("red: runs failed or missing", {a.left, caption_y}, small, kFailure, TextAlign::kLeft);
}

}  // namespace

void write_sweep_figure(const SweepFigure& f, const std::string& path, int width, int height) {
  if (f.panels.empty() || f.x.empty()) throw InputError(path + ": a sweep figure needs at least one panel and one value");
  const int cols = f.panels.size() > 1 ? 2 : 1;
  const int rows = static_cast<int>((f.panels.size() + 1) / 2);
  const int pw = width / cols, ph = height / rows;
  // Each panel is drawn on its own canvas (draw_frame paints the margins of the whole canvas)
  // and copied into the page.
  Canvas c(pw, ph);
  std::vector<std::uint8_t> page(static_cast<std::size_t>(width) * height * 4, 255), panel(static_cast<std::size_t>(pw) * ph * 4);
  for (std::size_t i = 0; i < f.panels.size(); ++i) {
    draw_panel(c, f, f.panels[i]);
    c.finish(panel.data());
    const int x0 = static_cast<int>(i % 2) * pw, y0 = static_cast<int>(i / 2) * ph;
    for (int y = 0; y < ph; ++y)
      std::memcpy(&page[(static_cast<std::size_t>(y0 + y) * width + x0) * 4], &panel[static_cast<std::size_t>(y) * pw * 4],
                  static_cast<std::size_t>(pw) * 4);
  }
  write_png(path, page.data(), width, height);
}

}  // namespace vascsim::render

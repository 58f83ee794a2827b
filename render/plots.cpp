#include "render/plots.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include <glm/common.hpp>

#include "render/frame_painter.h"
#include "render/label_placer.h"
#include "render/number_format.h"
#include "render/palette.h"
#include "render/png_writer.h"
#include "sim/io/output_file.h"
#include "sim/io/run_files.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {

namespace {

using palette::kActuation;
using palette::kContact;
using palette::kFailure;
using palette::kInk;

constexpr Rgba kGrid = hex(0xE3E6EA);
constexpr Rgba kWall = hex(0xC3CAD2);
constexpr Rgba kPath = hex(0x4C6EF5);
constexpr Rgba kTip = hex(0xF08C00);
constexpr Rgba kSecondary = hex(0x74B816);
constexpr Rgba kTertiary = hex(0x1098AD);
constexpr Rgba kFeed = hex(0x2B8A3E);

// Time series of a run, sampled at up to ~5000 logged frames.
struct Series {
  std::vector<double> t;                     // s
  std::vector<Vec2> tip, actuation;          // m, N
  std::vector<double> error, max_contact, total_contact;  // m, N, N
  std::vector<double> feed_force;                          // N
  bool has_actuation = false, has_contact = false, has_error = false, has_feed = false;
  bool error_from_path = false;  // no target logged: the error is the distance to the path
};

double distance_to_polyline(const Polyline& path, Vec2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Vec2 a = path[i - 1], d = path[i] - a;
    const double h = std::clamp((p - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
    best = std::min(best, (p - a - h * d).norm());
  }
  return best;
}

Series collect(const FrameSource& source, FrameRange frames) {
  Series s;
  const std::size_t step = std::max<std::size_t>(1, (frames.last - frames.first + 1) / 5000);
  FrameState f;
  for (std::size_t i = frames.first; i <= frames.last; i += step) {
    source.frame(i, f);
    s.t.push_back(f.time);
    s.tip.push_back(f.tip());
    s.actuation.push_back(f.actuation_total());
    s.has_actuation = !f.actuation.empty();
    s.has_contact = !f.contact.empty();
    double total = 0;
    for (std::size_t k = 0; k + 1 < f.contact.size(); k += 2) total += std::hypot(f.contact[k], f.contact[k + 1]);
    s.max_contact.push_back(f.max_contact());
    s.total_contact.push_back(total);
    // Tracking error: the logged value, else the distance to the controller's target, else to the path.
    double e = f.tip_error;
    if (e < 0 && f.has_reference) e = (f.tip() - f.reference).norm();
    s.error_from_path = e < 0 && source.metadata().path.size() >= 2;
    if (s.error_from_path) e = distance_to_polyline(source.metadata().path, f.tip());
    s.has_error = e >= 0;
    s.error.push_back(std::max(e, 0.0));
    s.has_feed = f.has_feed;
    s.feed_force.push_back(f.feed_force);
  }
  return s;
}

Axes plot_area(const Canvas& c) {
  Axes a;
  a.left = 0.11f * c.width();
  a.right = c.width() - 0.04f * c.width();
  a.top = 0.09f * c.height();
  a.bottom = c.height() - 0.12f * c.height();
  return a;
}

// The axes of a plot against time, spanning the series' times (1 s from a single frame's).
Axes time_axes(const Canvas& c, const Series& s) {
  Axes a = plot_area(c);
  a.xmin = s.t.front();
  a.xmax = s.t.back() > s.t.front() ? s.t.back() : s.t.front() + 1;
  return a;
}

void fit_range(const std::vector<double>& v, double& lo, double& hi, bool include_zero) {
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  for (double x : v) lo = std::min(lo, x), hi = std::max(hi, x);
  if (include_zero) lo = std::min(lo, 0.0), hi = std::max(hi, 0.0);
  if (!(hi > lo)) hi = lo + 1;
  const double pad = 0.05 * (hi - lo);
  hi += pad;
  if (!include_zero || lo < 0) lo -= pad;
}

void plot_line(Canvas& c, const Axes& a, const std::vector<double>& x, const std::vector<double>& y, float width,
               Rgba colour, bool dashed = false) {
  std::vector<glm::vec2> pts;
  for (std::size_t i = 0; i < x.size(); ++i) pts.push_back(a.map(x[i], y[i]));
  if (dashed) c.dashed_polyline(pts, width, 8, 5, colour);
  else c.polyline(pts, width, colour);
}

using LegendEntries = std::vector<std::pair<Rgba, std::string>>;

// Width (px) of the legend box for these entries.
float legend_width(Canvas& c, const LegendEntries& entries, int font) {
  float w = 0;
  for (const auto& e : entries) w = std::max(w, c.text_width(e.second, font));
  return w + 3.5f * font;
}

// A legend in the top-right corner of the axes: line samples and labels.
// `outside`: right of the axes (map plots, whose data fill the axes).
void legend(Canvas& c, const Axes& a, const LegendEntries& entries, int font, bool outside = false) {
  const float w = legend_width(c, entries, font);
  if (a.right + 20 + w > c.width()) outside = false;  // no room beside the axes
  const float x1 = outside ? a.right + 20 + w : a.right - 10, x0 = x1 - w, row = 1.4f * font;
  float y = a.top + 10;
  c.box({x0, y}, {x1, y + row * entries.size() + 0.6f * font}, hex(0xFFFFFF, 0.9f), 4);
  c.box_outline({x0, y}, {x1, y + row * entries.size() + 0.6f * font}, 1, kGrid, 4);
  y += row;
  for (const auto& e : entries) {
    c.capsule({x0 + 0.5f * font, y - 0.35f * font}, {x0 + 2.3f * font, y - 0.35f * font}, 2, e.first);
    c.text(e.second, {x0 + 2.9f * font, y}, font, kInk);
    y += row;
  }
}

// Walls at their true thickness (at least 3 px), light enough for the data drawn over them.
void draw_walls(Canvas& c, const Axes& a, const LogMetadata& m, double to_mm) {
  const double px_per_m = to_mm * (a.right - a.left) / (a.xmax - a.xmin);
  for (const auto& w : m.walls)
    c.capsule(a.map(w.a.x() * to_mm, w.a.y() * to_mm), a.map(w.b.x() * to_mm, w.b.y() * to_mm),
              std::max(1.5f, static_cast<float>(0.5 * w.thickness * px_per_m)), kWall);
}

// The axes of a map plot: the walls, the path, the tip's track and the whole rod of each frame
// in `shown`. Its legend (legend_box px wide) goes beside the map where that leaves the map at
// least half the width; otherwise inside, and the map keeps the whole width.
Axes map_axes(const Canvas& c, const FrameSource& source, const Series& s, double to_mm, float legend_box,
              const std::vector<FrameState>& shown = {}) {
  Axes a = plot_area(c);
  const float beside = c.width() - legend_box - 30.0f;  // 20 px gap, 10 px margin
  if (beside >= 0.5f * c.width()) a.right = std::min(a.right, beside);
  const LogMetadata& m = source.metadata();
  std::vector<double> xs, ys;
  auto add = [&](Vec2 p) { xs.push_back(p.x() * to_mm), ys.push_back(p.y() * to_mm); };
  for (const auto& w : m.walls)
    for (const Vec2& end : {w.a, w.b})
      for (const Vec2& corner : {Vec2(-1, -1), Vec2(1, 1)}) add(end + 0.5 * w.thickness * corner);
  for (const auto& p : m.path) add(p);
  for (const auto& p : s.tip) add(p);
  for (const FrameState& f : shown)
    for (std::size_t n = 0; n < f.node_count(); ++n) add(f.node(n));
  fit_range(xs, a.xmin, a.xmax, false);
  fit_range(ys, a.ymin, a.ymax, false);
  a.equal_aspect();
  return a;
}

void save(Canvas& c, const std::string& path, bool force, std::vector<std::string>& written) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !force) throw InputError(path + ": exists (use --force to overwrite)");
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(c.width()) * c.height() * 4);
  c.finish(rgba.data());
  write_png(path, rgba.data(), c.width(), c.height());
  written.push_back(path);
}

}  // namespace

glm::vec2 Axes::map(double x, double y) const {
  return {static_cast<float>(left + (x - xmin) / (xmax - xmin) * (right - left)),
          static_cast<float>(bottom - (y - ymin) / (ymax - ymin) * (bottom - top))};
}

void Axes::equal_aspect() {
  const double px_per_x = (right - left) / (xmax - xmin), px_per_y = (bottom - top) / (ymax - ymin);
  if (px_per_x > px_per_y) {
    const double half = 0.5 * (right - left) / px_per_y, mid = 0.5 * (xmin + xmax);
    xmin = mid - half, xmax = mid + half;
  } else {
    const double half = 0.5 * (bottom - top) / px_per_x, mid = 0.5 * (ymin + ymax);
    ymin = mid - half, ymax = mid + half;
  }
}

void draw_grid(Canvas& c, const Axes& a) {
  for (double x : nice_ticks(a.xmin, a.xmax, 8)) {
    const float px = a.map(x, a.ymin).x;
    c.box({px - 0.5f, a.top}, {px + 0.5f, a.bottom}, kGrid);
  }
  for (double y : nice_ticks(a.ymin, a.ymax, 6)) {
    const float py = a.map(a.xmin, y).y;
    c.box({a.left, py - 0.5f}, {a.right, py + 0.5f}, kGrid);
  }
}

void draw_frame(Canvas& c, const Axes& a, const std::string& xlabel, const std::string& ylabel,
                const std::string& title, Rgba page, const std::vector<std::pair<double, std::string>>& x_ticks) {
  // Data drawn so far is clipped to the axes by painting the margins over it.
  const float w = static_cast<float>(c.width()), h = static_cast<float>(c.height());
  c.fill_rect({0, 0}, {w, a.top}, page);
  c.fill_rect({0, a.bottom}, {w, h}, page);
  c.fill_rect({0, a.top}, {a.left, a.bottom}, page);
  c.fill_rect({a.right, a.top}, {w, a.bottom}, page);
  const int font = std::max(10, static_cast<int>(std::lround(c.height() / 44.0)));
  const int tick_font = std::max(9, static_cast<int>(std::lround(0.85 * font)));
  const auto xt = nice_ticks(a.xmin, a.xmax, 8), yt = nice_ticks(a.ymin, a.ymax, 6);
  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : 1, ystep = yt.size() > 1 ? yt[1] - yt[0] : 1;
  std::vector<std::pair<double, std::string>> x_labels = x_ticks;
  if (x_labels.empty())
    for (double x : xt) x_labels.emplace_back(x, format_tick(x, xstep));
  for (const auto& [x, label] : x_labels) {
    const glm::vec2 p = a.map(x, a.ymin);
    c.box({p.x - 0.75f, a.bottom}, {p.x + 0.75f, a.bottom + 6}, kInk);
    c.text(label, {p.x, a.bottom + 8 + tick_font}, tick_font, kInk, TextAlign::kCenter);
  }
  for (double y : yt) {
    const glm::vec2 p = a.map(a.xmin, y);
    c.box({a.left - 6, p.y - 0.75f}, {a.left, p.y + 0.75f}, kInk);
    c.text(format_tick(y, ystep), {a.left - 10, p.y + 0.35f * tick_font}, tick_font, kInk, TextAlign::kRight);
  }
  c.box_outline({a.left, a.top}, {a.right, a.bottom}, 1.5f, kInk);
  c.text(xlabel, {0.5f * (a.left + a.right), a.bottom + 2.2f * font + 8}, font, kInk, TextAlign::kCenter);
  c.text(ylabel, {a.left - 4.2f * font, 0.5f * (a.top + a.bottom)}, font, kInk, TextAlign::kCenter, 1.5707963f);
  c.text(title, {0.5f * (a.left + a.right), a.top - 0.8f * font}, static_cast<int>(std::lround(1.2 * font)), kInk,
         TextAlign::kCenter);
}

std::vector<std::string> write_plots(const FrameSource& source, const std::string& dir, bool force, FrameRange frames,
                                     int width, int height) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir)) throw InputError(dir + ": cannot create the plots directory");
  frames.last = std::min(frames.last, source.frame_count() - 1);
  if (frames.first > frames.last) throw InputError(dir + ": no logged frame to plot");
  const Series s = collect(source, frames);
  // A plot of what the log has: a free rod's run has no magnetic force, tracking error or wall
  // contact to plot (each was an empty plot saying so), a run only pushed from its root no
  // magnetic force; only a fed run has the feed's push.
  std::vector<const char*> names = {"tip_trajectory.png"};
  if (s.has_actuation) names.push_back("actuation_force.png");
  names.push_back("snapshots.png");
  if (s.has_error) names.push_back("tracking_error.png");
  if (s.has_contact) names.push_back("contact_force.png");
  if (s.has_feed) names.push_back(kFeedPlotFile);
  // Refuse before drawing anything, so a refusal leaves the directory as it was.
  for (const char* name : names) check_replaceable_output((fs::path(dir) / name).string(), force, source.run_files());
  // Replacing the plots (force), those of another run that this one has none of go: left beside
  // this run's, they would pass for its own.
  const auto written_here = [&](const char* name) {
    return std::any_of(names.begin(), names.end(), [&](const char* n) { return std::string(n) == name; });
  };
  std::vector<const char*> every(std::begin(kRunPlotFiles), std::end(kRunPlotFiles));
  every.push_back(kFeedPlotFile);
  for (const char* name : every)
    if (force && !written_here(name) && fs::is_regular_file(fs::symlink_status(fs::path(dir) / name, ec)))
      fs::remove(fs::path(dir) / name, ec);
  const LogMetadata& m = source.metadata();
  std::vector<std::string> written;
  Canvas c(width, height);
  const int font = std::max(10, static_cast<int>(std::lround(height / 44.0)));
  const Rgba white = hex(0xFFFFFF);
  double max_act = 0, max_con = 0, max_feed = 0;
  for (const auto& f : s.actuation) max_act = std::max(max_act, f.norm());
  for (double f : s.max_contact) max_con = std::max(max_con, f);
  for (double f : s.feed_force) max_feed = std::max(max_feed, std::abs(f));
  const DisplayUnit fu = force_unit(std::max({max_act, max_con, max_feed}));
  const std::string force_label = std::string("force (") + fu.name + ")";
  const double to_mm = 1e3;
  // The plots of a run that failed, was stopped or was killed say so in their top margin, as its
  // video's HUD does.
  const auto finish = [&](const char* name) {
    if (const auto& end = source.ended_early()) {
      char note[96];
      std::snprintf(note, sizeof note, "Run %s at %.3f s: the plots end with its last logged frame", verb(end->how), end->at);
      c.text(note, {0.02f * static_cast<float>(width), 1.4f * static_cast<float>(font)}, font, kFailure);
    }
    save(c, (fs::path(dir) / name).string(), force, written);
  };

  {  // Tip trajectory against the reference, with actuation arrows (paper Fig. 11).
    c.clear(white);
    std::vector<double> magnitudes;
    for (const auto& f : s.actuation) magnitudes.push_back(f.norm());
    const double typical = typical_peak(magnitudes);
    const bool arrows = s.has_actuation && typical > 0;
    const auto force_entry = [&](double nominal_px) {
      return "magnetic force (" + format_value(typical, fu, 2) + " = " + std::to_string(int(std::lround(nominal_px))) + " px)";
    };
    // Only what the plot draws: a free rod's run has no path, one only pushed from its root no
    // magnetic force (the legend listed both, the title named the force).
    const bool path = m.path.size() >= 2;
    LegendEntries entries = {{kTip, "tip trajectory"}};
    if (path) entries.insert(entries.begin(), {kPath, "reference path"});
    if (arrows) entries.push_back({kActuation, force_entry(999)});  // as wide as the label gets
    Axes a = map_axes(c, source, s, to_mm, legend_width(c, entries, font));
    draw_grid(c, a);
    draw_walls(c, a, m, to_mm);
    // The trajectory first and the reference dashed on top, so both show where they coincide.
    std::vector<glm::vec2> pts;
    for (const auto& p : s.tip) pts.push_back(a.map(p.x() * to_mm, p.y() * to_mm));
    c.polyline(pts, 4.0f, kTip);
    pts.clear();
    for (const auto& p : m.path) pts.push_back(a.map(p.x() * to_mm, p.y() * to_mm));
    c.dashed_polyline(pts, 1.8f, 9, 6, kPath);
    if (arrows) {
      const double nominal = 0.06 * (a.right - a.left), px_per_n = nominal / typical;
      for (int k = 0; k < 16; ++k) {
        const std::size_t i = (s.t.size() - 1) * k / 15;
        const glm::vec2 p = a.map(s.tip[i].x() * to_mm, s.tip[i].y() * to_mm);
        glm::vec2 d(float(s.actuation[i].x() * px_per_n), float(-s.actuation[i].y() * px_per_n));
        const float len = std::sqrt(d.x * d.x + d.y * d.y);
        if (len > 2.5f * nominal) d *= float(2.5 * nominal) / len;  // rare spikes capped
        c.arrow(p, p + d, 2.5f, kActuation);
      }
      entries.back().second = force_entry(nominal);
    }
    draw_frame(c, a, "x (mm)", "y (mm)", arrows ? "Tip trajectory and magnetic force" : "Tip trajectory", white);
    legend(c, a, entries, font, true);
    finish("tip_trajectory.png");
  }
  if (s.has_actuation) {  // Actuation force over time (Fig. 12).
    c.clear(white);
    Axes a = time_axes(c, s);
    std::vector<double> mag, fx, fy;
    for (const auto& f : s.actuation) mag.push_back(f.norm() * fu.factor), fx.push_back(f.x() * fu.factor), fy.push_back(f.y() * fu.factor);
    std::vector<double> all = mag;
    all.insert(all.end(), fx.begin(), fx.end());
    all.insert(all.end(), fy.begin(), fy.end());
    fit_range(all, a.ymin, a.ymax, true);
    draw_grid(c, a);
    plot_line(c, a, s.t, fx, 2, kSecondary);
    plot_line(c, a, s.t, fy, 2, kTertiary, true);
    plot_line(c, a, s.t, mag, 3, kActuation);
    draw_frame(c, a, "time (s)", "magnetic " + force_label, "Actuation (magnetic) force on the robot", white);
    legend(c, a, {{kActuation, "|F|"}, {kSecondary, "Fx"}, {kTertiary, "Fy"}}, font);
    finish("actuation_force.png");
  }
  {  // Whole-body snapshots with contact arrows (Fig. 14).
    c.clear(white);
    // As in the video: the 95th percentile draws a fixed length, so one spike does not shrink
    // every arrow to nothing; rarer, larger forces draw longer, up to a cap.
    const double typical = typical_peak(s.max_contact);
    const auto contact_entry = [&](double nominal_px) {
      return "contact force (" + format_value(typical, fu, 2) + " = " + std::to_string(int(std::lround(nominal_px))) +
             " px, max " + format_value(max_con, fu, 2) + ")";
    };
    LegendEntries entries = {{hex(0x3B5BA5), "rod (lighter = earlier)"}};
    if (typical > 0) entries.push_back({kContact, contact_entry(999)});  // as wide as the label gets
    // The whole rod of every snapshot is in the picture (a catheter reaches back out of the
    // vessel through its inlet, past the walls and the path).
    constexpr int kSnapshots = 6;
    std::vector<FrameState> snapshots(kSnapshots);
    for (int k = 0; k < kSnapshots; ++k)
      source.frame(frames.first + (frames.last - frames.first) * static_cast<std::size_t>(k) / (kSnapshots - 1), snapshots[k]);
    Axes a = map_axes(c, source, s, to_mm, legend_width(c, entries, font), snapshots);
    draw_grid(c, a);
    draw_walls(c, a, m, to_mm);
    const double nominal = 0.05 * (a.right - a.left), px_per_n = typical > 0 ? nominal / typical : 0;
    if (typical > 0) entries.back().second = contact_entry(nominal);
    const int label_font = static_cast<int>(0.8 * font);
    // Every rod first, then the labels over them: a label is placed clear of every snapshot's
    // rod where there is room (ahead of one tip it could hide another snapshot's rod).
    LabelPlacer labels({{a.left, a.top}, {a.right, a.bottom}});
    std::vector<std::vector<glm::vec2>> rods(kSnapshots);
    for (int k = 0; k < kSnapshots; ++k) {
      const FrameState& f = snapshots[k];
      const float shade = 0.25f + 0.75f * k / (kSnapshots - 1);  // later snapshots darker
      const Rgba rod{0.85f - 0.75f * shade, 0.90f - 0.65f * shade, 0.97f - 0.45f * shade, 1};
      std::vector<glm::vec2>& pts = rods[k];
      for (std::size_t n = 0; n < f.node_count(); ++n) pts.push_back(a.map(f.node(n).x() * to_mm, f.node(n).y() * to_mm));
      c.polyline(pts, 3.5f, rod);
      for (std::size_t n = 1; n < pts.size(); ++n)
        labels.avoid({glm::min(pts[n - 1], pts[n]) - glm::vec2(2.0f), glm::max(pts[n - 1], pts[n]) + glm::vec2(2.0f)});
      for (std::size_t n = 0; px_per_n > 0 && n < f.node_count() && !f.contact.empty(); ++n) {
        glm::vec2 d(float(f.contact[2 * n] * px_per_n), float(-f.contact[2 * n + 1] * px_per_n));
        const float len = std::sqrt(d.x * d.x + d.y * d.y);
        if (len > 2.5f * nominal) d *= float(2.5 * nominal) / len;
        if (len >= 1) c.arrow(pts[n], pts[n] + d, 2, kContact);
      }
    }
    for (int k = 0; k < kSnapshots; ++k) {
      const std::vector<glm::vec2>& pts = rods[k];
      char label[32];
      std::snprintf(label, sizeof label, "t = %.2f s", snapshots[k].time);
      // Ahead of the tip, where this snapshot's own rod is not, on a light card (it may still
      // fall on a wall).
      glm::vec2 ahead = pts.size() > 1 ? pts.back() - pts[pts.size() - 2] : glm::vec2(1, 0);
      const float ahead_len = std::sqrt(ahead.x * ahead.x + ahead.y * ahead.y);
      ahead = ahead_len > 0 ? ahead / ahead_len : glm::vec2(1, 0);
      const float w = c.text_width(label, label_font), h = static_cast<float>(label_font);
      const glm::vec2 tip = pts.back() + 8.0f * ahead;
      glm::vec2 at;  // left end of the baseline
      if (std::abs(ahead.x) >= std::abs(ahead.y))
        at = {ahead.x >= 0 ? tip.x : tip.x - w, tip.y + 0.35f * h};
      else
        at = {tip.x - 0.5f * w, ahead.y > 0 ? tip.y + h : tip.y - 0.3f * h};
      // Moved off the labels before it (a rod that hardly moved puts every tip on one spot) and
      // off the rods, with a leader back to its tip.
      const LabelBox wanted{at + glm::vec2(-3, -1.05f * h), at + glm::vec2(w + 3, 0.35f * h)};
      const LabelBox box = labels.place(wanted);
      if (box.min != wanted.min) {
        const glm::vec2 end(std::clamp(tip.x, box.min.x, box.max.x), std::clamp(tip.y, box.min.y, box.max.y));
        c.polyline({pts.back(), end}, 1.0f, hex(0x868E96));
      }
      c.box(box.min, box.max, hex(0xFFFFFF, 0.8f), 3);
      c.text(label, box.min + glm::vec2(3, 1.05f * h), label_font, kInk);
    }
    draw_frame(c, a, "x (mm)", "y (mm)", typical > 0 ? "Rod snapshots and contact forces" : "Rod snapshots", white);
    legend(c, a, entries, font, true);
    finish("snapshots.png");
  }
  if (s.has_error) {  // Tracking error over time.
    c.clear(white);
    Axes a = time_axes(c, s);
    std::vector<double> e;
    for (double v : s.error) e.push_back(v * to_mm);
    fit_range(e, a.ymin, a.ymax, true);
    draw_grid(c, a);
    plot_line(c, a, s.t, e, 2.5f, kPath);
    // Without a target (nothing steers the tip) the error is measured from the path, and says so.
    draw_frame(c, a, "time (s)", s.error_from_path ? "distance from path (mm)" : "tip error (mm)",
               s.error_from_path ? "Distance from tip to reference path" : "Tracking error: distance from tip to reference",
               white);
    finish("tracking_error.png");
  }
  if (s.has_contact) {  // Contact force over time.
    c.clear(white);
    Axes a = time_axes(c, s);
    std::vector<double> mx, tot;
    for (std::size_t i = 0; i < s.t.size(); ++i) mx.push_back(s.max_contact[i] * fu.factor), tot.push_back(s.total_contact[i] * fu.factor);
    std::vector<double> all = mx;
    all.insert(all.end(), tot.begin(), tot.end());
    fit_range(all, a.ymin, a.ymax, true);
    draw_grid(c, a);
    plot_line(c, a, s.t, tot, 2, kSecondary);
    plot_line(c, a, s.t, mx, 2.5f, kContact);
    draw_frame(c, a, "time (s)", "contact " + force_label, "Wall contact force", white);
    legend(c, a, {{kContact, "largest on one node"}, {kSecondary, "sum over nodes"}}, font);
    finish("contact_force.png");
  }
  if (s.has_feed) {  // The drive's push on the rod over time (negative: pulling it back).
    c.clear(white);
    Axes a = time_axes(c, s);
    std::vector<double> feed;
    for (double f : s.feed_force) feed.push_back(f * fu.factor);
    fit_range(feed, a.ymin, a.ymax, true);
    draw_grid(c, a);
    plot_line(c, a, s.t, feed, 2.5f, kFeed);
    draw_frame(c, a, "time (s)", "feed " + force_label, "Feed: the drive's push on the rod along the inlet", white);
    finish(kFeedPlotFile);
  }
  return written;
}

}  // namespace vascsim::render

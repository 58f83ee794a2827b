#include "render/frame_painter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/vec3.hpp>

#include "render/palette.h"
#include "render/polygon_fill.h"

namespace vascsim::render {

namespace {

using palette::kActuation;
using palette::kContact;
using palette::kFailure;
using palette::kInk;

// The palette: a light, calm page; the lumen a pale tissue tone bounded by dark walls; the rod
// dark blue; forces in saturated colours that differ also in lightness (readable in grey).
constexpr Rgba kPage = hex(0xEEF1F4);
constexpr Rgba kLumen = hex(0xFCEFEA);
constexpr Rgba kTissue = hex(0xEBDCD6);  // around a vessel network's lumen, within the bounds
constexpr Rgba kWall = hex(0x3C4650);
constexpr Rgba kPath = hex(0x4C6EF5, 0.85f);
constexpr Rgba kTrail = hex(0xF59F00);
constexpr Rgba kRod = hex(0x1B3A5C);
constexpr Rgba kRodEdge = hex(0x0B1A2A);
constexpr Rgba kTip = hex(0x1971C2);
constexpr Rgba kStart = hex(0x2F9E44);
constexpr Rgba kGoal = hex(0xC92A2A);
constexpr Rgba kPanel = hex(0xFFFFFF);
constexpr Rgba kPanelEdge = hex(0xD0D5DB);
constexpr Rgba kMuted = hex(0x5F6B76);

glm::vec2 apply(const glm::dmat3& m, Vec2 p) {
  const glm::dvec3 q = m * glm::dvec3(p.x(), p.y(), 1.0);
  return {static_cast<float>(q.x), static_cast<float>(q.y)};
}

bool has_bounds(const LogMetadata& meta) { return (meta.bounds.max - meta.bounds.min).minCoeff() > 0; }
bool has_path(const LogMetadata& meta) { return meta.path.size() >= 2; }
bool has_vessel(const LogMetadata& meta) { return !meta.lumen.empty() || !meta.walls.empty(); }
// A scene without navigation logs neither a path nor a start and goal apart.
bool has_start_goal(const LogMetadata& meta) { return !meta.path.empty() || meta.start != meta.goal; }

// Everything the fit camera must show: the environment's bounds, the lumen and every wall
// including its thickness (a thick outer wall reaches beyond the bounds); without bounds, also
// the path and rod.
Box2 world_box(const LogMetadata& meta, const FrameState& first) {
  Box2 b{Vec2::Constant(1e300), Vec2::Constant(-1e300)};
  auto grow = [&](Vec2 p, double radius) {
    b.min = b.min.cwiseMin(p - Vec2::Constant(radius));
    b.max = b.max.cwiseMax(p + Vec2::Constant(radius));
  };
  for (const auto& w : meta.walls) grow(w.a, 0.5 * w.thickness), grow(w.b, 0.5 * w.thickness);
  for (const auto& ring : meta.lumen)
    for (const auto& p : ring) grow(p, 0.0);
  if (has_bounds(meta)) {
    grow(meta.bounds.min, 0.0), grow(meta.bounds.max, 0.0);
    return b;
  }
  for (const auto& p : meta.path) grow(p, 0.0);
  for (std::size_t i = 0; i < first.node_count(); ++i) grow(first.node(i), 0.0);
  const Vec2 pad = Vec2::Constant(std::max(1e-3, 0.05 * (b.max - b.min).maxCoeff()));
  return {b.min - pad, b.max + pad};
}

// A legend arrow: `reference` newtons at `px_per_newton` from `start` (its centre line), then,
// `gap` px on, its value on `baseline`; arrow, gap and value fit in `room` px. Where the
// reference does not fit, a smaller round value is drawn, so the arrow always has the length
// its label says.
// Returns false, drawing nothing, where there is no room for an arrow at all (its entry's name
// is then left out too: a name without its arrow read as a missing symbol).
bool legend_arrow(Canvas& c, glm::vec2 start, float baseline, float room, float gap, double px_per_newton,
                  double reference, const DisplayUnit& unit, Rgba colour, float width, int font) {
  auto label = [&](double value) { return format_round_value(value, unit); };
  const double fits = (room - gap - c.text_width(label(reference), font)) / px_per_newton;  // N
  if (reference > fits) reference = fits > 0 ? nice_floor(fits) : 0;
  const float len = static_cast<float>(reference * px_per_newton);
  if (len < 4.0f) return false;
  c.arrow(start, {start.x + len, start.y}, width, colour);
  c.text(label(reference), {start.x + len + gap, baseline}, font, kInk);
  return true;
}

// A scale bar of a round length at most `max_px` long, its left end at `left` (the bar's
// centre line), labelled on `label_baseline`: beside the bar's right end, or under its left end.
void scale_bar(Canvas& c, glm::vec2 left, double max_px, double px_per_metre, float label_baseline, bool label_beside,
               int font) {
  const double bar_m = nice_floor(max_px / px_per_metre);
  const float bar_px = static_cast<float>(bar_m * px_per_metre), x = left.x, y = left.y;
  c.box({x, y - 3}, {x + bar_px, y + 3}, kInk);
  c.box({x, y - 8}, {x + 2, y + 8}, kInk);
  c.box({x + bar_px - 2, y - 8}, {x + bar_px, y + 8}, kInk);
  c.text(format_round_value(bar_m, length_unit(bar_m)),
         {label_beside ? x + bar_px + 0.6f * font : x, label_baseline}, font, kInk);
}

float actuation_arrow_width(float frame_height) { return std::max(3.0f, frame_height / 200.0f); }
float contact_arrow_width(float frame_height) { return std::max(2.0f, frame_height / 280.0f); }

double max_node_force(const std::vector<double>& f) {
  double m = 0;
  for (std::size_t i = 0; i + 1 < f.size(); i += 2) m = std::max(m, std::hypot(f[i], f[i + 1]));
  return m;
}

constexpr Rgba kOverlayRod = hex(0xE64980, 0.6f);
constexpr Rgba kOverlayEdge = hex(0xA61E4D, 0.6f);
constexpr Rgba kFriction = hex(0x2B8A3E);
constexpr Rgba kDrag = hex(0x0C8599);
constexpr Rgba kNode = hex(0xFFFFFF);
constexpr Rgba kSupport = hex(0x343A40);
const glm::vec2 kDownOnScreen(0, 1), kLeftOnScreen(-1, 0);

}  // namespace

double typical_peak(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !(x > 0); }), v.end());
  if (v.empty()) return 0;
  const std::size_t k = v.size() < 20 ? v.size() - 1 : static_cast<std::size_t>(0.95 * (v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
  return v[k];
}

LayerSet layers_with_content(const LogMetadata& metadata, const FrameLogHeader& header) {
  const auto recorded = [&](const char* channel) { return header.find_channel(channel) >= 0; };
  const bool contact = recorded(channel::kContactForce);
  LayerSet s = LayerSet::none();
  for (int i = 0; i < static_cast<int>(Layer::kCount); ++i) s.set(static_cast<Layer>(i), true);
  return s.set(Layer::kLumen, !metadata.lumen.empty() || (has_vessel(metadata) && has_bounds(metadata)))
      .set(Layer::kWalls, !metadata.walls.empty())
      .set(Layer::kPath, has_path(metadata) || recorded(channel::kTipReference))
      .set(Layer::kStartGoal, has_start_goal(metadata))
      .set(Layer::kSupports, !metadata.boundary.empty())
      .set(Layer::kMagnetic, recorded(channel::kActuationForce))
      .set(Layer::kContact, contact)
      // Friction draws at the contact force's scale, which a log without contact forces lacks.
      .set(Layer::kFriction, contact && recorded(channel::kFrictionForce))
      .set(Layer::kDrag, recorded(channel::kDragForce));
}

const char* layer_content_phrase(Layer layer) {
  switch (layer) {
    case Layer::kLumen: return "a vessel";
    case Layer::kWalls: return "vessel walls";
    case Layer::kPath: return "a reference path";
    case Layer::kStartGoal: return "a start or goal";
    case Layer::kSupports: return "a clamp or supports";
    case Layer::kMagnetic: return "a magnetic force";
    case Layer::kContact: return "contact forces";
    case Layer::kFriction: return "friction forces";
    case Layer::kDrag: return "drag forces";
    default: return "";
  }
}

ForcePeaks measure_force_peaks(const FrameSource& source) {
  const std::size_t frames = source.frame_count();
  const std::size_t step = std::max<std::size_t>(1, frames / 2000);
  std::vector<double> act, con, drag;
  FrameState f;
  for (std::size_t i = 0; i < frames; i += step) {
    source.frame(i, f);
    act.push_back(f.actuation_total().norm());
    con.push_back(f.max_contact());
    drag.push_back(max_node_force(f.drag));
  }
  return {typical_peak(act), typical_peak(con), typical_peak(drag)};
}

ForceScales scales_for(const ForcePeaks& peaks, const View& view) {
  ForceScales s;
  const double span = std::min(view.width * (view.side_panel() ? 0.72 : 1.0), static_cast<double>(view.height));
  s.unit = force_unit(std::max(peaks.actuation, peaks.contact));
  // A typical large force draws this long: visible, yet short of crossing the maze. Rarer,
  // larger forces draw longer, up to a cap (the HUD gives their value).
  if (peaks.actuation > 0) {
    s.actuation_px_per_newton =
        view.actuation_px_per_newton > 0 ? view.actuation_px_per_newton : 0.16 * span / peaks.actuation;
    s.actuation_reference = nice_floor(peaks.actuation);
    if (view.actuation_px_per_newton <= 0) s.actuation_max_px = 0.4 * span;
  }
  if (peaks.contact > 0) {
    s.contact_px_per_newton = view.contact_px_per_newton > 0 ? view.contact_px_per_newton : 0.10 * span / peaks.contact;
    s.contact_reference = nice_floor(peaks.contact);
    if (view.contact_px_per_newton <= 0) s.contact_max_px = 0.25 * span;
  }
  if (peaks.drag > 0) {
    s.drag_px_per_newton = 0.10 * span / peaks.drag;
    s.drag_reference = nice_floor(peaks.drag);
    s.drag_max_px = 0.25 * span;
  }
  return s;
}

ForceScales choose_force_scales(const FrameSource& source, const View& view) {
  return scales_for(measure_force_peaks(source), view);
}

FramePainter::FramePainter(const LogMetadata& metadata, const View& view, const ForceScales& scales,
                           const FrameState& first_frame, const RunsEndedEarly& ended_early)
    : meta_(metadata), view_(view), scales_(scales), ended_early_(ended_early), world_(world_box(metadata, first_frame)) {
  hud_quantities_ = {first_frame.tip_error >= 0, !first_frame.actuation.empty(), first_frame.has_feed,
                     !first_frame.contact.empty()};
  // The lumen is triangulated once, in metres; each frame only moves the vertices. A single
  // axis-aligned rectangle (a maze logs its bounds so) is filled with a clear as before: cheaper,
  // and maze pictures stay exactly what they were.
  lumen_is_box_ = meta_.lumen.size() == 1 && axis_aligned_rectangle(meta_.lumen[0], lumen_box_);
  if (!lumen_is_box_) lumen_triangles_ = triangulate_even_odd(meta_.lumen);
  const double w = view.width, h = view.height;
  side_panel_ = view.side_panel();
  const bool hud = view.layers.has(Layer::kHud), legend = view.layers.has(Layer::kLegend);
  // From the height, as for video frames; a frame taller than about twice its width (a phone's
  // portrait view) takes it from the width, so the HUD card's rows keep their labels and values apart.
  font_px_ = std::max(9, static_cast<int>(std::lround(std::min(h / 36.0, w / 16.8))));
  hud_row_ = 1.45f * static_cast<float>(font_px_);
  map_x0_ = 0;
  // The panel needs about 15 characters of width whatever the frame size. A frame too small for
  // it beside a map of 30 % of the width (a thumbnail) gets the card and band of narrow frames
  // instead: a panel squeezed to nothing drew its values over the map without their labels.
  map_x1_ = static_cast<float>(side_panel_ ? std::round(w - std::max(0.28 * w, 15.0 * font_px_)) : w);
  if (map_x1_ - map_x0_ < 0.3 * w) side_panel_ = false, map_x1_ = static_cast<float>(w);
  // A HUD taller than the frame (the thumbnail of a run that ended early; a fed run's six rows in
  // a frame 100 px high) leaves out the title, not a value.
  if (hud && (side_panel_ ? hud_text_bottom() : card_bottom()) > h) title_line_ = false;
  // Still too tall (a fed, steered run compared with another, both ended early: eight rows in a
  // frame 100 px high): the rows close up, to no less than 1.2 font sizes apart.
  const float fs = static_cast<float>(font_px_), card_margin = side_panel_ ? 0.0f : 0.4f * fs;
  const float overflow = hud_text_bottom() + card_margin - static_cast<float>(h);
  const int rows = hud_quantities_.rows() + ended_early_.count();
  if (hud && overflow > 0 && rows > 1) hud_row_ = std::max(1.2f * fs, hud_row_ - overflow / static_cast<float>(rows - 1));
  // Without a side panel the HUD card takes a band across the top: the map starts below it, so
  // the card never hides a wall or the rod.
  // Likewise the legend (arrow scales, scale bar) takes a band across the bottom.
  map_y0_ = hud && !side_panel_ ? card_bottom() + 0.4f * static_cast<float>(font_px_) : 0.0f;
  map_y1_ = static_cast<float>(legend && !side_panel_ ? h - band_height() : h);
  // In a frame too small for the bands beside the map, the map takes the whole frame under them
  // rather than a sliver, or none: a negative height flipped the map.
  if (map_y1_ - map_y0_ < 0.3 * h) map_y0_ = 0.0f, map_y1_ = static_cast<float>(h);
  const Vec2 size = world_.max - world_.min;
  scale_ = 0.94 * std::min((map_x1_ - map_x0_) / size.x(), (map_y1_ - map_y0_) / size.y()) * view.zoom;
}

glm::dmat3 FramePainter::camera(const FrameState& frame) const {
  const Vec2 centre = view_.camera == CameraMode::kFollow   ? frame.tip()
                      : view_.camera == CameraMode::kCentre ? view_.centre
                                                            : Vec2(0.5 * (world_.min + world_.max));
  glm::dmat3 m(1.0);
  m[0][0] = scale_;
  m[1][1] = -scale_;  // y up in the world, down on screen
  m[2][0] = 0.5 * (map_x0_ + map_x1_) - centre.x() * scale_;
  m[2][1] = 0.5 * (map_y0_ + map_y1_) + centre.y() * scale_;
  return m;
}

glm::dvec2 FramePainter::to_pixel(const FrameState& frame, Vec2 world) const {
  const glm::dvec3 q = camera(frame) * glm::dvec3(world.x(), world.y(), 1.0);
  return {q.x, q.y};
}

ViewTransform FramePainter::transform(const FrameState& frame) const {
  const glm::dmat3 m = camera(frame);
  return {m[0][0], m[2][0], m[2][1]};
}

void FramePainter::paint(Canvas& c, const FrameState& frame, const std::vector<Vec2>& trail,
                         const FrameState* overlay) {
  c.clear(kPage);
  paint_world(c, camera(frame), frame, trail, overlay);
  overlay_shown_ = overlay && view_.layers.has(Layer::kRod);
  if (view_.panel()) paint_panel(c, frame);
}

void FramePainter::paint_world(Canvas& c, const glm::dmat3& m, const FrameState& f, const std::vector<Vec2>& trail,
                               const FrameState* overlay) {
  const LayerSet& on = view_.layers;
  const float h = static_cast<float>(view_.height);
  const float s = static_cast<float>(scale_);
  if (on.has(Layer::kLumen)) paint_lumen(c, m);
  const float min_wall = std::max(2.0f, h / 300.0f);
  if (on.has(Layer::kWalls))
    for (const auto& w : meta_.walls)
      c.capsule(apply(m, w.a), apply(m, w.b), 0.5f * std::max(min_wall, static_cast<float>(w.thickness) * s), kWall);

  if (path_drawn()) {
    scratch_.clear();
    for (const auto& p : meta_.path) scratch_.push_back(apply(m, p));
    const float line = std::max(1.5f, h / 400.0f);
    c.dashed_polyline(scratch_, line, 4 * line, 3 * line, kPath);
  }

  const float marker = std::max(4.0f, h / 90.0f);
  if (start_goal_drawn()) {
    c.disc(apply(m, meta_.start), marker, kStart);
    c.disc(apply(m, meta_.start), 0.4f * marker, hex(0xFFFFFF));
    c.ring(apply(m, meta_.goal), marker, 0.45f * marker, kGoal);
    c.disc(apply(m, meta_.goal), 0.3f * marker, kGoal);
  }

  if (on.has(Layer::kTrail)) {
    scratch_.clear();
    for (const auto& p : trail) scratch_.push_back(apply(m, p));
    c.polyline(scratch_, std::max(2.0f, h / 300.0f), kTrail);
  }

  if (on.has(Layer::kPath) && f.has_reference) c.ring(apply(m, f.reference), 0.6f * marker, 0.25f * marker, kPath);

  if (on.has(Layer::kRod)) paint_rod(c, m, f, kRod, kRodEdge, kTip);
  // The other run's rod on top, translucent: where the two coincide both stay visible.
  if (overlay && on.has(Layer::kRod)) paint_rod(c, m, *overlay, kOverlayRod, kOverlayEdge, kOverlayEdge);
  scratch_.clear();
  for (std::size_t i = 0; i < f.node_count(); ++i) scratch_.push_back(apply(m, f.node(i)));
  if (on.has(Layer::kNodes)) {
    const float r = std::max(1.5f, std::min(4.0f, static_cast<float>(meta_.rod_outer_radius * scale_) * 0.6f));
    for (const auto& p : scratch_) {
      c.disc(p, r + 1.0f, kRodEdge);
      c.disc(p, r, kNode);
    }
  }
  if (on.has(Layer::kSupports)) paint_supports(c);

  // Arrows start at the node they act on and point along the force (screen y flips).
  const float contact_w = contact_arrow_width(h);
  paint_arrows(c, f.drag, arrow_scale(Layer::kDrag), scales_.drag_max_px, contact_w, kDrag);
  paint_arrows(c, f.friction, arrow_scale(Layer::kFriction), scales_.contact_max_px, contact_w, kFriction);
  paint_arrows(c, f.contact, arrow_scale(Layer::kContact), scales_.contact_max_px, contact_w, kContact);
  if (arrow_scale(Layer::kMagnetic) > 0 && !f.actuation.empty()) {
    const Vec2 F = f.actuation_total() * arrow_scale(Layer::kMagnetic);
    if (F.norm() >= 1.0)
      c.arrow(scratch_.back(), scratch_.back() + arrow_vector(F, scales_.actuation_max_px), actuation_arrow_width(h), kActuation);
  }
}

// On screen (y down), no longer than `max_px` nor than a length that has left the frame from any
// point in it: a user's scale (1e12 px/N) made arrows of 1e9 px, whose width float precision
// lost in the shader, so none was drawn. In double until capped, so no length overflows a float.
glm::vec2 FramePainter::arrow_vector(const Vec2& px, double max_px) const {
  const double cap = std::min(max_px, 2.0 * (view_.width + view_.height));
  const double len = px.norm();
  const Vec2 d = len > cap ? Vec2(px * (cap / len)) : px;
  return {static_cast<float>(d.x()), static_cast<float>(-d.y())};
}

// The lumen in the tissue tone, so the walls read as the boundary of a channel: the logged rings'
// even-odd interior over the rest of the bounds in a darker tissue tone; in older logs, without
// rings, the environment's extent. A run without a vessel (a free rod) has none: its bounds only
// frame the rod, and a lumen-toned box around it read as a channel the rod was in.
void FramePainter::paint_lumen(Canvas& c, const glm::dmat3& m) {
  if (!has_vessel(meta_)) return;
  auto fill_box = [&](const Box2& b, Rgba colour) {
    const glm::vec2 b0 = apply(m, b.min), b1 = apply(m, b.max);
    c.fill_rect(glm::min(b0, b1), glm::max(b0, b1), colour);
  };
  const bool bounded = has_bounds(meta_);
  const bool lumen_is_bounds =
      lumen_is_box_ && lumen_box_.min == meta_.bounds.min && lumen_box_.max == meta_.bounds.max;
  if (meta_.lumen.empty() || lumen_is_bounds) {
    if (bounded) fill_box(meta_.bounds, kLumen);
    return;
  }
  if (bounded) fill_box(meta_.bounds, kTissue);
  if (lumen_is_box_) {
    fill_box(lumen_box_, kLumen);
    return;
  }
  lumen_px_.clear();
  for (const Triangle& t : lumen_triangles_)
    for (const Vec2* p : {&t.a, &t.b, &t.c}) lumen_px_.push_back(apply(m, *p));
  outline_px_.resize(meta_.lumen.size());
  for (std::size_t i = 0; i < meta_.lumen.size(); ++i) {
    outline_px_[i].clear();
    for (const Vec2& p : meta_.lumen[i]) outline_px_[i].push_back(apply(m, p));
  }
  c.region(lumen_px_, outline_px_, kLumen);
}

float FramePainter::rod_radius_px() const {
  return std::max(static_cast<float>(meta_.rod_outer_radius * scale_), 0.5f * float(view_.min_rod_width_px));
}

// The rod at its true radius, never thinner than min_rod_width_px, with a dark edge.
void FramePainter::paint_rod(Canvas& c, const glm::dmat3& m, const FrameState& f, Rgba body, Rgba edge, Rgba tip) {
  const float r = rod_radius_px();
  scratch_.clear();
  for (std::size_t i = 0; i < f.node_count(); ++i) scratch_.push_back(apply(m, f.node(i)));
  if (scratch_.empty()) return;
  c.polyline(scratch_, 2 * r + 2.0f, edge);
  c.polyline(scratch_, 2 * r, body);
  c.disc(scratch_.back(), r + 1.5f, tip);
}

// The symbols of how the rod is held (render/support_symbols.h), at the held nodes (scratch_) where
// they are now: a support holding y stands under its node (x slides), one holding x to its left
// (y slides). Sized from the rod's drawn width, so they read at any zoom without hiding a short
// rod, and never smaller than the start and goal markers, so a thin rod's clamp still reads in a
// whole-frame view.
void FramePainter::paint_supports(Canvas& c) const {
  const BoundarySpec& holds = meta_.boundary;
  const std::size_t n = scratch_.size();
  const float h = static_cast<float>(view_.height);
  const float u = std::clamp(2.5f * rod_radius_px(), std::max(5.0f, h / 72.0f), std::max(5.0f, h / 20.0f));
  const SupportPen pen{u, std::max(1.0f, 0.15f * u), kSupport, kNode};
  // A node index outside the rod (a hand-edited log) draws nothing.
  const auto at = [&](int node) -> const glm::vec2* { return node >= 0 && std::size_t(node) < n ? &scratch_[node] : nullptr; };
  if (holds.clamp != ClampKind::kNone && n >= 2) {
    const glm::vec2 d = scratch_[1] - scratch_[0];
    const glm::vec2 along = glm::length(d) > 0 ? glm::normalize(d) : glm::vec2(1, 0);
    draw_clamp(c, holds.clamp == ClampKind::kCentred ? 0.5f * (scratch_[0] + scratch_[1]) : scratch_[0], along, pen);
  }
  for (int node : holds.pinned)
    if (const glm::vec2* p = at(node)) draw_stand(c, *p, kDownOnScreen, false, pen);
  for (const SupportSpec& s : holds.supports)
    if (const glm::vec2* p = at(s.node)) draw_stand(c, *p, s.axis == SupportAxis::kY ? kDownOnScreen : kLeftOnScreen, true, pen);
  for (const PrescribedMotionSpec& moved : holds.prescribed)
    if (const glm::vec2* p = at(moved.node)) draw_moved_ring(c, *p, pen);
}

// The kinds of support the map draws (those at nodes of the rod), in the legend's order.
std::vector<SupportKind> FramePainter::supports_drawn(std::size_t nodes) const {
  const BoundarySpec& holds = meta_.boundary;
  const auto in_rod = [&](int node) { return node >= 0 && std::size_t(node) < nodes; };
  const auto held_in = [&](SupportAxis axis) {
    return std::any_of(holds.supports.begin(), holds.supports.end(),
                       [&](const SupportSpec& s) { return s.axis == axis && in_rod(s.node); });
  };
  std::vector<SupportKind> kinds;
  if (holds.clamp != ClampKind::kNone && nodes >= 2) kinds.push_back(SupportKind::kClamp);
  if (std::any_of(holds.pinned.begin(), holds.pinned.end(), in_rod)) kinds.push_back(SupportKind::kPin);
  if (held_in(SupportAxis::kY)) kinds.push_back(SupportKind::kHeldInY);
  if (held_in(SupportAxis::kX)) kinds.push_back(SupportKind::kHeldInX);
  if (std::any_of(holds.prescribed.begin(), holds.prescribed.end(),
                  [&](const PrescribedMotionSpec& p) { return in_rod(p.node); }))
    kinds.push_back(SupportKind::kMoved);
  return kinds;
}

// A support's legend symbol in the row whose top left corner is `top_left` (a row is 1.45 font
// sizes high): the map's symbol on a stub of rod, sized to fit the row.
void FramePainter::paint_support_key(Canvas& c, SupportKind kind, glm::vec2 top_left, int fs) const {
  const float size = 0.42f * static_cast<float>(fs);
  const SupportPen pen{size, std::max(1.0f, 0.15f * size), kSupport, kNode};
  const float x0 = top_left.x, x1 = x0 + 2.2f * fs, mid = top_left.y + 0.65f * fs;
  // Thinner than the catheter's own entry: the symbol is what this entry shows.
  const float stub = std::min(rod_radius_px(), 0.12f * fs);
  const auto rod_stub = [&](glm::vec2 from) {
    from.x = std::max(from.x, x0 + stub + 1.0f);
    c.capsule(from, {x1 - stub - 1.0f, from.y}, stub + 1.0f, kRodEdge);
    c.capsule(from, {x1 - stub - 1.0f, from.y}, stub, kRod);
  };
  // A standing symbol's node at the row's top, the symbol below it; one held in x at mid-row,
  // its symbol to the left.
  const glm::vec2 standing(x0 + 1.1f * fs, top_left.y + 0.3f * size + 1.0f);
  const glm::vec2 left_of(x0 + stand_depth(true, pen), mid);
  switch (kind) {
    case SupportKind::kClamp:
      rod_stub({x0 + 0.5f * fs, mid});
      draw_clamp(c, {x0 + 0.5f * fs, mid}, {1, 0}, pen);
      break;
    case SupportKind::kPin:
    case SupportKind::kHeldInY:
      rod_stub({x0, standing.y});
      draw_stand(c, standing, kDownOnScreen, kind == SupportKind::kHeldInY, pen);
      break;
    case SupportKind::kHeldInX:
      rod_stub(left_of);
      draw_stand(c, left_of, kLeftOnScreen, true, pen);
      break;
    case SupportKind::kMoved:
      rod_stub({x0, mid});
      draw_moved_ring(c, {x0 + 1.1f * fs, mid}, pen);
      break;
  }
}

// Per-node arrows from the node positions in scratch_.
void FramePainter::paint_arrows(Canvas& c, const std::vector<double>& forces, double px_per_newton, double max_px,
                                float width, Rgba colour) {
  if (px_per_newton <= 0 || forces.size() != 2 * scratch_.size()) return;
  for (std::size_t i = 0; i < scratch_.size(); ++i) {
    const Vec2 px = Vec2(forces[2 * i], forces[2 * i + 1]) * px_per_newton;
    if (px.norm() >= 1.0) c.arrow(scratch_[i], scratch_[i] + arrow_vector(px, max_px), width, colour);
  }
}

double FramePainter::arrow_scale(Layer layer) const {
  if (!view_.layers.has(layer)) return 0.0;
  switch (layer) {
    case Layer::kMagnetic: return scales_.actuation_px_per_newton;
    case Layer::kContact:
    case Layer::kFriction: return scales_.contact_px_per_newton;
    case Layer::kDrag: return scales_.drag_px_per_newton;
    default: return 0.0;
  }
}

bool FramePainter::path_drawn() const { return view_.layers.has(Layer::kPath) && has_path(meta_); }

bool FramePainter::start_goal_drawn() const { return view_.layers.has(Layer::kStartGoal) && has_start_goal(meta_); }

float FramePainter::card_bottom() const {
  const float fs = static_cast<float>(font_px_), pad = 0.8f * fs, row = hud_row_;
  const float title = title_line_ ? 1.3f : 0.0f, rows = static_cast<float>(hud_quantities_.rows() + ended_early_.count());
  const float natural = 0.5f * pad + (0.3f + title + rows) * row + pad;
  // A card taller than the frame even without its title (a thumbnail of two runs that ended
  // early) gives up its bottom margin first: it ended 3 px past a 90 px frame with room to spare.
  const float text_bottom = 0.5f * pad + hud_text_bottom();
  return std::min(natural, std::max(text_bottom + 0.1f * pad, static_cast<float>(view_.height) - 0.5f));
}

float FramePainter::hud_text_bottom() const {
  const float fs = static_cast<float>(font_px_), pad = 0.8f * fs, row = hud_row_;
  const float title = title_line_ ? 1.3f : 0.0f, rows = static_cast<float>(hud_quantities_.rows() + ended_early_.count());
  return pad + fs + (title + rows - 1.0f) * row + 0.35f * fs;
}

float FramePainter::band_height() const {
  const float fs = static_cast<float>(font_px_), pad = 0.8f * fs, row = 1.45f * fs;
  return 2.0f * pad + 2.0f * row;
}

// Narrow frames: the side panel's legend in brief, on a card across the bottom: each force
// arrow at the length of a round value, then the scale bar.
void FramePainter::paint_band(Canvas& c) const {
  const float W = static_cast<float>(view_.width), H = static_cast<float>(view_.height);
  const int fs = font_px_, small = std::max(9, static_cast<int>(std::lround(0.8 * fs)));
  const float pad = 0.8f * fs, row = 1.45f * fs, mid = -0.35f * fs;
  const float x0 = 0.5f * pad, x1 = W - 0.5f * pad, top = map_y1_ + 0.5f * pad;
  c.box({x0, top}, {x1, H - 0.5f * pad}, hex(0xFFFFFF, 0.88f), 0.4f * fs);
  float y = top + 0.5f * pad + 0.9f * fs;
  const float half = 0.5f * (x1 - x0 - pad);
  float x = x0 + 0.5f * pad;
  auto arrow_entry = [&](double px_per_newton, double reference, Rgba colour, float width, const char* what) {
    if (px_per_newton <= 0) return;
    const float start = x + c.text_width(what, small) + 0.5f * fs;
    if (legend_arrow(c, {start, y + mid}, y, x + half - start - 0.6f * fs, 0.4f * fs, px_per_newton, reference,
                     scales_.unit, colour, width, small))
      c.text(what, {x, y}, small, kInk);
    x += half;
  };
  arrow_entry(arrow_scale(Layer::kMagnetic), scales_.actuation_reference, kActuation, actuation_arrow_width(H), "Magnetic");
  arrow_entry(arrow_scale(Layer::kContact), scales_.contact_reference, kContact, contact_arrow_width(H), "Contact");
  y += row;
  scale_bar(c, {x0 + 0.5f * pad, y + mid}, 0.3 * (x1 - x0), scale_, y, true, small);
}

void FramePainter::paint_panel(Canvas& c, const FrameState& f) {
  const float W = static_cast<float>(view_.width), H = static_cast<float>(view_.height);
  const int fs = font_px_, small = std::max(9, static_cast<int>(std::lround(0.8 * fs)));
  const float pad = 0.8f * fs, row = 1.45f * fs;
  const bool hud = view_.layers.has(Layer::kHud), legend = view_.layers.has(Layer::kLegend);
  float x0, y0, x1;
  if (side_panel_) {
    x0 = map_x1_;
    x1 = W;
    y0 = 0;
    c.fill_rect({x0, 0}, {W, H}, kPanel);
    c.fill_rect({x0, 0}, {x0 + 1.0f, H}, kPanelEdge);
  } else {
    if (legend) paint_band(c);
    if (!hud) return;
    // Narrow frames: a compact translucent card over the map's top-left corner.
    x0 = 0.5f * pad;
    y0 = 0.5f * pad;
    x1 = x0 + std::min(W - pad, 16.0f * fs);
    c.box({x0, y0}, {x1, card_bottom()}, hex(0xFFFFFF, 0.88f), 0.4f * fs);
  }
  const float lx = x0 + pad, rx = x1 - pad;
  float y = y0 + pad + fs;
  char buf[64];
  panel_items_.clear();
  hud_fields_.clear();
  // A line of text at baseline `baseline` reaches from one font size above it to a third below.
  const auto record = [&](const char* what, float first_baseline, float last_baseline, const std::string& label = {}) {
    panel_items_.push_back({what, lx, rx, first_baseline - fs, last_baseline + 0.35f * fs, label});
  };
  if (hud) {
    const float hud_top = y;
    if (!meta_.title.empty() && title_line_) {
      c.text(meta_.title, {lx, y}, static_cast<int>(std::lround(1.1 * fs)), kInk);
      y += 1.3f * hud_row_;
    }
    const DisplayUnit mm = length_unit(0.01);
    std::snprintf(buf, sizeof buf, "%.3f s", f.time);
    // The first label that leaves room for the value; in a card too narrow for any, the value
    // alone (the rows' order is the same at every size).
    auto field = [&](std::initializer_list<const char*> labels, const std::string& value, Rgba label_colour = kMuted,
                     Rgba value_colour = kInk) {
      const float value_left = rx - c.text_width(value, fs);
      const char* shown = nullptr;
      for (const char* label : labels)
        if (lx + c.text_width(label, fs) + 0.5f * fs <= value_left) {
          shown = label;
          break;
        }
      if (shown) c.text(shown, {lx, y}, fs, label_colour);
      c.text(value, {rx, y}, fs, value_colour, TextAlign::kRight);
      hud_fields_.push_back({shown ? shown : "", shown ? lx + c.text_width(shown, fs) : lx, value_left, value});
      y += hud_row_;
    };
    field({"Time", "t"}, buf);
    if (hud_quantities_.tip_error) field({"Tip error", "Error"}, format_value(f.tip_error, mm, 2));
    if (hud_quantities_.magnetic)
      field({"Magnetic force", "Magnetic", "Force"}, format_value(f.actuation_total().norm(), scales_.unit, 2));
    if (hud_quantities_.feed) {
      // The drive's push at the force arrows' unit; a pull shows with its sign (not a push too
      // small to show: "-0.00 mN").
      const double push = std::abs(f.feed_force * scales_.unit.factor) < 0.005 ? 0.0 : f.feed_force;
      field({"Feed force", "Feed"}, format_value(push, scales_.unit, 2));
      field({"Fed length", "Fed"}, format_value(f.fed_length, mm, 1));
    }
    if (hud_quantities_.contact) field({"Max contact", "Contact"}, format_value(f.max_contact(), scales_.unit, 2));
    // Literals: hud_fields() keeps the label shown.
    if (const auto& end = ended_early_.run) {
      std::snprintf(buf, sizeof buf, "at %.3f s", end->at);
      switch (end->how) {
        case EarlyEnd::How::kFailed: field({"Run failed", "Failed"}, buf, kFailure, kFailure); break;
        case EarlyEnd::How::kStopped: field({"Run stopped", "Stopped"}, buf, kFailure, kFailure); break;
        case EarlyEnd::How::kKilled: field({"Run killed", "Killed"}, buf, kFailure, kFailure); break;
      }
    }
    if (const auto& end = ended_early_.overlay) {
      std::snprintf(buf, sizeof buf, "at %.3f s", end->at);
      switch (end->how) {
        case EarlyEnd::How::kFailed: field({"Compared run failed", "Compared failed", "B failed"}, buf, kFailure, kFailure); break;
        case EarlyEnd::How::kStopped:
          field({"Compared run stopped", "Compared stopped", "B stopped"}, buf, kFailure, kFailure);
          break;
        case EarlyEnd::How::kKilled: field({"Compared run killed", "Compared killed", "B killed"}, buf, kFailure, kFailure); break;
      }
    }
    // On a card, the card is what it was laid out in.
    if (side_panel_)
      record("hud", hud_top, y - hud_row_);
    else
      panel_items_.push_back({"hud", x0, x1, y0, card_bottom(), {}});
  }
  if (!side_panel_ || !legend) return;

  // Legend: each symbol as drawn on the map; force arrows at the length of a round value.
  if (hud) {
    y += 0.6f * row;
    c.box({lx, y - fs}, {rx, y - fs + 1.0f}, kPanelEdge);
    y += 0.4f * row;
  }
  // The scale bar sits at the bottom (its ends reach 8 px above its line); the entries above it
  // in order of need: the force arrows (their lengths are read against them), then the symbols.
  // In a short frame the entries that would reach the scale bar are left out, not drawn over it.
  const float by = H - pad - 1.6f * fs, bar_top = by - 8.0f;
  const auto fits = [&](int rows) { return y + (rows - 1) * row + 0.35f * fs <= bar_top - 0.3f * fs; };
  const float sym_end = lx + 2.2f * fs, text_x = lx + 2.8f * fs, mid = -0.35f * fs;
  auto entry = [&](const std::string& label) {
    c.text(label, {text_x, y}, small, kInk);
    record("legend", y, y, label);
    y += row;
  };
  auto arrow_entry = [&](double px_per_newton, double reference, Rgba colour, float width, const char* what) {
    if (px_per_newton <= 0 || !fits(2)) return;
    c.text(what, {lx, y}, small, kInk);
    record("legend", y, y + row, what);
    y += row;
    legend_arrow(c, {lx, y + mid}, y, rx - lx, 0.6f * fs, px_per_newton, reference, scales_.unit, colour, width, small);
    y += row;
  };
  // A lambda so that the first entry that does not fit ends the list (those below need less room
  // only by accident, and a gap in the order reads as a missing symbol).
  const auto symbols = [&] {
    arrow_entry(arrow_scale(Layer::kMagnetic), scales_.actuation_reference, kActuation, actuation_arrow_width(H),
                "Magnetic force");
    arrow_entry(arrow_scale(Layer::kContact), scales_.contact_reference, kContact, contact_arrow_width(H), "Contact force");
    if (!f.friction.empty())
      arrow_entry(arrow_scale(Layer::kFriction), scales_.contact_reference, kFriction, contact_arrow_width(H), "Friction force");
    if (!f.drag.empty())
      arrow_entry(arrow_scale(Layer::kDrag), scales_.drag_reference, kDrag, contact_arrow_width(H), "Drag force");
    if (!fits(1)) return;
    // The rod as thick as the map draws it, up to the height of its row: zoomed in, a true-width
    // symbol became a disc over the entries above and below (its label gives the diameter).
    const float r = std::min(rod_radius_px(), 0.35f * fs);
    c.capsule({lx + r + 1, y + mid}, {sym_end - r - 1, y + mid}, r + 1.0f, kRodEdge);
    c.capsule({lx + r + 1, y + mid}, {sym_end - r - 1, y + mid}, r, kRod);
    std::snprintf(buf, sizeof buf, "catheter \xC3\x98 %.2f mm", 2e3 * meta_.rod_outer_radius);
    entry(buf);
    if (overlay_shown_) {
      if (!fits(1)) return;
      c.capsule({lx + r + 1, y + mid}, {sym_end - r - 1, y + mid}, r + 1.0f, kOverlayEdge);
      c.capsule({lx + r + 1, y + mid}, {sym_end - r - 1, y + mid}, r, kOverlayRod);
      entry("compared run's catheter");
    }
    // Only what the map draws: a free rod's run has no path, start or goal to explain.
    if (path_drawn()) {
      if (!fits(1)) return;
      c.dashed_polyline({{lx, y + mid}, {sym_end, y + mid}}, std::max(1.5f, H / 400.0f), 6.0f, 4.0f, kPath);
      entry("reference path");
    }
    if (view_.layers.has(Layer::kTrail)) {
      if (!fits(1)) return;
      c.capsule({lx, y + mid}, {sym_end, y + mid}, 0.5f * std::max(2.0f, H / 300.0f), kTrail);
      entry("tip trail");
    }
    if (view_.layers.has(Layer::kSupports))
      for (SupportKind kind : supports_drawn(f.node_count())) {
        if (!fits(1)) return;
        paint_support_key(c, kind, {lx, y - fs}, fs);
        entry(support_label(kind));
      }
    if (!start_goal_drawn() || !fits(1)) return;
    const float mk = std::min(0.45f * fs, std::max(4.0f, H / 90.0f));
    c.disc({lx + mk, y + mid}, mk, kStart);
    c.disc({lx + mk, y + mid}, 0.4f * mk, hex(0xFFFFFF));
    c.ring({sym_end - mk, y + mid}, mk, 0.45f * mk, kGoal);
    c.disc({sym_end - mk, y + mid}, 0.3f * mk, kGoal);
    entry("start, goal");
  };
  symbols();

  // Scale bar at the bottom: a round length about half the panel wide; left out where the HUD
  // itself reaches down to it (a frame a few text lines high).
  if (!panel_items_.empty() && panel_items_.back().bottom > bar_top - 0.3f * fs) return;
  scale_bar(c, {lx, by}, 0.6 * (rx - lx), scale_, by + 1.4f * fs, false, small);
  panel_items_.push_back({"scale bar", lx, rx, bar_top, by + 1.75f * fs, {}});
}

}  // namespace vascsim::render

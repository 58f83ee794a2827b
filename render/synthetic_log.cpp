#include "render/synthetic_log.h"

#include <algorithm>
#include <cmath>

#include "sim/log/frame_log.h"

namespace vascsim::render {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Point and unit tangent at arc length s along a polyline; beyond the ends it continues straight.
void along(const Polyline& path, double s, Vec2& point, Vec2& tangent) {
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Vec2 d = path[i] - path[i - 1];
    const double len = d.norm();
    if (s <= len || i + 1 == path.size()) {
      tangent = d / len;
      point = path[i - 1] + tangent * s;
      return;
    }
    s -= len;
  }
}

}  // namespace

LogMetadata synthetic_metadata(const SyntheticLogSpec& spec) {
  LogMetadata m;
  const int n = spec.grid;
  const double c = spec.cell;
  m.title = spec.title;
  m.bounds = {Vec2(0, 0), Vec2(n * c, n * c)};
  auto wall = [&](double x0, double y0, double x1, double y1) {
    m.walls.push_back({Vec2(x0, y0), Vec2(x1, y1), spec.wall_thickness});
  };
  for (int k = 0; k < n; ++k) {  // the outer boundary, one segment per cell edge
    wall(k * c, 0, (k + 1) * c, 0);
    wall(k * c, n * c, (k + 1) * c, n * c);
    wall(0, k * c, 0, (k + 1) * c);
    wall(n * c, k * c, n * c, (k + 1) * c);
  }
  // Row separators leave one gap, alternately at the right and the left end: a serpentine.
  for (int r = 0; r + 1 < n; ++r) {
    const int gap = r % 2 == 0 ? n - 1 : 0;
    for (int k = 0; k < n; ++k)
      if (k != gap) wall(k * c, (r + 1) * c, (k + 1) * c, (r + 1) * c);
  }
  for (int r = 0; r < n; ++r) {
    const double y = (r + 0.5) * c;
    const double x_in = r % 2 == 0 ? 0.5 * c : (n - 0.5) * c, x_out = r % 2 == 0 ? (n - 0.5) * c : 0.5 * c;
    m.path.emplace_back(x_in, y);
    m.path.emplace_back(x_out, y);
  }
  m.lumen_width = c;
  m.start = m.path.front();
  m.goal = m.path.back();
  m.rod_outer_radius = spec.rod_radius;
  m.rod_length = spec.rod_length;
  m.output_interval = spec.frames > 1 ? spec.duration / (spec.frames - 1) : 0.0;
  return m;
}

void write_synthetic_log(const std::string& path, const SyntheticLogSpec& spec) {
  write_synthetic_log(path, spec, synthetic_metadata(spec));
}

void write_synthetic_log(const std::string& path, const SyntheticLogSpec& spec, const LogMetadata& m) {
  const auto nodes = static_cast<std::uint32_t>(spec.nodes);
  FrameLogHeader h;
  h.node_count = nodes;
  h.channels.push_back({channel::kPosition, "m", ChannelLayout::kNodeVectors, 2 * nodes});
  if (spec.forces) {
    h.channels.push_back({channel::kActuationForce, "N", ChannelLayout::kNodeVectors, 2 * nodes});
    h.channels.push_back({channel::kContactForce, "N", ChannelLayout::kNodeVectors, 2 * nodes});
  }
  if (spec.friction_and_drag) {
    h.channels.push_back({channel::kFrictionForce, "N", ChannelLayout::kNodeVectors, 2 * nodes});
    h.channels.push_back({channel::kDragForce, "N", ChannelLayout::kNodeVectors, 2 * nodes});
  }
  if (spec.reference) {
    h.channels.push_back({channel::kTipReference, "m", ChannelLayout::kVector, 2});
    h.channels.push_back({channel::kTipError, "m", ChannelLayout::kScalars, 1});
  }
  if (spec.feed) {
    h.channels.push_back({channel::kFeedForce, "N", ChannelLayout::kScalars, 1});
    h.channels.push_back({channel::kFeedLength, "m", ChannelLayout::kScalars, 1});
  }
  h.metadata = write_log_metadata(m);
  FrameLogWriter writer(path, h);

  // A log of a run without a path (a free rod's) still needs a rod that moves.
  const Polyline route = m.path.size() >= 2 ? m.path : synthetic_metadata(spec).path;
  const double ds = spec.rod_length / (spec.nodes - 1);
  std::vector<double> values, pos(2 * nodes), act(2 * nodes), con(2 * nodes), friction(2 * nodes), drag(2 * nodes);
  for (int f = 0; f < spec.frames; ++f) {
    const double t = spec.frames > 1 ? spec.duration * f / (spec.frames - 1) : 0.0;
    const double s_tip = spec.rod_length + spec.speed * t;
    std::vector<Vec2> normals(nodes);
    for (std::uint32_t i = 0; i < nodes; ++i) {
      const double s = s_tip - (nodes - 1 - i) * ds;
      Vec2 p = Vec2::Zero(), tangent = Vec2::UnitX();
      along(route, s, p, tangent);
      normals[i] = Vec2(-tangent.y(), tangent.x());
      // An S-shaped wiggle that fades to zero at the tip, so the tip stays on the path.
      const double wiggle = 0.12 * spec.cell * std::sin(2 * kPi * s / (1.5 * spec.cell)) * (s_tip - s) / spec.rod_length;
      p += normals[i] * wiggle;
      pos[2 * i] = p.x();
      pos[2 * i + 1] = p.y();
    }
    Vec2 tip_p = Vec2::Zero(), tip_t = Vec2::UnitX();
    along(route, s_tip, tip_p, tip_t);
    values.assign(pos.begin(), pos.end());
    if (spec.forces) {
      std::fill(act.begin(), act.end(), 0.0);
      act[2 * (nodes - 1)] = spec.actuation * tip_t.x();
      act[2 * (nodes - 1) + 1] = spec.actuation * tip_t.y();
      std::fill(con.begin(), con.end(), 0.0);
      for (std::size_t k = 0; k < spec.contact_nodes.size(); ++k) {
        const int i = std::clamp(spec.contact_nodes[k], 0, spec.nodes - 1);
        const double sign = k % 2 == 0 ? 1.0 : -1.0;
        con[2 * i] = sign * spec.contact * normals[i].x();
        con[2 * i + 1] = sign * spec.contact * normals[i].y();
      }
      values.insert(values.end(), act.begin(), act.end());
      values.insert(values.end(), con.begin(), con.end());
    }
    if (spec.friction_and_drag) {
      std::fill(friction.begin(), friction.end(), 0.0);
      for (const int k : spec.contact_nodes) {
        const auto i = static_cast<std::size_t>(std::clamp(k, 0, spec.nodes - 1));
        friction[2 * i] = -0.5 * spec.contact * normals[i].y();
        friction[2 * i + 1] = 0.5 * spec.contact * normals[i].x();
      }
      std::fill(drag.begin(), drag.end(), 0.0);
      const std::size_t tip = nodes - 1;  // against the motion: the normal turned back
      drag[2 * tip] = -0.1 * spec.actuation * normals[tip].y();
      drag[2 * tip + 1] = 0.1 * spec.actuation * normals[tip].x();
      values.insert(values.end(), friction.begin(), friction.end());
      values.insert(values.end(), drag.begin(), drag.end());
    }
    if (spec.reference) {
      Vec2 ref = Vec2::Zero(), ref_t = Vec2::UnitX();
      along(route, s_tip + 0.2 * spec.cell, ref, ref_t);
      const Vec2 tip(pos[2 * (nodes - 1)], pos[2 * (nodes - 1) + 1]);
      values.push_back(ref.x());
      values.push_back(ref.y());
      values.push_back((tip - ref).norm());
    }
    if (spec.feed) {
      values.push_back(spec.feed_force * (spec.duration > 0 ? t / spec.duration : 1.0));
      values.push_back(spec.speed * t);
    }
    writer.append(t, values);
  }
  writer.close();
}

}  // namespace vascsim::render

#include "sim/io/log_metadata.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "sim/io/json_fields.h"
#include "sim/io/scene_sections.h"
#include "sim/scene/input_error.h"

namespace vascsim {

using nlohmann::json;

namespace {

json point(const Vec2& p) { return json::array({p.x(), p.y()}); }

Polyline read_polyline(const json& array, const io::FieldReader& in, const std::string& key) {
  if (!array.is_array()) in.fail(key, "an array of points", array);
  Polyline out;
  for (const auto& p : array) {
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
      in.fail(key, "an array of [x, y] points", p);
    out.emplace_back(p[0].get<double>(), p[1].get<double>());
  }
  return out;
}

}  // namespace

std::string write_log_metadata(const LogMetadata& m) {
  json j;
  j["title"] = m.title;
  j["scene"] = m.scene_json.empty() ? json(nullptr) : json::parse(m.scene_json);
  j["bounds"] = {point(m.bounds.min), point(m.bounds.max)};
  json walls = json::array();
  for (const auto& w : m.walls) walls.push_back({w.a.x(), w.a.y(), w.b.x(), w.b.y(), w.thickness});
  j["walls"] = walls;
  j["lumen_width"] = m.lumen_width;
  json lumen = json::array();
  for (const auto& ring : m.lumen) {
    json points = json::array();
    for (const auto& p : ring) points.push_back(point(p));
    lumen.push_back(points);
  }
  j["lumen"] = lumen;
  json path = json::array();
  for (const auto& p : m.path) path.push_back(point(p));
  j["path"] = path;
  j["start"] = point(m.start);
  j["goal"] = point(m.goal);
  j["rod"] = {{"outer_radius", m.rod_outer_radius}, {"length", m.rod_length}};
  j["output_interval"] = m.output_interval;
  if (!m.boundary.empty()) j["boundary"] = io::write_boundary(m.boundary);
  j["provenance"] = {{"vascsim_version", m.vascsim_version}, {"commit", m.commit}, {"scene_hash", m.scene_hash}};
  return j.dump();
}

LogMetadata read_log_metadata(const std::string& text, const std::string& label) {
  const json j = io::parse_json_strictly(text, label + " (metadata)");
  LogMetadata m;
  // Newer writers may add keys, here or in a nested object; an older reader ignores them rather
  // than refusing the log (values it knows are still checked).
  io::FieldReader in(j, label + " (metadata)", "", io::UnknownKeys::kIgnore);
  m.title = in.text("title", "");
  if (const json* scene = in.raw("scene"); scene && !scene->is_null()) m.scene_json = scene->dump(2);
  if (const json* b = in.raw("bounds")) {
    Polyline corners = read_polyline(*b, in, "bounds");
    if (corners.size() != 2) in.fail("bounds", "two corners", *b);
    m.bounds = {corners[0], corners[1]};
  }
  if (const json* walls = in.raw("walls")) {
    if (!walls->is_array()) in.fail("walls", "an array", *walls);
    for (const auto& w : *walls) {
      if (!w.is_array() || w.size() != 5) in.fail("walls", "[x0, y0, x1, y1, thickness] items", w);
      for (const auto& v : w)
        if (!v.is_number()) in.fail("walls", "numbers", w);
      m.walls.push_back({Vec2(w[0].get<double>(), w[1].get<double>()), Vec2(w[2].get<double>(), w[3].get<double>()),
                         w[4].get<double>()});
    }
  }
  m.lumen_width = in.number("lumen_width", 0.0, 0.0, 1e6);
  if (const json* lumen = in.raw("lumen")) {
    if (!lumen->is_array()) in.fail("lumen", "an array of rings", *lumen);
    for (const auto& ring : *lumen) {
      m.lumen.push_back(read_polyline(ring, in, "lumen"));
      if (m.lumen.back().size() < 3) in.fail("lumen", "rings of at least 3 points", ring);
    }
  }
  if (const json* path = in.raw("path")) m.path = read_polyline(*path, in, "path");
  m.start = in.vec2("start", m.start);
  m.goal = in.vec2("goal", m.goal);
  auto rod = in.object("rod");
  m.rod_outer_radius = rod.number("outer_radius", 0.0, 0.0, 1e6);
  m.rod_length = rod.number("length", 0.0, 0.0, 1e6);
  m.output_interval = in.number("output_interval", 0.0, 0.0, 1e9);
  if (in.raw("boundary")) {
    io::FieldReader boundary = in.object("boundary");
    io::read_boundary(boundary, m.boundary);
  }
  if (const json* p = in.raw("provenance"); p && p->is_object()) {
    auto text = [&](const char* key) { return p->contains(key) && (*p)[key].is_string() ? (*p)[key].get<std::string>() : ""; };
    m.vascsim_version = text("vascsim_version");
    m.commit = text("commit");
    m.scene_hash = text("scene_hash");
  }
  return m;
}

bool same_environment(const LogMetadata& a, const LogMetadata& b) {
  const auto same_wall = [](const WallSegment& p, const WallSegment& q) {
    return p.a == q.a && p.b == q.b && p.thickness == q.thickness;
  };
  return a.bounds.min == b.bounds.min && a.bounds.max == b.bounds.max && a.lumen == b.lumen &&
         std::equal(a.walls.begin(), a.walls.end(), b.walls.begin(), b.walls.end(), same_wall);
}

}  // namespace vascsim

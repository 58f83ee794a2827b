// The `vessels` section: a centreline graph or an image mask (docs/environment.md).
#include <cmath>
#include <filesystem>

#include "sim/io/scene_sections.h"

namespace vascsim::io {

using nlohmann::json;

namespace {

// m: a number (the same at both ends) or an array of them.
std::vector<double> read_radii(FieldReader& in) {
  const json* r = in.raw("radius");
  if (!r) in.fail("radius", "a radius (m) or an array of radii", json());
  if (r->is_number()) return {in.positive("radius", 0.0, 1e3), 0.0};
  if (!r->is_array() || r->empty()) in.fail("radius", "a radius (m) or an array of radii", *r);
  std::vector<double> out;
  for (std::size_t k = 0; k < r->size(); ++k) {
    if (!(*r)[k].is_number()) in.fail("radius", "numbers (m)", *r);
    out.push_back((*r)[k].get<double>());
  }
  return out;
}

template <typename Item, typename Reader>
std::vector<Item> read_list(FieldReader& in, const std::string& key, const std::string& expected, Reader reader,
                            std::size_t max_items = 100000) {
  std::vector<Item> out;
  const json* list = in.raw(key);
  if (!list) return out;
  if (!list->is_array()) in.fail(key, expected, *list);
  if (list->size() > max_items) in.fail(key, expected + ", at most " + std::to_string(max_items), *list);
  for (std::size_t i = 0; i < list->size(); ++i) {
    FieldReader item = in.nested(list->at(i), key + "/" + std::to_string(i));
    if (!list->at(i).is_object()) item.fail("", expected, list->at(i));
    out.push_back(reader(item));
    item.finish();
  }
  return out;
}

// Per segment. Building the lumen costs more than linearly in them (8000 via points took 21 s and
// 1.1 GB, 5000 stenoses 60 s and 3.3 GB), and no drawn or traced vessel needs more.
constexpr std::size_t kMaxViaPoints = 2000;
constexpr std::size_t kMaxStenoses = 100, kMaxAneurysms = 100;
constexpr const char* kPointWithinBounds = "a point [x, y] (m) with |x|, |y| <= 1000";
bool within_bounds(const Vec2& p) { return std::abs(p.x()) <= kMaxCoordinate && std::abs(p.y()) <= kMaxCoordinate; }

VesselSegmentSpec read_segment(FieldReader& in) {
  VesselSegmentSpec s;
  s.from = in.text("from", "");
  s.to = in.text("to", "");
  if (s.from.empty()) in.fail("from", "a node name", in.has("from") ? *in.raw("from") : json());
  if (s.to.empty()) in.fail("to", "a node name", in.has("to") ? *in.raw("to") : json());
  s.radius = read_radii(in);
  if (s.radius.size() == 2 && s.radius[1] == 0.0 && in.raw("radius")->is_number()) s.radius[1] = s.radius[0];
  if (const json* via = in.raw("via")) {
    if (!via->is_array() || via->size() > kMaxViaPoints)
      in.fail("via", "an array of at most " + std::to_string(kMaxViaPoints) + " [x, y] points (m); resample a longer centreline", *via);
    for (std::size_t k = 0; k < via->size(); ++k) {
      const json& p = via->at(k);
      const std::string at = "via/" + std::to_string(k);
      if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
        in.fail(at, "a point [x, y] (m)", p);
      s.via.emplace_back(p[0].get<double>(), p[1].get<double>());
      if (!s.via.back().allFinite()) in.fail(at, "a finite point", p);
      if (!within_bounds(s.via.back())) in.fail(at, kPointWithinBounds, p);
    }
  }
  s.stenoses = read_list<StenosisSpec>(in, "stenoses", "an array of {\"at\", \"length\", \"fraction\"}", [](FieldReader& f) {
    StenosisSpec st;
    st.at = f.number("at", st.at, 0.0, 1e3);
    st.length = f.positive("length", st.length, 1e3);
    st.fraction = f.positive("fraction", st.fraction, 1.0);
    return st;
  }, kMaxStenoses);
  s.aneurysms = read_list<AneurysmSpec>(in, "aneurysms", "an array of {\"at\", \"side\", \"radius\", \"neck\"}", [](FieldReader& f) {
    AneurysmSpec a;
    a.at = f.number("at", a.at, 0.0, 1e3);
    a.left = f.choice("side", "left", {"left", "right"}) == "left";
    a.radius = f.positive("radius", a.radius, 1e3);
    a.neck = f.positive("neck", a.neck, 1e3);
    return a;
  }, kMaxAneurysms);
  return s;
}

// Returns the `pixel_hash` the scene states ("" if none), checked once the pixels are read.
std::string read_mask(FieldReader& in, VesselMaskSpec& m) {
  m.file = in.text("file", "");
  if (m.file.empty()) in.fail("file", "the path of a PNG (white lumen on black)", in.has("file") ? *in.raw("file") : json());
  m.pixel_size = in.positive("pixel_size", m.pixel_size, 1.0);
  // Grey levels at or above the threshold are lumen: 0 would make the whole image lumen.
  if (const json* t = in.raw("threshold"); t && !(t->is_number() && t->get<double>() > 0.0 && t->get<double>() <= 1.0))
    in.fail("threshold", "a grey level in (0, 1] of white in " + m.file, *t);
  m.threshold = in.number("threshold", m.threshold, 0.0, 1.0);
  const std::string pixel_hash = in.text("pixel_hash", "");
  // As `vascsim vessels` writes it: the image's 64-bit FNV-1a hash in 16 hex digits. Anything
  // else is a typo, not an image that changed.
  if (!pixel_hash.empty() &&
      (pixel_hash.size() != 16 || pixel_hash.find_first_not_of("0123456789abcdef") != std::string::npos))
    in.fail("pixel_hash", "16 lower-case hex digits, the hash vascsim vessels writes of " + m.file + " (or no pixel_hash)",
            pixel_hash);
  in.finish();
  // A relative path is relative to the scene file, so a scene and its mask move together.
  const std::filesystem::path file(m.file);
  m.resolved = file.is_absolute() ? m.file : (std::filesystem::path(in.file()).parent_path() / file).string();
  return pixel_hash;
}

}  // namespace

void read_vessels(FieldReader& in, VesselsSpec& out) {
  if (in.has("mask")) {
    out.from_mask = true;
    for (const char* key : {"nodes", "segments", "route"})
      if (in.has(key)) in.fail(key, "no graph beside a \"mask\" (the image is the whole network)", *in.raw(key));
    FieldReader mask = in.object("mask");
    const std::string pixel_hash = read_mask(mask, out.mask);
    for (const char* key : {"start", "goal"})
      if (!in.has(key)) in.fail(key, "a point [x, y] (m) inside the mask's lumen", json());
    out.mask.start = in.vec2("start", out.mask.start, kMaxCoordinate);
    out.mask.goal = in.vec2("goal", out.mask.goal, kMaxCoordinate);
    in.finish();
    out.mask.grey = load_mask_pixels(out.mask, in.file(), in.pointer_of("mask") + "/file");
    // As a graph's goal must be another node: a goal on the start made a path of length 0, an
    // inlet with no direction and a run that crumpled the rod against the image's edge (exit 0).
    if ((out.mask.goal - out.mask.start).norm() < 2.0 * out.mask.pixel_size)
      in.fail("goal", "a point at least two pixels of " + out.mask.resolved + " (" + format_number(2.0 * out.mask.pixel_size) +
                          " m) from the start", to_json(out.mask.goal));
    if (!pixel_hash.empty() && pixel_hash != out.mask.pixel_hash)
      mask.fail("pixel_hash", "the hash of " + out.mask.resolved + " as it is now, " + out.mask.pixel_hash +
                                  " (the image changed since this scene was written)", pixel_hash);
    return;
  }
  const json* nodes = in.raw("nodes");
  if (!nodes || !nodes->is_object() || nodes->empty())
    in.fail("nodes", "an object of named points, e.g. {\"inlet\": [1.0, 0.5]}", nodes ? *nodes : json());
  for (const auto& [name, p] : nodes->items()) {
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
      FieldReader(*nodes, in.file(), in.pointer_of("nodes")).fail(name, "a point [x, y] (m)", p);
    out.nodes.push_back({name, Vec2(p[0].get<double>(), p[1].get<double>())});
    if (!within_bounds(out.nodes.back().position))
      FieldReader(*nodes, in.file(), in.pointer_of("nodes")).fail(name, kPointWithinBounds, p);
  }
  out.segments = read_list<VesselSegmentSpec>(in, "segments", "an array of {\"from\", \"to\", \"radius\"} segments", read_segment);
  if (out.segments.empty()) in.fail("segments", "at least one segment", in.has("segments") ? *in.raw("segments") : json());
  out.start = in.text("start", "");
  out.goal = in.text("goal", "");
  if (out.start.empty()) in.fail("start", "the name of the inlet node", in.has("start") ? *in.raw("start") : json());
  if (out.goal.empty()) in.fail("goal", "the name of the goal node", in.has("goal") ? *in.raw("goal") : json());
  if (const json* route = in.raw("route")) {
    if (!route->is_array() || route->size() < 2) in.fail("route", "an array of at least two node names", *route);
    for (std::size_t k = 0; k < route->size(); ++k) {
      const json& n = route->at(k);
      if (!n.is_string()) in.fail("route/" + std::to_string(k), "a node name", n);
      out.route.push_back(n.get<std::string>());
    }
  }
  in.finish();
}

json write_vessels(const VesselsSpec& spec) {
  json j;
  if (spec.from_mask) {
    j["mask"] = {{"file", spec.mask.file}, {"pixel_size", spec.mask.pixel_size}, {"threshold", spec.mask.threshold}};
    if (!spec.mask.pixel_hash.empty()) j["mask"]["pixel_hash"] = spec.mask.pixel_hash;
    j["start"] = to_json(spec.mask.start);
    j["goal"] = to_json(spec.mask.goal);
    return j;
  }
  json nodes = json::object();
  for (const auto& n : spec.nodes) nodes[n.name] = to_json(n.position);
  j["nodes"] = nodes;
  json segments = json::array();
  for (const auto& s : spec.segments) {
    json seg = {{"from", s.from}, {"to", s.to}, {"radius", s.radius}};
    if (!s.via.empty()) {
      json via = json::array();
      for (const auto& p : s.via) via.push_back(to_json(p));
      seg["via"] = via;
    }
    for (const auto& st : s.stenoses) seg["stenoses"].push_back({{"at", st.at}, {"length", st.length}, {"fraction", st.fraction}});
    for (const auto& a : s.aneurysms)
      seg["aneurysms"].push_back({{"at", a.at}, {"side", a.left ? "left" : "right"}, {"radius", a.radius}, {"neck", a.neck}});
    segments.push_back(seg);
  }
  j["segments"] = segments;
  j["start"] = spec.start;
  j["goal"] = spec.goal;
  if (!spec.route.empty()) j["route"] = spec.route;
  return j;
}

}  // namespace vascsim::io

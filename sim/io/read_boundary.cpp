#include "sim/io/scene_sections.h"

namespace vascsim::io {

using nlohmann::json;

namespace {

const char* clamp_name(ClampKind c) {
  switch (c) {
    case ClampKind::kFirstEdge: return "first_edge";
    case ClampKind::kCentred: return "centred";
    default: return "none";
  }
}

// Node indices are checked against the rod's node count when the Model is built.
int read_node(FieldReader& in, const std::string& key, int fallback) {
  return static_cast<int>(in.integer(key, fallback, -1000000, 999999));
}

}  // namespace

void read_boundary(FieldReader& in, BoundarySpec& out) {
  const std::string clamp = in.choice("clamp", clamp_name(out.clamp), {"none", "first_edge", "centred"});
  out.clamp = clamp == "first_edge" ? ClampKind::kFirstEdge : clamp == "centred" ? ClampKind::kCentred : ClampKind::kNone;
  if (const json* pinned = in.raw("pinned")) {
    if (!pinned->is_array()) in.fail("pinned", "an array of node indices", *pinned);
    out.pinned.clear();
    for (std::size_t i = 0; i < pinned->size(); ++i) {
      const json& v = (*pinned)[i];
      // Compared in the value's own type: an unsigned 2^64 - 1 read as signed would be -1, the tip.
      const bool index = v.is_number_unsigned() ? v.get<unsigned long long>() <= 1000000u
                         : v.is_number_integer() && v.get<long long>() >= -1000000 && v.get<long long>() <= 1000000;
      if (!index) in.fail("pinned/" + std::to_string(i), "an integer node index in [-1000000, 1000000]", v);
      out.pinned.push_back(v.get<int>());
    }
  }
  if (const json* list = in.raw("supports")) {
    if (!list->is_array()) in.fail("supports", "an array of objects", *list);
    out.supports.clear();
    for (std::size_t i = 0; i < list->size(); ++i) {
      FieldReader item = in.nested((*list)[i], "supports/" + std::to_string(i));
      SupportSpec support;
      support.node = read_node(item, "node", support.node);
      support.axis = item.choice("hold", "y", {"x", "y"}) == "x" ? SupportAxis::kX : SupportAxis::kY;
      item.finish();
      out.supports.push_back(support);
    }
  }
  if (const json* list = in.raw("prescribed")) {
    if (!list->is_array()) in.fail("prescribed", "an array of objects", *list);
    out.prescribed.clear();
    for (std::size_t i = 0; i < list->size(); ++i) {
      FieldReader item = in.nested((*list)[i], "prescribed/" + std::to_string(i));
      PrescribedMotionSpec p;
      p.node = read_node(item, "node", p.node);
      p.velocity = item.vec2("velocity", p.velocity, kMaxSpeed);
      p.amplitude = item.vec2("amplitude", p.amplitude, kMaxCoordinate);
      p.frequency = item.number("frequency", p.frequency, 0.0, 1e6);
      item.finish();
      out.prescribed.push_back(p);
    }
  }
  in.finish();
}

json write_boundary(const BoundarySpec& spec) {
  json prescribed = json::array();
  for (const auto& p : spec.prescribed)
    prescribed.push_back({{"node", p.node},
                          {"velocity", to_json(p.velocity)},
                          {"amplitude", to_json(p.amplitude)},
                          {"frequency", p.frequency}});
  json supports = json::array();
  for (const auto& s : spec.supports) supports.push_back({{"node", s.node}, {"hold", s.axis == SupportAxis::kX ? "x" : "y"}});
  return {{"clamp", clamp_name(spec.clamp)}, {"pinned", spec.pinned}, {"supports", supports}, {"prescribed", prescribed}};
}

}  // namespace vascsim::io

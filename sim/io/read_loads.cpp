#include "sim/io/scene_sections.h"

namespace vascsim::io {

using nlohmann::json;

namespace {

const char* profile_name(LoadProfile p) {
  switch (p) {
    case LoadProfile::kRamp: return "ramp";
    case LoadProfile::kSine: return "sine";
    default: return "constant";
  }
}

}  // namespace

void read_loads(FieldReader& in, LoadSpec& out) {
  {
    FieldReader g = in.object("gravity");
    out.gravity.enabled = g.boolean("enabled", out.gravity.enabled);
    out.gravity.acceleration = g.vec2("acceleration", out.gravity.acceleration, kMaxAcceleration);
    g.finish();
  }
  {
    FieldReader d = in.object("damping");
    out.damping.enabled = d.boolean("enabled", out.damping.enabled);
    out.damping.coefficient = d.number("coefficient", out.damping.coefficient, 0.0, 1e9);
    d.finish();
  }
  {
    FieldReader d = in.object("drag");
    out.drag.enabled = d.boolean("enabled", out.drag.enabled);
    out.drag.fluid_density = d.number("fluid_density", out.drag.fluid_density, 0.0, 1e5);
    out.drag.drag_coefficient = d.number("drag_coefficient", out.drag.drag_coefficient, 0.0, 1e3);
    const std::string area = d.choice("area", out.drag.area == DragArea::kNodes ? "nodes" : "tip", {"nodes", "tip"});
    out.drag.area = area == "tip" ? DragArea::kTipFrontal : DragArea::kNodes;
    // The paper's frontal tip drag has one coefficient; a second one there would be silently unused.
    if (out.drag.area == DragArea::kTipFrontal && d.has("tangential_coefficient"))
      d.fail("tangential_coefficient", "area \"nodes\" for a tangential coefficient (the tip's frontal drag has one)",
             *d.raw("tangential_coefficient"));
    out.drag.tangential_coefficient = d.number("tangential_coefficient", out.drag.tangential_coefficient, 0.0, 1e3);
    d.finish();
  }
  {
    FieldReader m = in.object("magnet");
    out.magnet.enabled = m.boolean("enabled", out.magnet.enabled);
    out.magnet.moment = m.number("moment", out.magnet.moment, -1e6, 1e6);
    out.magnet.field = m.number("field", out.magnet.field, 0.0, 1e3);
    out.magnet.angle = m.number("angle", out.magnet.angle, -1e3, 1e3);
    out.magnet.ramp_time = m.number("ramp_time", out.magnet.ramp_time, 0.0, 1e7);
    out.magnet.rotation_rate = m.number("rotation_rate", out.magnet.rotation_rate, -1e6, 1e6);
    m.finish();
  }
  if (const json* list = in.raw("bodies")) {
    if (!list->is_array()) in.fail("bodies", "an array of objects", *list);
    out.bodies.clear();
    for (std::size_t i = 0; i < list->size(); ++i) {
      FieldReader item = in.nested((*list)[i], "bodies/" + std::to_string(i));
      BodySpec b;
      b.node = static_cast<int>(item.integer("node", b.node, -1000000, 999999));
      b.mass = item.number("mass", b.mass, 0.0, 1e6);
      b.linear_drag = item.number("linear_drag", b.linear_drag, 0.0, 1e9);
      b.quadratic_drag = item.number("quadratic_drag", b.quadratic_drag, 0.0, 1e9);
      item.finish();
      out.bodies.push_back(b);
    }
  }
  if (const json* list = in.raw("point")) {
    if (!list->is_array()) in.fail("point", "an array of objects", *list);
    out.point_loads.clear();
    for (std::size_t i = 0; i < list->size(); ++i) {
      FieldReader item = in.nested((*list)[i], "point/" + std::to_string(i));
      PointLoadSpec p;
      p.node = static_cast<int>(item.integer("node", p.node, -1000000, 999999));
      p.force = item.vec2("force", p.force, kMaxForce);
      p.moment = item.number("moment", p.moment, -1e9, 1e9);
      const std::string profile = item.choice("profile", profile_name(p.profile), {"constant", "ramp", "sine"});
      p.profile = profile == "ramp" ? LoadProfile::kRamp : profile == "sine" ? LoadProfile::kSine : LoadProfile::kConstant;
      p.ramp_time = item.positive("ramp_time", p.ramp_time, 1e7);
      p.frequency = item.number("frequency", p.frequency, 0.0, 1e6);
      p.phase = item.number("phase", p.phase, -1e3, 1e3);
      item.finish();
      out.point_loads.push_back(p);
    }
  }
  in.finish();
}

json write_loads(const LoadSpec& spec) {
  json points = json::array();
  for (const auto& p : spec.point_loads)
    points.push_back({{"node", p.node},
                      {"force", to_json(p.force)},
                      {"moment", p.moment},
                      {"profile", profile_name(p.profile)},
                      {"ramp_time", p.ramp_time},
                      {"frequency", p.frequency},
                      {"phase", p.phase}});
  json bodies = json::array();
  for (const auto& b : spec.bodies)
    bodies.push_back({{"node", b.node}, {"mass", b.mass}, {"linear_drag", b.linear_drag}, {"quadratic_drag", b.quadratic_drag}});
  json drag = {{"enabled", spec.drag.enabled},
               {"fluid_density", spec.drag.fluid_density},
               {"drag_coefficient", spec.drag.drag_coefficient},
               {"area", spec.drag.area == DragArea::kNodes ? "nodes" : "tip"}};
  if (spec.drag.area == DragArea::kNodes) drag["tangential_coefficient"] = spec.drag.tangential_coefficient;
  return {{"gravity", {{"enabled", spec.gravity.enabled}, {"acceleration", to_json(spec.gravity.acceleration)}}},
          {"damping", {{"enabled", spec.damping.enabled}, {"coefficient", spec.damping.coefficient}}},
          {"drag", drag},
          {"magnet",
           {{"enabled", spec.magnet.enabled},
            {"moment", spec.magnet.moment},
            {"field", spec.magnet.field},
            {"angle", spec.magnet.angle},
            {"ramp_time", spec.magnet.ramp_time},
            {"rotation_rate", spec.magnet.rotation_rate}}},
          {"bodies", bodies},
          {"point", points}};
}

}  // namespace vascsim::io

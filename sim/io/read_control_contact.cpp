#include <cmath>
#include <limits>

#include "sim/io/scene_sections.h"

namespace vascsim::io {

using nlohmann::json;

const char* actuation_mode_name(ActuationMode m) {
  switch (m) {
    case ActuationMode::kNone: return "none";
    case ActuationMode::kKinematic: return "kinematic";
    case ActuationMode::kField: return "field";
    default: return "force";
  }
}

namespace {

const char* contact_name(ContactMode m) {
  switch (m) {
    case ContactMode::kNone: return "none";
    case ContactMode::kPaper: return "paper";
    default: return "implicit";
  }
}

// control.advance: {"speed": v, "start": t0, "stop": t1} (fed at v from t0 to t1), or
// {"points": [[t, s], ...]} (the fed length s at times t, linear between them).
void read_advance(FieldReader& control, AdvanceSpec& out) {
  FieldReader in = control.object("advance");
  out.points.clear();
  if (in.has("points")) {
    for (const char* key : {"speed", "start", "stop"})
      if (in.has(key)) in.fail(key, "either \"points\" or \"speed\", \"start\" and \"stop\", not both", *in.raw(key));
    const json& list = *in.raw("points");
    if (!list.is_array() || list.size() < 2 || list.size() > 100000) in.fail("points", "an array of 2 to 100000 [t, s] pairs", list);
    for (std::size_t i = 0; i < list.size(); ++i) {
      const json& p = list[i];
      const bool pair = p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number();
      const double t = pair ? p[0].get<double>() : NAN, s = pair ? p[1].get<double>() : NAN;
      if (!pair || !(t >= 0.0 && t <= 1e7) || !(std::abs(s) <= 1e3) || (i > 0 && !(t > out.points.back().first)))
        in.fail("points/" + std::to_string(i),
                "[t, s]: t in s, >= 0 and after the previous point's, s the fed length in m (|s| <= 1000)", p);
      // The rod starts where the scene places it: a first s other than 0 was read as a length fed
      // before the run and quietly subtracted (points (0.1, 0.05), (0.3, 0.1) fed 0.05 m, not 0.1).
      if (i == 0 && s != 0.0)
        in.fail("points/0", "[t, 0]: the fed length is 0 at the first point (the rod starts where the scene places it)", p);
      out.points.emplace_back(t, s);
    }
  } else {
    const double speed = in.number("speed", 0.01, -100.0, 100.0);
    const double start = in.number("start", 0.0, 0.0, 1e7);
    const double stop = in.number("stop", start + 1.0, 0.0, 1e7);
    if (!(stop > start)) in.fail("stop", "a time after \"start\"", *in.raw("stop"));
    out.points = {{start, 0.0}, {stop, speed * (stop - start)}};
  }
  in.finish();
}

}  // namespace

void read_control(FieldReader& in, ControlSpec& out) {
  const std::string mode = in.choice("mode", actuation_mode_name(out.mode), {"none", "force", "kinematic", "field"});
  out.mode = mode == "none"        ? ActuationMode::kNone
             : mode == "kinematic" ? ActuationMode::kKinematic
             : mode == "field"     ? ActuationMode::kField
                                   : ActuationMode::kForce;
  if (in.has("advance")) read_advance(in, out.advance);
  // Kinematic mode's gains mean other things than the force modes' N/m and N s/m, so they have
  // their own defaults: Kp 0.5, half the position error corrected per step (the force modes' 4
  // was refused as out of [0, 1], a value the user never wrote; with 0.5 maze_default reaches
  // its goal with a tip error of 0.05 mm RMS), and Kd none (a lag in s: the force modes' 0.4
  // would slow the imposed tip by a time constant of a quarter second).
  const bool kinematic = out.mode == ActuationMode::kKinematic;
  out.kp = in.number("kp", kinematic && !in.has("kp") ? 0.5 : out.kp, 0.0, 1e9);
  out.kd = in.number("kd", kinematic && !in.has("kd") ? 0.0 : out.kd, 0.0, 1e9);
  if (out.mode == ActuationMode::kKinematic && out.kp > 1.0)
    in.fail("kp", "a number in [0, 1] in kinematic mode (the command is the reference plus Kp times the position error)",
            json(out.kp));
  out.actuated_nodes = static_cast<int>(in.integer("actuated_nodes", out.actuated_nodes, 1, 3));
  out.magnet_moment = in.number("magnet_moment", out.magnet_moment, 0.0, 1e6);
  out.field_strength = in.number("field_strength", out.field_strength, 0.0, 100.0);
  out.lead_time = in.number("lead_time", out.lead_time, 0.0, 1e6);
  auto d = in.object("disturbance");
  const std::string kind = d.choice("kind", out.disturbance.kind == DisturbanceKind::kPosition ? "position" : "force",
                                    {"force", "position"});
  out.disturbance.kind = kind == "position" ? DisturbanceKind::kPosition : DisturbanceKind::kForce;
  if (out.disturbance.kind == DisturbanceKind::kPosition && out.mode != ActuationMode::kKinematic)
    d.fail("kind", "\"force\" in " + mode + " mode (\"position\" offsets the tip that kinematic mode imposes; "
                   "no other mode imposes one)", json(kind));
  out.disturbance.amplitude = d.number("amplitude", out.disturbance.amplitude, 0.0, 1e6);
  out.disturbance.omega = d.number("omega", out.disturbance.omega, 0.0, 1e6);
  const Vec2 direction = d.vec2("direction", out.disturbance.direction);
  if (direction.isZero(0.0)) d.fail("direction", "a non-zero vector [x, y]", to_json(direction));
  // Normalised (stably: [1e200, 1e200] has no finite plain norm, [1e-200, 1e-200] a zero one),
  // but a vector already of unit length (to rounding) is kept as written: dividing it by its norm
  // can move its last bit, and the canonical text a log stores must read back to itself.
  out.disturbance.direction = std::abs(direction.norm() - 1.0) <= 4 * std::numeric_limits<double>::epsilon()
                                  ? direction
                                  : direction.stableNormalized();
  d.finish();
  in.finish();
}

json write_control(const ControlSpec& spec) {
  json out = {{"mode", actuation_mode_name(spec.mode)},
          {"kp", spec.kp},
          {"kd", spec.kd},
          {"actuated_nodes", spec.actuated_nodes},
          {"magnet_moment", spec.magnet_moment},
          {"field_strength", spec.field_strength},
          {"lead_time", spec.lead_time},
          {"disturbance",
           {{"kind", spec.disturbance.kind == DisturbanceKind::kPosition ? "position" : "force"},
            {"amplitude", spec.disturbance.amplitude},
            {"omega", spec.disturbance.omega},
            {"direction", to_json(spec.disturbance.direction)}}}};
  if (spec.advance.enabled()) {
    json points = json::array();
    for (const auto& [t, s] : spec.advance.points) points.push_back({t, s});
    out["advance"] = {{"points", points}};
  }
  return out;
}

void read_contact(FieldReader& in, ContactSpec& out) {
  const std::string mode = in.choice("mode", contact_name(out.mode), {"implicit", "paper", "none"});
  out.mode = mode == "paper" ? ContactMode::kPaper : mode == "none" ? ContactMode::kNone : ContactMode::kImplicit;
  out.activation_distance = in.number("activation_distance", out.activation_distance, 0.0, 1.0);
  out.stiffness = in.number("stiffness", out.stiffness, 0.0, 1e9);
  out.friction = in.number("friction", out.friction, 0.0, 10.0);
  out.slip_velocity = in.positive("slip_velocity", out.slip_velocity, 1e3);
  out.paper_gain = in.positive("paper_gain", out.paper_gain, 1e12);
  out.paper_iterations = static_cast<int>(in.integer("paper_iterations", out.paper_iterations, 1, 100000));
  out.self = in.boolean("self", out.self);
  in.finish();
}

json write_contact(const ContactSpec& spec) {
  return {{"mode", contact_name(spec.mode)},
          {"activation_distance", spec.activation_distance},
          {"stiffness", spec.stiffness},
          {"friction", spec.friction},
          {"slip_velocity", spec.slip_velocity},
          {"paper_gain", spec.paper_gain},
          {"paper_iterations", spec.paper_iterations},
          {"self", spec.self}};
}

}  // namespace vascsim::io

#include "sim/scene/unused_fields.h"

#include <initializer_list>
#include <string>

namespace vascsim {

namespace {

void add(std::vector<UnusedField>& out, const std::string& section, std::initializer_list<const char*> keys,
         const std::string& why) {
  for (const char* key : keys) out.push_back({section + "/" + key, why});
}

const char* contact_mode_name(ContactMode m) {
  return m == ContactMode::kNone ? "none" : m == ContactMode::kPaper ? "paper" : "implicit";
}

void path_fields(const Scene& s, std::vector<UnusedField>& out) {
  if (!s.has_environment) {
    add(out, "/path", {"solver", "corner_radius", "speed", "ramp_time"},
        "a scene without a maze or vessels has no route to follow");
    return;
  }
  if (s.environment == EnvironmentKind::kVessels)
    add(out, "/path", {"solver"}, "vessel scenes are routed along their graph or mask, not by a maze solver");
  else if (s.maze.explicit_walls && s.path.solver == PathSolver::kWallFollower)
    add(out, "/path", {"solver"}, "explicit walls are always routed breadth-first (\"bfs\") on their grid");
}

void control_fields(const Scene& s, std::vector<UnusedField>& out) {
  if (!s.has_environment) return;  // the reader refuses a control section there
  const ControlSpec& c = s.control;
  if (c.mode == ActuationMode::kNone)
    add(out, "/control", {"kp", "kd", "actuated_nodes"}, "control.mode is \"none\" (no tip actuation)");
  if (c.mode != ActuationMode::kField)
    add(out, "/control", {"magnet_moment", "field_strength"}, "they set the tip magnet of control.mode \"field\"");
  if (c.disturbance.amplitude == 0.0)
    add(out, "/control/disturbance", {"omega", "direction"}, "control.disturbance.amplitude is 0 (switched off)");
  // The kinematic tip follows its command exactly: a force on it is taken up by the motion
  // imposed on it and moves nothing.
  else if (c.mode == ActuationMode::kKinematic && c.disturbance.kind == DisturbanceKind::kForce)
    out.push_back({"/control/disturbance",
                   "a disturbance of kind \"force\" acts on the tip, whose motion control.mode \"kinematic\" imposes "
                   "(kind \"position\" disturbs the command)"});
}

void contact_fields(const Scene& s, std::vector<UnusedField>& out) {
  const ContactSpec& c = s.contact;
  // Self-contact is a barrier too: it takes its reach and stiffness from the same two fields.
  const auto barrier_unused = [&](const std::string& why) {
    if (!c.self) add(out, "/contact", {"activation_distance", "stiffness"}, why + "; contact.self is off");
  };
  if (!s.has_environment) {
    const std::string why = "a scene without a maze or vessels has no walls";
    add(out, "/contact", {"mode", "friction", "slip_velocity", "paper_gain", "paper_iterations"}, why);
    barrier_unused(why);
    return;
  }
  const std::string mode = std::string("contact.mode is \"") + contact_mode_name(c.mode) + "\"";
  if (c.mode != ContactMode::kImplicit) {
    const std::string why = mode + " (the implicit barrier and its friction are off; the paper's penalty has neither)";
    add(out, "/contact", {"friction", "slip_velocity"}, why);
    barrier_unused(why);
  } else if (c.friction == 0.0)
    add(out, "/contact", {"slip_velocity"}, "contact.friction is 0 (it regularises friction)");
  if (c.mode != ContactMode::kPaper)
    add(out, "/contact", {"paper_gain", "paper_iterations"}, mode + " (they set the paper's penalty)");
}

void boundary_fields(const Scene& s, std::vector<UnusedField>& out) {
  for (std::size_t i = 0; i < s.boundary.prescribed.size(); ++i)
    if (s.boundary.prescribed[i].amplitude.isZero(0.0))
      add(out, "/boundary/prescribed/" + std::to_string(i), {"frequency"}, "its amplitude is [0, 0] (no oscillation)");
}

void loads_fields(const Scene& s, std::vector<UnusedField>& out) {
  for (std::size_t i = 0; i < s.loads.point_loads.size(); ++i) {
    const std::string at = "/loads/point/" + std::to_string(i);
    const LoadProfile p = s.loads.point_loads[i].profile;
    if (p != LoadProfile::kRamp) add(out, at, {"ramp_time"}, "its profile is not \"ramp\"");
    if (p != LoadProfile::kSine) add(out, at, {"frequency", "phase"}, "its profile is not \"sine\"");
  }
}

void solver_fields(const Scene& s, std::vector<UnusedField>& out) {
  const SolverSpec& v = s.solver;
  if (v.mode == SolveMode::kStatic) {
    const std::string why = "solver.mode is \"static\" (an equilibrium has no time steps)";
    add(out, "/solver", {"scheme", "dt", "adaptive", "rtol", "atol_position", "atol_velocity", "dt_min", "dt_floor",
                         "dt_mean_min", "mean_burst", "dt_max", "newton_stop_share"},
        why);
    add(out, "/run", {"duration", "output_interval"}, why + ": the log holds the start and the equilibrium");
    return;
  }
  add(out, "/solver", {"load_steps", "stable_branch"}, "solver.mode is \"dynamic\" (they set the static solve)");
  if (v.adaptive != StepControl::kError) {
    const std::string why = std::string("solver.adaptive is \"") + (v.adaptive == StepControl::kRetry ? "retry" : "off") +
                            "\" (a fixed step; they set error control)";
    add(out, "/solver", {"rtol", "atol_position", "atol_velocity", "dt_min", "dt_floor", "dt_mean_min", "mean_burst",
                         "dt_max", "newton_stop_share"},
        why);
  } else if (v.dt_mean_min == 0.0) {
    add(out, "/solver", {"mean_burst"}, "solver.dt_mean_min is 0 (it is the credit below that floor)");
  }
  if (v.adaptive == StepControl::kOff)
    add(out, "/solver", {"max_halvings"}, "solver.adaptive is \"off\" (a failed step ends the run)");
}

}  // namespace

std::vector<UnusedField> unused_fields(const Scene& scene) {
  std::vector<UnusedField> out;
  path_fields(scene, out);
  solver_fields(scene, out);  // also the run section's fields in static mode
  control_fields(scene, out);
  contact_fields(scene, out);
  boundary_fields(scene, out);
  loads_fields(scene, out);
  return out;
}

}  // namespace vascsim

#include "sim/io/run_summary.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "sim/io/json_fields.h"
#include "sim/io/provenance.h"
#include "sim/io/scene_reader.h"
#include "sim/io/scene_sections.h"

namespace vascsim {

using nlohmann::json;

namespace {

// JSON has no NaN or infinity: unknown values are null.
json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

}  // namespace

std::string run_summary_json(const Scene& scene, const Run& run) {
  const RunStatistics& s = run.statistics();
  json j;
  j["format"] = "vascsim-summary/1";
  j["scene"] = scene.name;
  const Provenance p = provenance_of(scene_to_json(scene));
  j["provenance"] = {{"vascsim_version", p.version}, {"commit", p.commit}, {"scene_hash", p.scene_hash}};
  j["ok"] = !s.failed;
  j["failure"] = s.failed ? json(s.failure) : json(nullptr);
  // Stopped by the user or a job scheduler rather than failed by the physics: a sweep runs it again.
  j["stopped_by"] = s.stopped_by.empty() ? json(nullptr) : json(s.stopped_by);
  const bool is_static = scene.solver.mode == SolveMode::kStatic;
  j["mode"] = is_static ? "static" : "dynamic";  // static: steps are load increments, time the load scale
  j["steps"] = s.steps;
  j["rejected_steps"] = s.rejected_steps;
  if (!is_static) {
    // The step sizes taken; with error control also the rejections and the largest error kept.
    j["step_size"] = {{"min", s.steps ? json(s.dt_min) : json(nullptr)},
                      {"max", s.steps ? json(s.dt_max) : json(nullptr)},
                      {"mean", s.steps ? json(s.simulated_time / s.steps) : json(nullptr)}};
    if (scene.solver.adaptive == StepControl::kError)
      j["error_control"] = {{"rejected_steps", s.error_rejected_steps},
                            {"error_max", s.error_max},
                            {"kept_over_tolerance", s.warnings.step_over_tolerance.count},
                            {"error_max_at_floor", s.error_max_at_floor},
                            {"steps_cut_to_frames", s.steps_cut_to_frames}};
  }
  j["newton_iterations"] = {{"total", s.newton_iterations},
                            {"mean", s.steps ? static_cast<double>(s.newton_iterations) / s.steps : 0.0},
                            {"max", s.newton_iterations_max},
                            {"all_attempts", s.newton_iterations_all}};
  j["frames"] = s.frames;
  j["axial_strain_max"] = s.axial_strain_max;
  j["simulated_time"] = s.simulated_time;
  j["wall_time"] = s.wall_time;
  j["real_time_factor"] = s.wall_time > 0 && !is_static ? json(s.simulated_time / s.wall_time) : json(nullptr);
  // Fields the scene file gave that its configuration does not use (the run warned of them).
  j["unused_fields"] = json::array();
  for (const UnusedField& u : scene.unused_given) j["unused_fields"].push_back({{"pointer", u.pointer}, {"why", u.why}});
  auto warning = [](const WarningCount& w) { return json{{"count", w.count}, {"first_time", number(w.first_time)}}; };
  j["warnings"] = {{"newton_round_off_stop", warning(s.warnings.newton_round_off)},
                   {"step_retried", warning(s.warnings.step_retried)},
                   {"step_over_tolerance", warning(s.warnings.step_over_tolerance)},
                   {"paper_contact_iteration_cap", warning(s.warnings.paper_contact_cap)},
                   {"unresolved_step", warning(s.warnings.unresolved_step)},
                   {"unstable_equilibrium", warning(s.warnings.unstable_equilibrium)},
                   {"left_unstable_equilibrium", warning(s.warnings.left_unstable)},
                   {"load_path_jumped", warning(s.warnings.load_path_jumped)},
                   {"stability_undecided", warning(s.warnings.stability_undecided)},
                   {"large_axial_strain", warning(s.warnings.large_axial_strain)}};
  const State& state = run.state();
  json positions = json::array(), velocities = json::array();
  for (Eigen::Index i = 0; i < state.x.size(); i += 2) {
    positions.push_back({number(state.x[i]), number(state.x[i + 1])});
    velocities.push_back({number(state.v[i]), number(state.v[i + 1])});
  }
  j["final_state"] = {{"t", state.t}, {"positions", positions}, {"velocities", velocities}};
  if (run.navigation()) {
    json contact_time = json::array();
    for (double t : s.contact_time) contact_time.push_back(t);
    // A rod only pushed from its root has no tip error: the distance to a target that nothing
    // steered towards would read as a tracking error (its frame log leaves tip/error out too).
    const bool steered = scene.control.mode != ActuationMode::kNone;
    const json no_value(nullptr);
    j["navigation"] = {{"control_mode", io::actuation_mode_name(scene.control.mode)},
                       {"goal_reached", s.goal_reached},
                       {"goal_time", number(s.goal_time)},
                       {"tip_error_rms", steered ? json(s.tip_error_rms) : no_value},
                       {"tip_error_max", steered ? json(s.tip_error_max) : no_value},
                       {"actuation_force_max", s.actuation_force_max},
                       {"actuation_force_mean", s.actuation_force_mean},
                       {"contact_force_max", s.contact_force_max},
                       {"min_gap", number(s.min_gap)},
                       {"max_penetration", s.max_penetration},
                       {"contact_time_per_node", contact_time},
                       {"paper_contact_iterations_max", s.paper_contact_iterations_max},
                       {"trajectory_duration", run.navigation()->trajectory->duration()}};
    if (scene.control.advance.enabled())
      j["navigation"]["advance"] = {{"fed_length", scene.control.advance.fed_length(s.simulated_time)},
                                    {"feed_force_max", s.feed_force_max},
                                    {"feed_force_mean", s.feed_force_mean}};
  }
  return j.dump(2, ' ', false, decltype(j)::error_handler_t::replace) + "\n";  // a scene file name need not be UTF-8
}

}  // namespace vascsim

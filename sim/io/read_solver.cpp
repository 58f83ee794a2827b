#include "sim/io/scene_sections.h"

namespace vascsim::io {

using nlohmann::json;

namespace {

const char* step_control_name(StepControl c) {
  return c == StepControl::kError ? "error" : c == StepControl::kRetry ? "retry" : "off";
}

// "error", "retry" or "off"; true and false are the older spelling (before error control) of
// "retry" and "off", kept so that the scenes stored in older logs read as they ran.
StepControl read_step_control(FieldReader& in, StepControl fallback) {
  if (const nlohmann::json* raw = in.raw("adaptive"); raw && raw->is_boolean())
    return in.boolean("adaptive", false) ? StepControl::kRetry : StepControl::kOff;
  const std::string name = in.choice("adaptive", step_control_name(fallback), {"error", "retry", "off"});
  return name == "error" ? StepControl::kError : name == "retry" ? StepControl::kRetry : StepControl::kOff;
}

}  // namespace

// The preset is read first and fills the scheme, the step control, dt and the tolerances; fields
// given explicitly override it. The writer records the
// resolved values and the preset, so reading its output is stable.
void read_solver(FieldReader& in, SolverSpec& out) {
  const std::string mode = in.choice("mode", out.mode == SolveMode::kStatic ? "static" : "dynamic", {"dynamic", "static"});
  out.mode = mode == "static" ? SolveMode::kStatic : SolveMode::kDynamic;
  const std::string preset = in.choice("preset", out.preset, {"fast", "balanced", "accurate"});
  apply_solver_preset(preset, out);
  const std::string scheme =
      in.choice("scheme", out.scheme == Scheme::kBdf2 ? "bdf2" : "backward_euler", {"backward_euler", "bdf2"});
  out.scheme = scheme == "bdf2" ? Scheme::kBdf2 : Scheme::kBackwardEuler;
  // A scene that names its dt and not its step control means that step: fixed, as before presets
  // chose steps by error.
  const bool fixed_dt = in.raw("dt") && !in.raw("adaptive");
  out.adaptive = read_step_control(in, fixed_dt ? StepControl::kRetry : out.adaptive);
  // Below a nanosecond the inertia term M/h^2 swamps the stiffness (and overflows past ~1e-150 s):
  // such a dt is a typo, refused here rather than failing the run as a singular Newton matrix.
  out.dt = in.number("dt", out.dt, 1e-9, 10.0);
  out.rtol = in.number("rtol", out.rtol, 0.0, 1.0);
  out.atol_position = in.number("atol_position", out.atol_position, 0.0, 1.0);
  out.atol_velocity = in.number("atol_velocity", out.atol_velocity, 0.0, 100.0);
  if (out.adaptive == StepControl::kError && !(out.rtol > 0 || out.atol_position > 0 || out.atol_velocity > 0))
    in.fail("rtol", "a positive rtol, atol_position or atol_velocity for \"adaptive\": \"error\"",
            in.raw("rtol") ? *in.raw("rtol") : nlohmann::json(out.rtol));
  out.dt_max = in.positive("dt_max", out.dt_max, 10.0);
  out.dt_min = in.positive("dt_min", out.dt_min, out.dt_max);
  out.dt_floor = in.number("dt_floor", out.dt_floor, 0.0, out.dt_max);
  out.dt_mean_min = in.number("dt_mean_min", out.dt_mean_min, 0.0, out.dt_max);
  // dt_min is where an error-controlled run gives up; a first step or a floor below it took steps
  // the run could not have chosen, and failed on the first rejection "at the smallest step".
  if (out.adaptive == StepControl::kError) {
    const auto got = [&](const char* key, double value) { return in.raw(key) ? *in.raw(key) : nlohmann::json(value); };
    if (out.dt < out.dt_min)
      in.fail("dt_min", "at most the first step, dt = " + format_number(out.dt) + " s", got("dt_min", out.dt_min));
    if (out.dt_floor > 0.0 && out.dt_floor < out.dt_min)
      in.fail("dt_min", "at most the floor, dt_floor = " + format_number(out.dt_floor) + " s", got("dt_min", out.dt_min));
  }
  out.mean_burst = in.number("mean_burst", out.mean_burst, 0.0, 1e9);
  out.newton_stop_share = in.number("newton_stop_share", out.newton_stop_share, 0.0, 1.0);
  out.rel_tol = in.positive("rel_tol", out.rel_tol, 1.0);
  out.abs_tol = in.number("abs_tol", out.abs_tol, 0.0, 1e9);
  out.step_tol = in.positive("step_tol", out.step_tol, 1.0);
  out.max_iterations = static_cast<int>(in.integer("max_iterations", out.max_iterations, 1, 1000));
  out.max_halvings = static_cast<int>(in.integer("max_halvings", out.max_halvings, 0, 40));
  out.load_steps = static_cast<int>(in.integer("load_steps", out.load_steps, 1, 100000));
  out.stable_branch = in.boolean("stable_branch", out.stable_branch);
  in.finish();
}

json write_solver(const SolverSpec& spec) {
  return {{"mode", spec.mode == SolveMode::kStatic ? "static" : "dynamic"},
          {"preset", spec.preset},
          {"scheme", spec.scheme == Scheme::kBdf2 ? "bdf2" : "backward_euler"},
          {"dt", spec.dt},
          {"rel_tol", spec.rel_tol},
          {"abs_tol", spec.abs_tol},
          {"step_tol", spec.step_tol},
          {"max_iterations", spec.max_iterations},
          {"adaptive", step_control_name(spec.adaptive)},
          {"rtol", spec.rtol},
          {"atol_position", spec.atol_position},
          {"atol_velocity", spec.atol_velocity},
          {"dt_min", spec.dt_min},
          {"dt_floor", spec.dt_floor},
          {"dt_mean_min", spec.dt_mean_min},
          {"mean_burst", spec.mean_burst},
          {"dt_max", spec.dt_max},
          {"newton_stop_share", spec.newton_stop_share},
          {"max_halvings", spec.max_halvings},
          {"load_steps", spec.load_steps},
          {"stable_branch", spec.stable_branch}};
}

}  // namespace vascsim::io

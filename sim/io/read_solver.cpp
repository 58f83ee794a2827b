#include "sim/io/scene_sections.h"

namespace vascsim::io {

using nlohmann::json;

// The preset is read first and fills scheme, dt and rel_tol; fields given explicitly override
// it. The writer records the resolved values and the preset, so reading its output is stable.
void read_solver(FieldReader& in, SolverSpec& out) {
  const std::string mode = in.choice("mode", out.mode == SolveMode::kStatic ? "static" : "dynamic", {"dynamic", "static"});
  out.mode = mode == "static" ? SolveMode::kStatic : SolveMode::kDynamic;
  const std::string preset = in.choice("preset", out.preset, {"fast", "balanced", "accurate"});
  apply_solver_preset(preset, out);
  const std::string scheme =
      in.choice("scheme", out.scheme == Scheme::kBdf2 ? "bdf2" : "backward_euler", {"backward_euler", "bdf2"});
  out.scheme = scheme == "bdf2" ? Scheme::kBdf2 : Scheme::kBackwardEuler;
  out.dt = in.positive("dt", out.dt, 10.0);
  out.rel_tol = in.positive("rel_tol", out.rel_tol, 1.0);
  out.abs_tol = in.number("abs_tol", out.abs_tol, 0.0, 1e9);
  out.step_tol = in.positive("step_tol", out.step_tol, 1.0);
  out.max_iterations = static_cast<int>(in.integer("max_iterations", out.max_iterations, 1, 1000));
  out.adaptive = in.boolean("adaptive", out.adaptive);
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
          {"adaptive", spec.adaptive},
          {"max_halvings", spec.max_halvings},
          {"load_steps", spec.load_steps},
          {"stable_branch", spec.stable_branch}};
}

}  // namespace vascsim::io

// Stability at the extremes (issue 3): time steps from 1e-6 to 1e-1 s, Young's modulus from 1e3
// to 2e11 Pa, 3 to 2000 nodes, a tip load of alpha = 20, a rod starting coiled or folded back on
// itself. Each run must either succeed or stop with a clear message; never NaN or Inf in the
// state, never a hang (every loop in the stepper is capped). Few steps each, to stay lean under
// the sanitizers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "sim/run/compile.h"
#include "sim/run/run.h"
#include "sim/step/model.h"
#include "sim/step/statics.h"
#include "sim/step/stepper.h"
#include "tests/rod_test_scenes.h"

namespace vascsim {
namespace {

Scene loaded_cantilever(int nodes, double alpha) {
  Scene s = test::cantilever(nodes);
  s.solver.mode = SolveMode::kDynamic;
  s.solver.rel_tol = 1e-6;
  const double l = s.rod.length;
  PointLoadSpec tip;
  tip.force = Vec2(0.0, -alpha * test::bending_stiffness(s.rod) / (l * l));
  s.loads.point_loads.push_back(tip);
  return s;
}

// Steps until `steps` succeed or one fails; checks the state stays finite and failures explain.
void run_case(const Scene& scene, double dt, int steps, const char* label) {
  const Model model = *compile(scene);
  State s = initial_state(model);
  Workspace ws(model);
  const Controls controls;
  for (int i = 0; i < steps; ++i) {
    const StepReport r = step(model, s, ws, controls, dt);
    ASSERT_TRUE(s.x.allFinite() && s.v.allFinite()) << label;
    if (!r.ok) {
      EXPECT_FALSE(r.failure.empty()) << label;
      std::printf("[ %s ] stopped cleanly: %s\n", label, r.failure.c_str());
      return;
    }
    EXPECT_LE(r.residual, scene.solver.rel_tol) << label;
  }
}

// The same cases with the default step control (the balanced preset: error control with a
// floor), through a whole run: each ends its short run or stops with a message, never with a
// non-finite frame.
void run_controlled_case(Scene scene, double duration, const char* label) {
  apply_solver_preset("balanced", scene.solver);
  scene.run.duration = duration;
  scene.run.output_interval = duration / 4;
  Run run(compile(scene));
  struct FiniteSink : FrameSink {
    void write(double, const std::vector<double>& values) override {
      for (double v : values) finite = finite && std::isfinite(v);
    }
    bool finite = true;
  } sink;
  const bool ok = run.run(sink);
  EXPECT_TRUE(sink.finite) << label;
  ASSERT_TRUE(run.state().x.allFinite() && run.state().v.allFinite()) << label;
  if (!ok) {
    EXPECT_FALSE(run.statistics().failure.empty()) << label;
    std::printf("[ %s, error control ] stopped cleanly: %s\n", label, run.statistics().failure.c_str());
  } else {
    EXPECT_GE(run.state().t, duration * (1 - 1e-9)) << label;
  }
}

TEST(RodExtremes, EveryCaseUnderErrorControl) {
  run_controlled_case(loaded_cantilever(21, 2.0), 0.05, "alpha 2");
  for (double e : {1e3, 2e11}) {
    Scene s = loaded_cantilever(21, 2.0);
    s.rod.youngs_modulus = e;
    const double l = s.rod.length;
    s.loads.point_loads[0].force = Vec2(0.0, -2.0 * test::bending_stiffness(s.rod) / (l * l));
    run_controlled_case(s, 0.01, e < 1e6 ? "E 1e3" : "E 2e11");
  }
  run_controlled_case(loaded_cantilever(3, 2.0), 0.05, "N 3");
  run_controlled_case(loaded_cantilever(2000, 2.0), 0.004, "N 2000");
  run_controlled_case(loaded_cantilever(41, 20.0), 0.02, "alpha 20");
  Scene coiled;
  coiled.has_environment = false;
  coiled.rod.nodes = 60;
  coiled.shape.initial_curvature = 1.0 / 0.02;
  run_controlled_case(coiled, 0.01, "coiled");
  coiled.shape.initial_curvature = 1e6;
  run_controlled_case(coiled, 0.01, "folded");
}

TEST(RodExtremes, TimeSteps) {
  run_case(loaded_cantilever(21, 2.0), 1e-6, 3, "dt 1e-6");
  run_case(loaded_cantilever(21, 2.0), 1e-1, 5, "dt 1e-1");
}

TEST(RodExtremes, YoungsModulus) {
  for (double e : {1e3, 2e11}) {
    Scene s = loaded_cantilever(21, 2.0);
    s.rod.youngs_modulus = e;  // the load scales with EI: the same alpha
    const double l = s.rod.length;
    s.loads.point_loads[0].force = Vec2(0.0, -2.0 * test::bending_stiffness(s.rod) / (l * l));
    run_case(s, 1e-3, 3, e < 1e6 ? "E 1e3" : "E 2e11");
  }
}

TEST(RodExtremes, NodeCounts) {
  run_case(loaded_cantilever(3, 2.0), 1e-3, 3, "N 3");
  run_case(loaded_cantilever(2000, 2.0), 1e-3, 2, "N 2000");
}

TEST(RodExtremes, LargeStaticLoad) {
  Scene s = loaded_cantilever(41, 20.0);
  s.solver.mode = SolveMode::kStatic;
  const Model model = *compile(s);
  State state = initial_state(model);
  Workspace ws(model);
  const StaticReport r = solve_static(model, state, ws, Controls{});
  ASSERT_TRUE(state.x.allFinite());
  EXPECT_TRUE(r.ok) << r.failure;
  // At alpha = 20 the tip hangs nearly straight down: deflection close to L.
  EXPECT_GT(-state.x[2 * 41 - 1], 0.85 * s.rod.length);
}

TEST(RodExtremes, CoiledAndFoldedStarts) {
  Scene coiled;
  coiled.has_environment = false;
  coiled.rod.nodes = 60;
  coiled.shape.initial_curvature = 1.0 / 0.02;  // about four turns of 2 cm radius, unwinding
  run_case(coiled, 1e-3, 5, "coiled");
  Scene folded = coiled;
  folded.shape.initial_curvature = 1e6;  // every hinge turned by the 0.95 pi cap: a zigzag folded on itself
  run_case(folded, 1e-3, 5, "folded");
}

}  // namespace
}  // namespace vascsim

// A Newton warm start (sim/step/stepper.h, used by the paper contact's re-solves of a step) starts
// Newton at the given positions for an attempt of exactly its dt, and is ignored for any other.
// A cantilever swinging under a tip load: from its own solution Newton has nothing to do, from
// the predictor it needs iterations; a warm start of another dt leaves the step bit for bit as
// without one.
#include <gtest/gtest.h>

#include "sim/run/compile.h"
#include "sim/step/model.h"
#include "sim/step/stepper.h"
#include "tests/rod_test_scenes.h"

namespace vascsim {
namespace {

constexpr double kDt = 2e-3;  // s

struct Stepped {
  StepReport report;
  State state;
};

Stepped step_from(const Model& model, const State& start, const NewtonWarmStart* warm) {
  Workspace ws(model);
  Stepped out{StepReport{}, start};
  out.report = step(model, out.state, ws, Controls{}, kDt, {}, warm);
  return out;
}

Model swinging_cantilever() {
  Scene scene = test::cantilever(21);
  scene.solver.rel_tol = 1e-10;
  PointLoadSpec tip;
  tip.force = Vec2(0.0, -1e-3);  // N: a large swing, so that the predictor is far off
  scene.loads.point_loads.push_back(tip);
  return *compile(scene);
}

TEST(NewtonWarmStart, FromTheStepsOwnSolutionNewtonHasNothingToDo) {
  const Model model = swinging_cantilever();
  const State start = initial_state(model);
  const Stepped cold = step_from(model, start, nullptr);
  ASSERT_TRUE(cold.report.ok) << cold.report.failure;
  EXPECT_GT(cold.report.iterations, 1);
  const NewtonWarmStart warm{cold.state.x, kDt};
  const Stepped hot = step_from(model, start, &warm);
  ASSERT_TRUE(hot.report.ok) << hot.report.failure;
  EXPECT_EQ(hot.report.iterations, 0);
  EXPECT_EQ(hot.state.x, cold.state.x);
}

TEST(NewtonWarmStart, AWarmStartOfAnotherStepIsIgnored) {
  const Model model = swinging_cantilever();
  const State start = initial_state(model);
  const Stepped cold = step_from(model, start, nullptr);
  NewtonWarmStart other{cold.state.x, 2 * kDt};
  other.x.array() += 1e-3;  // m: would change the iterations if it were used
  const Stepped with_other = step_from(model, start, &other);
  EXPECT_EQ(with_other.report.iterations, cold.report.iterations);
  EXPECT_EQ(with_other.state.x, cold.state.x);
}

}  // namespace
}  // namespace vascsim

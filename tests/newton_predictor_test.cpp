// The Newton predictor of a dynamic step (sim/step/stepper.cpp) extrapolates with constant
// acceleration. A free rod falling under gravity moves exactly so, and BDF2 integrates that
// motion exactly once its start-up transient (a mode decaying as 3^-n) has gone, so from then on
// the predicted state already solves the step: Newton needs no iteration. A constant-velocity
// predictor, as before, needs one on every step.
#include <gtest/gtest.h>

#include "sim/run/compile.h"
#include "sim/step/model.h"
#include "sim/step/stepper.h"

namespace vascsim {
namespace {

TEST(NewtonPredictor, AFallingRodNeedsNoNewtonIterationOnceBdf2HasStarted) {
  Scene scene;
  scene.has_environment = false;
  scene.rod.nodes = 11;
  scene.loads.gravity.enabled = true;
  scene.solver.scheme = Scheme::kBdf2;
  scene.solver.rel_tol = 1e-10;
  const Model model = *compile(scene);
  State s = initial_state(model);
  Workspace ws(model);
  int iterations_late = 0;
  for (int i = 0; i < 100; ++i) {
    const StepReport r = step_once(model, s, ws, Controls{}, 1e-3);
    ASSERT_TRUE(r.ok) << r.failure;
    if (i >= 60) iterations_late += r.iterations;
  }
  EXPECT_EQ(iterations_late, 0);
  // And the fall is the exact one, g t^2 / 2, up to the start-up step's constant offset.
  const double t = s.t, g = 9.81;
  EXPECT_NEAR(s.v[1], -g * t, 1e-9);
}

}  // namespace
}  // namespace vascsim

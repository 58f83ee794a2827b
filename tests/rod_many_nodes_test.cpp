// Time steps of a finely meshed rod must not be rejected (issue 16 item 5d). A centred-clamp
// cantilever of 10^4 nodes under a small tip load, at dt = 0.01 s: every Newton matrix is well
// posed (the mass term M/h^2 bounds its softest mode from below), yet the old block-pivot test
// (the product of a pivot's two eigenvalues against its diagonal squared; docs/solver.md) called
// the tip pivot singular, and each step was halved until M/h^2 hid it: 30 rejected attempts in
// 16 steps for 0.04 s, and at 10^5 nodes and dt = 1e-3 runs of minutes. Counts, not times: the
// cost is the benchmark's business (vascsim bench speed, "Whole run").
#include <gtest/gtest.h>

#include "sim/run/compile.h"
#include "sim/step/model.h"
#include "sim/step/newton.h"
#include "sim/step/stepper.h"

namespace vascsim {
namespace {

TEST(RodManyNodes, CantileverStepsAreNotRejectedAt10000Nodes) {
  Scene scene;
  scene.has_environment = false;
  scene.rod.nodes = 10000;
  scene.boundary.clamp = ClampKind::kCentred;
  PointLoadSpec tip;
  tip.force = Vec2(0.0, -1e-5);  // N
  scene.loads.point_loads.push_back(tip);
  const Model model = *compile(scene);
  State state = initial_state(model);
  Workspace ws(model);
  const double dt = 0.01;  // s
  int rejected = 0, iterations = 0;
  for (int k = 0; k < 4; ++k) {
    const StepReport r = step(model, state, ws, Controls{}, dt);
    ASSERT_TRUE(r.ok) << r.failure;
    EXPECT_EQ(r.dt, dt) << "step " << k;
    rejected += r.rejected;
    iterations += r.total_iterations;
  }
  EXPECT_EQ(rejected, 0);
  EXPECT_LE(iterations, 4 * 4) << "Newton iterations in 4 steps";
  EXPECT_LT(state.position(model.nodes() - 1).y(), 0.0) << "the tip moves along the load";
}

}  // namespace
}  // namespace vascsim

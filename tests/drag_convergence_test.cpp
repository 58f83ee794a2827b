// Time convergence of the whole-body (cross-flow) drag: a cantilever of the paper's rod swings in
// blood under a tip load large enough to turn its edges by tens of degrees, so the drag's
// direction follows the rod. BDF2 is second order (docs/references.md section 0.2), so the tip's
// error at a fixed time against a run at an 8x smaller step must fall about 4x per halving of dt.
// The drag once took its tangents from the start of each step, an error of the rod's rotation
// within the step: the run was then first order (the error fell about 2x per halving).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "sim/run/compile.h"
#include "sim/step/model.h"
#include "sim/step/stepper.h"
#include "tests/rod_test_scenes.h"

namespace vascsim {
namespace {

Scene swinging_cantilever_in_blood() {
  Scene s = test::cantilever(21);
  s.solver.mode = SolveMode::kDynamic;
  s.solver.scheme = Scheme::kBdf2;
  s.solver.rel_tol = 1e-12;
  s.loads.drag.enabled = true;
  s.loads.drag.area = DragArea::kNodes;
  PointLoadSpec tip;
  tip.node = -1;
  tip.profile = LoadProfile::kRamp;  // switched on smoothly: a step load would excite modes no dt here resolves
  tip.ramp_time = 0.3;                // s
  tip.force = Vec2(0.0, 20.0 * test::bending_stiffness(s.rod) / (s.rod.length * s.rod.length));  // N
  s.loads.point_loads.push_back(tip);
  return s;
}

// The tip's position every 0.02 s over `duration`.
std::vector<Vec2> tip_path(const Scene& scene, double duration, double dt) {
  const Model model = *compile(scene);
  State s = initial_state(model);
  Workspace ws(model);
  std::vector<Vec2> path;
  const int steps = static_cast<int>(std::lround(duration / dt)), every = static_cast<int>(std::lround(0.02 / dt));
  for (int i = 1; i <= steps; ++i) {
    const StepReport r = step_once(model, s, ws, Controls{}, dt);
    EXPECT_TRUE(r.ok) << r.failure;
    if (!r.ok) break;
    if (i % every == 0) path.push_back(s.position(model.nodes() - 1));
  }
  return path;
}

double largest_distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) d = std::max(d, (a[k] - b[k]).norm());
  return d;
}

TEST(DragConvergence, WholeBodyDragOnASwingingRodIsSecondOrderInTime) {
  const Scene scene = swinging_cantilever_in_blood();
  const double duration = 1.0;  // s
  const std::vector<Vec2> reference = tip_path(scene, duration, 6.25e-5);
  // The rod does turn: the tip moves by a large fraction of the length.
  ASSERT_GT((reference.back() - test::static_equilibrium(test::cantilever(21)).position(20)).norm(), 0.1 * scene.rod.length);
  const double e1 = largest_distance(tip_path(scene, duration, 2e-3), reference);
  const double e2 = largest_distance(tip_path(scene, duration, 1e-3), reference);
  const double e3 = largest_distance(tip_path(scene, duration, 5e-4), reference);
  const double order_coarse = std::log2(e1 / e2), order_fine = std::log2(e2 / e3);
  std::printf("errors %g %g %g m, orders %.2f %.2f\n", e1, e2, e3, order_coarse, order_fine);
  EXPECT_GT(order_coarse, 1.7) << "errors " << e1 << " " << e2 << " " << e3 << " m";
  EXPECT_GT(order_fine, 1.7) << "errors " << e1 << " " << e2 << " " << e3 << " m";
}

}  // namespace
}  // namespace vascsim

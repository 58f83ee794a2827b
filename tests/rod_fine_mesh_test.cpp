// Static solves on fine meshes (issue 16 item 5a): a 2001-node cantilever, whose tip pivot in the
// Newton matrix's LDL^T is ~1e-10 of the diagonal (EI/L^3 against EA/dl), must solve like a
// 41-node one; so must a 10001-node one, whose residual's round-off (|K| |x| eps, K's bending
// stiffness growing like N^3) is 1e-2 of the load early in the load ramp (docs/solver.md).
// References the code did not produce: docs/references.md section 1 (the elastica table of
// Bisshopp & Drucker, Q. Appl. Math. 3:272, 1945, and Mattiasson, IJNME 17:145, 1981) and
// section 8 (a dead tip moment bends the rod into a circular arc of angle phi = M L / EI).
#include <gtest/gtest.h>

#include <cmath>

#include "sim/run/compile.h"
#include "sim/step/model.h"
#include "sim/step/newton.h"
#include "sim/step/statics.h"
#include "tests/rod_test_scenes.h"

namespace vascsim {
namespace {

using test::bending_stiffness;
using test::cantilever;

class RodFineMesh : public ::testing::TestWithParam<int> {};

State solve_cantilever(const Scene& scene, const PointLoadSpec& tip) {
  Scene s = scene;
  s.loads.point_loads.push_back(tip);
  StaticReport r;
  const State state = test::static_equilibrium(s, &r);
  EXPECT_EQ(r.negative_pivots, 0) << "a cantilever's equilibrium is stable";
  return state;
}

// alpha = P L^2 / EI = 10, the table's largest deflection (the tip turns 82 degrees). At 2001
// nodes the discretisation error is ~1e-7 (second order from 6.6e-5 at 81 nodes); what is left
// is the rod's extensibility, which the inextensible elastica ignores: the axial strain is about
// P / EA = alpha EI / (EA L^2) = 5e-5 for the paper's rod.
TEST_P(RodFineMesh, CantileverTipLoadMatchesElastica) {
  const int nodes = GetParam();
  const Scene scene = cantilever(nodes);
  const double ei = bending_stiffness(scene.rod), l = scene.rod.length;
  PointLoadSpec tip;
  tip.force = Vec2(0.0, -10.0 * ei / (l * l));
  const State state = solve_cantilever(scene, tip);
  const Vec2 x = state.position(nodes - 1);
  const Vec2 e = x - state.position(nodes - 2);
  EXPECT_NEAR(-x.y() / l, 0.81060902, 1e-4 * 0.81060902);
  EXPECT_NEAR(1.0 - x.x() / l, 0.55499560, 1e-4 * 0.55499560);
  EXPECT_NEAR(-std::atan2(e.y(), e.x()) * 180.0 / M_PI, 81.949, 1e-4 * 81.949);
}

// M = 2 pi EI / L rolls the rod into a full circle of radius R = L / (2 pi) through the root,
// centred at (0, R): every node on it, the tip back at the root heading along +x again.
TEST_P(RodFineMesh, TipMomentRollsCantileverIntoFullCircle) {
  const int nodes = GetParam();
  const Scene scene = cantilever(nodes);
  const double ei = bending_stiffness(scene.rod), l = scene.rod.length;
  PointLoadSpec tip;
  tip.moment = 2.0 * M_PI * ei / l;
  const State state = solve_cantilever(scene, tip);
  const double radius = l / (2.0 * M_PI);
  const Vec2 centre(0.0, radius);
  double off_circle = 0.0;
  for (int i = 1; i < nodes; ++i)
    off_circle = std::max(off_circle, std::abs((state.position(i) - centre).norm() - radius));
  EXPECT_LT(off_circle, 1e-5 * radius);
  EXPECT_LT(state.position(nodes - 1).norm(), 1e-5 * l);
  // The last edge is the chord of the arc's last dl = L / (N - 1.5): it heads half its turn,
  // dl / (2 R) = pi / (N - 1.5), short of the tip tangent. Beside that, DER's curvature
  // 2 tan(phi/2) (with its derivative sec^2(phi/2)) turns each hinge short by (kappa dl)^2 / 3 =
  // 3.3e-6 of its turn: 2.1e-5 rad over the whole circle.
  const Vec2 e = state.position(nodes - 1) - state.position(nodes - 2);
  EXPECT_NEAR(std::atan2(e.y(), e.x()), -M_PI / (nodes - 1.5), 4e-5);
  // Half way along the rod is the top of the circle: node k sits (k - 1/2) dl from the root, so
  // node (N - 1) / 2 is dl/4 short of L/2 (3e-7 R lower than the top at 2001 nodes).
  EXPECT_NEAR(state.position((nodes - 1) / 2).y(), 2.0 * radius, 1e-5 * radius);
}

INSTANTIATE_TEST_SUITE_P(Nodes, RodFineMesh, ::testing::Values(2001, 10001),
                         [](const auto& info) { return std::to_string(info.param) + "_nodes"; });

}  // namespace
}  // namespace vascsim

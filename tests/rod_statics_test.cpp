// Static validation of the rod (sim/step/statics.h) against closed forms and tables the code did
// not produce: docs/references.md sections 1 (elastica, small deflection, self-weight),
// 3 (Euler buckling) and 8 (tip moment), and the spatial convergence order (section 0).
#include <gtest/gtest.h>

#include <cmath>

#include "sim/run/compile.h"
#include "sim/step/banded_ldlt.h"
#include "sim/step/model.h"
#include "sim/step/newton.h"
#include "sim/step/statics.h"
#include "tests/rod_test_scenes.h"

namespace vascsim {
namespace {

using test::bending_stiffness;
using test::cantilever;

struct Tip {
  Vec2 position;
  double angle;  // rad, heading of the last edge
};

Tip solve_with_tip_load(Scene scene, const Vec2& force, double moment = 0.0) {
  PointLoadSpec tip;
  tip.force = force;
  tip.moment = moment;
  scene.loads.point_loads.push_back(tip);
  const Model model = *compile(scene);
  State state = initial_state(model);
  Workspace ws(model);
  const StaticReport r = solve_static(model, state, ws, Controls{});
  EXPECT_TRUE(r.ok) << r.failure;
  const int n = model.nodes();
  const Vec2 e = state.position(n - 1) - state.position(n - 2);
  return {state.position(n - 1), std::atan2(e.y(), e.x())};
}

// docs/references.md section 1, large deflection (Bisshopp & Drucker; Mattiasson): N = 41, centred clamp.
TEST(RodStatics, CantileverTipLoadMatchesElasticaTable) {
  struct Row { double alpha, deflection, shortening, rotation_deg; };
  const Row table[] = {{0.5, 0.16214358, 0.01591896, 14.011},
                       {1, 0.30172077, 0.05643324, 26.434},
                       {2, 0.49345748, 0.16064172, 44.791},
                       {5, 0.71379152, 0.38762836, 69.635},
                       {10, 0.81060902, 0.55499560, 81.949}};
  const Scene scene = cantilever(41);
  const double ei = bending_stiffness(scene.rod), l = scene.rod.length;
  for (const Row& row : table) {
    const Tip tip = solve_with_tip_load(scene, Vec2(0.0, -row.alpha * ei / (l * l)));
    EXPECT_NEAR(-tip.position.y() / l, row.deflection, 1e-3 * row.deflection) << "alpha " << row.alpha;
    EXPECT_NEAR(1.0 - tip.position.x() / l, row.shortening, 3e-3 * row.shortening) << "alpha " << row.alpha;
    EXPECT_NEAR(-tip.angle * 180.0 / M_PI, row.rotation_deg, 1e-3 * row.rotation_deg) << "alpha " << row.alpha;
  }
}

// docs/references.md section 1, small deflection: P L^3 / (3 EI), rotation P L^2 / (2 EI) at alpha = 0.01.
TEST(RodStatics, SmallDeflectionMatchesEulerBernoulli) {
  const Scene scene = cantilever(41);
  const double ei = bending_stiffness(scene.rod), l = scene.rod.length;
  const double p = 0.01 * ei / (l * l);
  const Tip tip = solve_with_tip_load(scene, Vec2(0.0, -p));
  EXPECT_NEAR(-tip.position.y(), p * l * l * l / (3 * ei), 1e-3 * p * l * l * l / (3 * ei));
  EXPECT_NEAR(-tip.angle, p * l * l / (2 * ei), 1e-3 * p * l * l / (2 * ei));
}

// docs/references.md section 1, self-weight: q L^4 / (8 EI) for q L^3 / EI <= 0.1.
TEST(RodStatics, SelfWeightMatchesEulerBernoulli) {
  Scene scene = cantilever(41);
  const double ei = bending_stiffness(scene.rod), l = scene.rod.length;
  const double area = M_PI * (std::pow(scene.rod.outer_radius, 2) - std::pow(scene.rod.inner_radius, 2));
  const double q_target = 0.05 * ei / (l * l * l);
  scene.loads.gravity.enabled = true;
  scene.loads.gravity.acceleration = Vec2(0.0, -q_target / (scene.rod.density * area));
  // With the centred clamp the half edge behind the root carries weight too but, being clamped,
  // none of it reaches the free span.
  const Tip tip = solve_with_tip_load(scene, Vec2::Zero());
  const double expected = q_target * std::pow(l, 4) / (8 * ei);
  EXPECT_NEAR(-tip.position.y(), expected, 2e-3 * expected);
}

// docs/references.md section 8: a dead tip moment bends the cantilever into a circular arc, phi = M L / EI.
TEST(RodStatics, TipMomentGivesCircularArc) {
  const Scene scene = cantilever(41);
  const double ei = bending_stiffness(scene.rod), l = scene.rod.length;
  const double phi = 1.0;
  const Tip tip = solve_with_tip_load(scene, Vec2::Zero(), phi * ei / l);
  EXPECT_NEAR(tip.position.x(), l * std::sin(phi) / phi, 1e-3 * l);
  EXPECT_NEAR(tip.position.y(), l * (1 - std::cos(phi)) / phi, 1e-3 * l);
}

// Newton on a tip moment converges quadratically only if the moment's stiffness has the sign the
// force-module contract states, K = -dF/dx (with +dF/dx, as before issue 16's audit found it
// fixed, the same answers took 70 iterations instead of 27). Load stepping from 0 to M = EI/L.
TEST(RodStatics, TipMomentNewtonConvergesQuadratically) {
  Scene scene = cantilever(41);
  PointLoadSpec tip;
  tip.moment = bending_stiffness(scene.rod) / scene.rod.length;
  scene.loads.point_loads.push_back(tip);
  const Model model = *compile(scene);
  State state = initial_state(model);
  Workspace ws(model);
  const StaticReport r = solve_static(model, state, ws, Controls{});
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_EQ(r.rejected, 0);
  EXPECT_LE(r.iterations, 5 * r.increments) << r.increments << " increments";
}

// docs/references.md section 0: with the centred clamp, the tip deflection error falls as dl^2.
TEST(RodStatics, SpatialConvergenceIsSecondOrder) {
  const double exact = 0.30172077;  // alpha = 1, section 1 table
  double errors[3];
  const int nodes[3] = {11, 21, 41};
  for (int k = 0; k < 3; ++k) {
    const Scene scene = cantilever(nodes[k]);
    const double ei = bending_stiffness(scene.rod), l = scene.rod.length;
    const Tip tip = solve_with_tip_load(scene, Vec2(0.0, -ei / (l * l)));
    errors[k] = std::abs(-tip.position.y() / l - exact);
  }
  // dl = L/(N - 1.5): the ratio of consecutive dl is 19.5/9.5 and 39.5/19.5.
  const double order = std::log(errors[1] / errors[2]) / std::log(39.5 / 19.5);
  const double order_coarse = std::log(errors[0] / errors[1]) / std::log(19.5 / 9.5);
  EXPECT_NEAR(order, 2.0, 0.15) << "errors " << errors[0] << " " << errors[1] << " " << errors[2];
  EXPECT_NEAR(order_coarse, 2.0, 0.3);
}

// docs/references.md section 3, Euler buckling of a clamped-free column: P_cr = pi^2 EI / (4 L^2). The straight
// rod under axial compression P is an equilibrium; its stiffness matrix acquires a negative
// eigenvalue (an LDL^T negative pivot, Sylvester's law of inertia) exactly when P > P_cr.
TEST(RodStatics, BucklingLoadOfClampedFreeColumn) {
  Scene scene = cantilever(41);
  scene.solver.stable_branch = false;  // the straight column's inertia, not the buckled one's
  const double ei = bending_stiffness(scene.rod), l = scene.rod.length;
  const double p_cr = M_PI * M_PI * ei / (4 * l * l);
  auto negative_eigenvalues = [&](double p) {
    Scene s = scene;
    PointLoadSpec tip;
    tip.force = Vec2(-p, 0.0);
    s.loads.point_loads.push_back(tip);
    const Model model = *compile(s);
    State state = initial_state(model);
    Workspace ws(model);
    const StaticReport r = solve_static(model, state, ws, Controls{});
    EXPECT_TRUE(r.ok) << r.failure;
    NewtonProblem problem;
    assemble(model, problem, state.x, ws, true);
    return banded_ldlt_factor(ws.jacobian).negative_pivots;
  };
  double lo = 0.5 * p_cr, hi = 1.5 * p_cr;
  ASSERT_EQ(negative_eigenvalues(lo), 0);
  ASSERT_GT(negative_eigenvalues(hi), 0);
  for (int k = 0; k < 12; ++k) {
    const double mid = 0.5 * (lo + hi);
    (negative_eigenvalues(mid) > 0 ? hi : lo) = mid;
  }
  EXPECT_NEAR(0.5 * (lo + hi), p_cr, 0.01 * p_cr);
}

// A free rod has rigid motions: the static solve must say its matrix is singular, not hang.
TEST(RodStatics, UnconstrainedRodFailsWithClearMessage) {
  Scene scene = cantilever(10);
  scene.boundary.clamp = ClampKind::kNone;
  PointLoadSpec tip;
  tip.force = Vec2(0.0, 1e-3);
  scene.loads.point_loads.push_back(tip);
  const Model model = *compile(scene);
  State state = initial_state(model);
  Workspace ws(model);
  const StaticReport r = solve_static(model, state, ws, Controls{});
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.failure.find("singular"), std::string::npos) << r.failure;
  EXPECT_TRUE(state.x.allFinite());
}

}  // namespace
}  // namespace vascsim

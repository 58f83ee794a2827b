// Dynamic validation of the stepper (sim/step/stepper.h) against references the code did not
// produce: the exact discrete backward Euler oscillator and its damping (docs/references.md
// sections 0.2 and 5), convergence orders of backward Euler and BDF2, cantilever natural
// frequencies (section 2), quadratic drag terminal velocity and backward Euler transient
// (section 4), and the sign of external forces.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "sim/rod/loads.h"
#include "sim/run/compile.h"
#include "sim/step/model.h"
#include "sim/step/newton.h"
#include "sim/step/stepper.h"
#include "tests/rod_test_scenes.h"

namespace vascsim {
namespace {

// The axial oscillator of tests/rod_test_scenes.h (k/m = (2 pi)^2), started displaced.
struct Oscillator {
  Scene scene;
  double amplitude = 0.01;  // m, initial displacement of node 2
  explicit Oscillator(Scheme scheme) : scene(test::axial_oscillator(scheme)) {}
  // Displacement of node 2 divided by the amplitude after `steps` steps of dt.
  double run(double dt, int steps, double* velocity = nullptr) const {
    const Model model = *compile(scene);
    State s = initial_state(model);
    s.x[4] += amplitude;
    Workspace ws(model);
    for (int i = 0; i < steps; ++i) {
      const StepReport r = step_once(model, s, ws, Controls{}, dt);
      EXPECT_TRUE(r.ok) << r.failure;
    }
    if (velocity) *velocity = s.v[4] / amplitude;
    return (s.x[4] - 1.0) / amplitude;
  }
};

// docs/references.md section 5 (Hairer & Wanner): w = 2 pi, x0 = 1, after 1 s.
TEST(RodDynamics, BackwardEulerOscillatorMatchesExactDiscreteSolution) {
  const Oscillator osc(Scheme::kBackwardEuler);
  EXPECT_NEAR(osc.run(0.1, 10), 0.1480882808, 1e-9);
  EXPECT_NEAR(osc.run(0.01, 100), 0.8211598426, 1e-9);
}

// docs/references.md section 0.2: each backward Euler step multiplies the amplitude by 1/sqrt(1 + h^2).
TEST(RodDynamics, BackwardEulerDampingPerStep) {
  const Oscillator osc(Scheme::kBackwardEuler);
  const double w = 2 * M_PI;
  for (double h : {0.1, 0.5, 2.0}) {
    double v = 0.0;
    const double x = osc.run(h / w, 1, &v);
    EXPECT_NEAR(std::hypot(x, v / w), 1.0 / std::sqrt(1.0 + h * h), 1e-10) << "h " << h;
    EXPECT_NEAR(std::atan2(-v / w, x), std::atan(h), 1e-10) << "h " << h;
  }
}

// Global error at t = 1 s against cos(2 pi t), halving dt twice.
double measured_order(Scheme scheme) {
  const Oscillator osc(scheme);
  double e[3];
  for (int k = 0; k < 3; ++k) {
    const int steps = 100 << k;
    e[k] = std::abs(osc.run(1.0 / steps, steps) - 1.0);
  }
  return std::log2(e[1] / e[2]);
}

TEST(RodDynamics, BackwardEulerIsFirstOrder) { EXPECT_NEAR(measured_order(Scheme::kBackwardEuler), 1.0, 0.15); }
TEST(RodDynamics, Bdf2IsSecondOrder) { EXPECT_NEAR(measured_order(Scheme::kBdf2), 2.0, 0.15); }

// docs/references.md section 2 (Blevins): clamped-free, w_n = (beta_n L)^2 sqrt(EI / (rho A L^4)). The
// transverse stiffness of the straight cantilever (centred clamp) and the lumped masses give the
// discrete frequencies as a generalised eigenproblem. The DER stencil is the central difference
// of the fourth derivative, whose symbol (2 - 2 cos k dl)^2 / dl^4 makes w_n low by
// (beta_n dl)^2 / 12: 1e-4 for mode 1 at N = 41 (as docs/references.md section 2 says) but 1.2e-3 and 3.3e-3
// for modes 2 and 3, so those are checked at N = 81 where the same estimate gives 3e-4 and 8e-4.
Eigen::VectorXd cantilever_frequencies(int nodes) {
  const Scene scene = test::cantilever(nodes);
  const Model model = *compile(scene);
  State s = initial_state(model);
  Workspace ws(model);
  std::fill(ws.fixed.begin(), ws.fixed.end(), 0);
  NewtonProblem p;
  assemble(model, p, s.x, ws, true);
  const Eigen::MatrixXd k_all = ws.jacobian.to_dense();
  const int free = model.nodes() - 2;  // nodes 2 .. N-1, y only
  Eigen::MatrixXd k(free, free), m = Eigen::MatrixXd::Zero(free, free);
  for (int a = 0; a < free; ++a) {
    m(a, a) = model.rod.mass[a + 2];
    for (int b = 0; b < free; ++b) k(a, b) = k_all(2 * (a + 2) + 1, 2 * (b + 2) + 1);
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(k, m);
  return eig.eigenvalues().head(3).cwiseSqrt();
}

TEST(RodDynamics, CantileverNaturalFrequencies) {
  const Scene scene = test::cantilever(41);
  const double ei = test::bending_stiffness(scene.rod), l = scene.rod.length;
  const double rho_a = scene.rod.density * M_PI *
                       (std::pow(scene.rod.outer_radius, 2) - std::pow(scene.rod.inner_radius, 2));
  const double beta_l[3] = {1.8751040687, 4.6940911330, 7.8547574382};
  const Eigen::VectorXd w41 = cantilever_frequencies(41), w81 = cantilever_frequencies(81);
  for (int n = 0; n < 3; ++n) {
    const double expected = beta_l[n] * beta_l[n] * std::sqrt(ei / (rho_a * std::pow(l, 4)));
    if (n == 0) {
      EXPECT_NEAR(w41[n], expected, 2e-4 * expected) << "mode 1, N = 41";
    }
    EXPECT_NEAR(w81[n], expected, 1e-3 * expected) << "mode " << n + 1 << ", N = 81";
    // Second-order convergence of every mode (dl ratio 79.5 / 39.5).
    const double order = std::log(std::abs(w41[n] - expected) / std::abs(w81[n] - expected)) / std::log(79.5 / 39.5);
    EXPECT_NEAR(order, 2.0, 0.15) << "mode " << n + 1;
  }
}

// A straight solid rod falling broadside through a fluid with drag on every node (refs
// section 4): every node has the same k = c_i / m_i, so the rod translates rigidly and each node
// obeys m dv/dt = m g - c v |v|.
struct FallingRod {
  Scene scene;
  FallingRod() {
    scene.has_environment = false;
    scene.rod.nodes = 5;
    scene.rod.inner_radius = 0.0;
    scene.loads.gravity.enabled = true;
    scene.loads.drag.enabled = true;
    scene.solver.scheme = Scheme::kBackwardEuler;
    scene.solver.rel_tol = 1e-13;
  }
};

TEST(RodDynamics, QuadraticDragTerminalVelocity) {
  const FallingRod f;
  const Model model = *compile(f.scene);
  State s = initial_state(model);
  Workspace ws(model);
  for (int i = 0; i < 200; ++i) ASSERT_TRUE(step_once(model, s, ws, Controls{}, 0.01).ok);
  const double r = f.scene.rod.outer_radius, g = 9.81;
  const double v_t = std::sqrt(M_PI * r * f.scene.rod.density * g / (1025.0 * 1.0536));
  for (int i = 0; i < model.nodes(); ++i) {
    EXPECT_NEAR(s.v[2 * i + 1], -v_t, 1e-8 * v_t);
    EXPECT_NEAR(s.v[2 * i], 0.0, 1e-12);
  }
}

TEST(RodDynamics, QuadraticDragBackwardEulerTransientIsExact) {
  const FallingRod f;
  const Model model = *compile(f.scene);
  State s = initial_state(model);
  Workspace ws(model);
  const double r = f.scene.rod.outer_radius, g = 9.81, h = 0.005;
  const double k = 0.5 * 1025.0 * 1.0536 * 2 * r / (f.scene.rod.density * M_PI * r * r);
  double u = 0.0;  // downward speed of the exact discrete solution
  for (int i = 0; i < 20; ++i) {
    ASSERT_TRUE(step_once(model, s, ws, Controls{}, h).ok);
    // m (u1 - u0)/h = m g - c u1^2  =>  k h u1^2 + u1 - (u0 + g h) = 0
    u = (-1.0 + std::sqrt(1.0 + 4.0 * k * h * (u + g * h))) / (2.0 * k * h);
    EXPECT_NEAR(-s.v[5], u, 1e-10 * u) << "step " << i;
  }
}

// Drag on every node splits into cross-flow and axial parts (the cross-flow principle, paper
// V.A's refinement; docs/references.md section 4 for each part). A straight solid rod falling at 30 degrees to
// its axis reaches each part's own terminal speed, m g_t = c_t v_t^2 and m g_n = c_n v_n^2, so it
// drifts along itself far faster than the fall direction suggests; it neither turns nor bends
// (c_i / m_i is the same on every node).
TEST(RodDynamics, CrossFlowDragTerminalVelocityPerDirection) {
  FallingRod f;
  const double g = 9.81, angle = M_PI / 6.0, cd_t = 0.05;
  f.scene.loads.gravity.acceleration = g * Vec2(std::cos(angle), -std::sin(angle));
  f.scene.loads.drag.tangential_coefficient = cd_t;
  const Model model = *compile(f.scene);
  State s = initial_state(model);
  Workspace ws(model);
  for (int i = 0; i < 400; ++i) ASSERT_TRUE(step_once(model, s, ws, Controls{}, 0.01).ok);
  const double r = f.scene.rod.outer_radius, rho_s = f.scene.rod.density, rho = 1025.0;
  // m_i / c_i = rho_s pi r^2 dl / (1/2 rho Cd 2 r dl) = pi r rho_s / (rho Cd)
  const double v_axial = std::sqrt(M_PI * r * rho_s * g * std::cos(angle) / (rho * cd_t));
  const double v_normal = std::sqrt(M_PI * r * rho_s * g * std::sin(angle) / (rho * 1.0536));
  for (int i = 0; i < model.nodes(); ++i) {
    EXPECT_NEAR(s.v[2 * i], v_axial, 1e-8 * v_axial) << "node " << i;
    EXPECT_NEAR(s.v[2 * i + 1], -v_normal, 1e-8 * v_normal) << "node " << i;
    EXPECT_NEAR(s.x[2 * i + 1], s.x[1], 1e-9) << "the rod stays straight and level";
  }
}

// A free rod of `nodes` nodes in the default fluid, with cross-flow drag and nothing else.
Scene free_rod_in_drag(int nodes) {
  Scene scene;
  scene.has_environment = false;
  scene.rod.nodes = nodes;
  scene.loads.drag.enabled = true;
  return scene;
}

// The drag's Newton matrix is -dF/dv * dv_dx (the tangent is lagged, so F depends on v alone
// within a step), checked by central differences on a bent rod moving every which way.
TEST(RodDynamics, CrossFlowDragStiffnessIsTheVelocityJacobian) {
  const Scene scene = free_rod_in_drag(5);
  const Model model = *compile(scene);
  const QuadraticDragModule drag(model.rod, scene.loads.drag);
  State start = initial_state(model);
  for (int i = 0; i < model.nodes(); ++i) start.x[2 * i + 1] = 0.02 * std::sin(3.0 * i);  // bent
  Eigen::VectorXd v(2 * model.nodes());
  for (int k = 0; k < v.size(); ++k) v[k] = 0.3 * std::cos(1.7 * k + 0.4);
  const Controls controls;
  auto force_at = [&](const Eigen::VectorXd& velocity, BandedMatrix* stiffness) {
    ForceContext ctx = ForceContext::at(start, controls);
    ctx.v = &velocity;
    ctx.dv_dx = 250.0;  // 1/s, as backward Euler with h = 4 ms
    Eigen::VectorXd f = Eigen::VectorXd::Zero(velocity.size());
    drag.add(ctx, f, stiffness);
    return f;
  };
  BandedMatrix k(static_cast<int>(v.size()));
  force_at(v, &k);
  const double h = 1e-7;
  for (int col = 0; col < v.size(); ++col) {
    Eigen::VectorXd plus = v, minus = v;
    plus[col] += h;
    minus[col] -= h;
    const Eigen::VectorXd df_dv = (force_at(plus, nullptr) - force_at(minus, nullptr)) / (2.0 * h);
    for (int row = 0; row < v.size(); ++row)
      EXPECT_NEAR(k.at(row, col), -250.0 * df_dv[row], 1e-6 * (1.0 + std::abs(k.at(row, col)))) << row << ", " << col;
  }
}

// The run keeps the drag's step tangents in a cache (loads.h): whatever the order in which steps
// of other starts and lengths come, a cached call gives the forces of a call from scratch.
TEST(RodDynamics, CrossFlowDragTangentCacheNeverServesAnotherStep) {
  const Scene scene = free_rod_in_drag(6);
  const Model model = *compile(scene);
  const QuadraticDragModule drag(model.rod, scene.loads.drag);
  const std::unique_ptr<ModuleCache> cache = drag.make_cache();
  ASSERT_NE(cache, nullptr);
  State a = initial_state(model), b = initial_state(model);
  for (int i = 0; i < model.nodes(); ++i) {
    a.v[2 * i + 1] = 0.5 * i;                        // the rod swings round: its tangents turn in a step
    b.x[2 * i + 1] = 0.01 * std::sin(2.0 * i);       // bent
    b.v[2 * i] = -0.2 * i;
  }
  State b_moving = b;
  b_moving.v[3] += 0.7;  // same positions, other velocities
  Eigen::VectorXd v(2 * model.nodes());
  for (int k = 0; k < v.size(); ++k) v[k] = 0.3 * std::cos(1.3 * k + 0.2);
  const Controls controls;
  auto force = [&](const State& start, double h, ModuleCache* with) {
    ForceContext ctx = ForceContext::at(start, controls);
    ctx.t = start.t + h;
    ctx.v = &v;
    ctx.cache = with;
    Eigen::VectorXd f = Eigen::VectorXd::Zero(v.size());
    drag.add(ctx, f, nullptr);
    return f;
  };
  const std::vector<std::pair<const State*, double>> calls = {
      {&a, 0.01}, {&a, 0.01}, {&a, 0.02}, {&b, 0.02}, {&b_moving, 0.02}, {&a, 0.01}, {&a, 0.0}};
  for (std::size_t k = 0; k < calls.size(); ++k) {
    const Eigen::VectorXd cached = force(*calls[k].first, calls[k].second, cache.get());
    const Eigen::VectorXd fresh = force(*calls[k].first, calls[k].second, nullptr);
    EXPECT_EQ(cached, fresh) << "call " << k;
  }
  // The calls differ: a cache that ignored the start or the step would have failed above.
  EXPECT_GT((force(a, 0.01, nullptr) - force(a, 0.02, nullptr)).norm(), 1e-9);
  EXPECT_GT((force(b, 0.02, nullptr) - force(b_moving, 0.02, nullptr)).norm(), 1e-9);
}

// External forces accelerate the rod along themselves: after one step of a free rod the
// momentum change is exactly F h (internal forces cancel). The paper's code and dismech-rods
// had the sign backwards.
TEST(RodDynamics, ExternalForceSign) {
  Scene scene;
  scene.has_environment = false;
  scene.rod.nodes = 6;
  scene.solver.scheme = Scheme::kBackwardEuler;
  scene.solver.rel_tol = 1e-12;
  PointLoadSpec tip;
  tip.force = Vec2(2e-3, -1e-3);
  scene.loads.point_loads.push_back(tip);
  const Model model = *compile(scene);
  State s = initial_state(model);
  Workspace ws(model);
  const double h = 1e-3;
  ASSERT_TRUE(step_once(model, s, ws, Controls{}, h).ok);
  Vec2 momentum = Vec2::Zero();
  for (int i = 0; i < model.nodes(); ++i) momentum += model.rod.mass[i] * s.velocity(i);
  EXPECT_NEAR(momentum.x(), 2e-3 * h, 1e-9 * 2e-3 * h);
  EXPECT_NEAR(momentum.y(), -1e-3 * h, 1e-9 * 1e-3 * h);
  EXPECT_GT(s.velocity(5).x(), 0.0);
  EXPECT_LT(s.velocity(5).y(), 0.0);
}

// A node with prescribed motion follows it exactly; the rest of the rod is dragged along.
TEST(RodDynamics, PrescribedNodeFollowsItsMotion) {
  Scene scene;
  scene.has_environment = false;
  scene.rod.nodes = 8;
  PrescribedMotionSpec drive;
  drive.node = -1;
  drive.velocity = Vec2(0.0, 0.05);
  scene.boundary.prescribed.push_back(drive);
  const Model model = *compile(scene);
  State s = initial_state(model);
  const Vec2 start = s.position(7);
  Workspace ws(model);
  Controls controls;
  for (int i = 0; i < 100; ++i) ASSERT_TRUE(step(model, s, ws, controls, 1e-3).ok);
  EXPECT_NEAR((s.position(7) - start - Vec2(0.0, 0.005)).norm(), 0.0, 1e-12);
  EXPECT_GT(s.position(6).y(), 1e-4);
  // A controller target overrides for the step: hold the tip where it is.
  controls.time = s.t;
  controls.targets.push_back({-1, s.position(7), Vec2::Zero()});
  const Vec2 held = s.position(7);
  ASSERT_TRUE(step(model, s, ws, controls, 1e-3).ok);
  EXPECT_NEAR((s.position(7) - held).norm(), 0.0, 1e-15);
}

// A step that cannot converge leaves the state untouched and says why; with adaptive stepping
// the same step succeeds with a smaller dt.
TEST(RodDynamics, FailedStepKeepsStateAndAdaptiveRetrySucceeds) {
  Scene scene;
  scene.has_environment = false;
  scene.rod.nodes = 20;
  scene.boundary.clamp = ClampKind::kFirstEdge;
  scene.solver.max_iterations = 3;
  PointLoadSpec tip;
  tip.force = Vec2(0.0, 0.05);  // large for this soft rod: the tip swings far in one big step
  scene.loads.point_loads.push_back(tip);
  scene.solver.adaptive = StepControl::kOff;
  {
    const Model model = *compile(scene);
    State s = initial_state(model);
    const State before = s;
    Workspace ws(model);
    const StepReport r = step(model, s, ws, Controls{}, 0.2);
    ASSERT_FALSE(r.ok);
    EXPECT_NE(r.failure.find("t = 0"), std::string::npos) << r.failure;
    EXPECT_EQ(s.x, before.x);
    EXPECT_EQ(s.v, before.v);
    EXPECT_EQ(s.t, 0.0);
  }
  scene.solver.adaptive = StepControl::kRetry;
  const Model model = *compile(scene);
  State s = initial_state(model);
  Workspace ws(model);
  const StepReport r = step(model, s, ws, Controls{}, 0.2);
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_GT(r.rejected, 0);
  EXPECT_LT(r.dt, 0.2);
  EXPECT_NEAR(s.t, r.dt, 1e-15);
}

}  // namespace
}  // namespace vascsim

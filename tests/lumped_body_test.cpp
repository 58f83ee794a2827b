// Lumped bodies (loads.bodies: extra mass and its own linear or quadratic drag on a node) against
// exact solutions: the axial oscillator of tests/rod_dynamics_test.cpp (node 2 on a clamped first
// edge is a linear spring k, docs/references.md section 5) with a body of mass M on that node
// oscillates at w = sqrt(k / (m + M)); with linear drag c it is the damped oscillator
// x = A e^(-zeta w t) (cos w_d t + zeta / sqrt(1 - zeta^2) sin w_d t), zeta = c / (2 sqrt(k (m + M)));
// a free rod with quadratic drag c2 on each of its n nodes falls at the terminal speed where the
// drag balances the weight, v = sqrt(g sum(m) / (n c2)).
#include <gtest/gtest.h>

#include <cmath>

#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/scene/input_error.h"
#include "sim/step/model.h"
#include "sim/step/stepper.h"
#include "tests/rod_test_scenes.h"

namespace vascsim {
namespace {

Scene oscillator_with_body(double body_mass, double linear_drag) {
  Scene scene = test::axial_oscillator(Scheme::kBdf2);  // k / m = (2 pi)^2 without the body
  scene.loads.bodies.push_back({2, body_mass, linear_drag, 0.0});
  return scene;
}

// Node 2's displacement over its initial one after 1 s of steps of 1e-3 s.
double displacement_after_one_second(const Scene& scene) {
  const Model model = *compile(scene);
  State s = initial_state(model);
  const double a = 0.01;
  s.x[4] += a;
  Workspace ws(model);
  for (int i = 0; i < 1000; ++i) {
    const StepReport r = step_once(model, s, ws, Controls{}, 1e-3);
    EXPECT_TRUE(r.ok) << r.failure;
  }
  return (s.x[4] - 1.0) / a;
}

TEST(LumpedBody, MassLowersTheFrequencyAndLinearDragDampsAsExpected) {
  const Model bare = *compile(oscillator_with_body(0.0, 0.0));
  const double m = bare.rod.mass[2], k = std::pow(2 * M_PI, 2) * m;  // N/m
  const double body = 3 * m;  // four times the mass: half the frequency
  const double w = std::sqrt(k / (m + body));
  EXPECT_NEAR(displacement_after_one_second(oscillator_with_body(body, 0.0)), std::cos(w * 1.0), 2e-3);
  const double zeta = 0.1, c = 2 * zeta * std::sqrt(k * (m + body));  // N s/m
  const double wd = w * std::sqrt(1 - zeta * zeta);
  const double exact = std::exp(-zeta * w) * (std::cos(wd) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd));
  EXPECT_NEAR(displacement_after_one_second(oscillator_with_body(body, c)), exact, 2e-3);
}

TEST(LumpedBody, QuadraticDragGivesTheTerminalSpeed) {
  Scene scene;
  scene.has_environment = false;
  scene.rod.nodes = 5;
  scene.rod.length = 0.1;
  scene.loads.gravity.enabled = true;
  const double c2 = 0.02;  // kg/m
  for (int i = 0; i < 5; ++i) scene.loads.bodies.push_back({i, 1e-3, 0.0, c2});
  scene.solver.dt = 2e-3;
  const Model model = *compile(scene);
  const double g = 9.81, n = 5;
  const double v_terminal = std::sqrt(g * model.rod.mass.sum() / (n * c2));  // about 0.7 m/s; tau = v / g
  State s = initial_state(model);
  Workspace ws(model);
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(step(model, s, ws, Controls{}, 2e-3).ok);  // 2 s, ~30 time constants
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(s.v[2 * i + 1], -v_terminal, 1e-6 * v_terminal) << "node " << i;
}

TEST(LumpedBody, ReadWriteAndErrors) {
  const Scene s = read_scene_text(R"({"maze": null, "loads": {"bodies": [{"node": -1, "mass": 0.002, "quadratic_drag": 0.5}]}})",
                                  "b.json");
  ASSERT_EQ(s.loads.bodies.size(), 1u);
  EXPECT_EQ(read_scene_text(scene_to_json(s), "b.json").loads.bodies[0].quadratic_drag, 0.5);
  Scene far = s;
  far.loads.bodies[0].node = 99;
  try {
    compile(far);
    ADD_FAILURE() << "a body on node 99 of 50 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/loads/bodies/0/node"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vascsim

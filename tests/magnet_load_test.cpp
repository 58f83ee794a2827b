// A tip magnet in a fixed uniform field (loads.magnet) against the exact answer for an
// inextensible Euler-Bernoulli cantilever: a uniform field exerts only a couple on the magnet,
// M = m B sin(phi - theta), with theta the tip's angle and phi the field's, so the bending moment
// is M all along the rod, which bends into a circular arc of curvature M / EI with
// theta = M L / EI. The tip angle therefore solves theta = (m B L / EI) sin(phi - theta)
// (e.g. Zhao et al., "Mechanics of hard-magnetic soft materials", JMPS 124 (2019), sec. 5.1, and
// the magnetic elastica of Wang et al., Soft Robotics 2020).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/scene/input_error.h"
#include "sim/step/model.h"
#include "sim/step/statics.h"
#include "tests/rod_test_scenes.h"

namespace vascsim {
namespace {

// theta = a sin(phi - theta) by bisection on [0, phi] (the left side grows, the right falls).
double exact_tip_angle(double a, double phi) {
  double lo = 0.0, hi = phi;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid < a * std::sin(phi - mid) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct Equilibrium {
  double tip_angle;    // rad, of the distal edge
  double curvature_spread;  // max |kappa_i - kappa_mean| / kappa_mean over interior hinges
};

Equilibrium solve(double a, double phi, int nodes) {
  Scene scene = test::cantilever(nodes);
  const double ei = test::bending_stiffness(scene.rod), l = scene.rod.length;
  scene.loads.magnet.enabled = true;
  scene.loads.magnet.moment = 0.01;
  scene.loads.magnet.field = a * ei / (l * scene.loads.magnet.moment);
  scene.loads.magnet.angle = phi;
  scene.solver.load_steps = 20;
  const State state = test::static_equilibrium(scene);
  const int n = scene.rod.nodes;
  const Eigen::Vector2d last = state.position(n - 1) - state.position(n - 2);
  // Turning angle between consecutive edges from node 2 on (the centred clamp holds the first).
  std::vector<double> turn;
  for (int i = 2; i + 1 < n; ++i) {
    const Eigen::Vector2d e0 = state.position(i) - state.position(i - 1), e1 = state.position(i + 1) - state.position(i);
    turn.push_back(std::atan2(e0.x() * e1.y() - e0.y() * e1.x(), e0.dot(e1)));
  }
  double mean = 0.0, spread = 0.0;
  for (double t : turn) mean += t / turn.size();
  for (double t : turn) spread = std::max(spread, std::abs(t - mean) / std::abs(mean));
  return {std::atan2(last.y(), last.x()), spread};
}

// The distal edge's direction is the tangent at its midpoint, dl / 2 short of the tip, so the
// discrete tip angle converges to the exact one as dl (first order): checked at N = 41 and 81,
// and the Richardson extrapolation 2 theta_81 - theta_41 against the exact angle.
TEST(MagnetLoad, TipAngleMatchesTheMagneticElastica) {
  // a = m B L / EI; phi the field's angle from the undeformed rod.
  for (const auto& [a, phi] : {std::pair{1.0, M_PI / 2}, std::pair{0.3, M_PI / 2}, std::pair{3.0, M_PI / 2},
                               std::pair{2.0, 3 * M_PI / 4}}) {
    const double exact = exact_tip_angle(a, phi);
    const Equilibrium coarse = solve(a, phi, 41), fine = solve(a, phi, 81);
    std::printf("a %.1f phi %.4f: exact %.6f, N 41 %.6f, N 81 %.6f, extrapolated %.6f\n", a, phi, exact,
                coarse.tip_angle, fine.tip_angle, 2 * fine.tip_angle - coarse.tip_angle);
    EXPECT_NEAR(std::log2((exact - coarse.tip_angle) / (exact - fine.tip_angle)), 1.0, 0.1) << "a " << a;
    EXPECT_NEAR(2 * fine.tip_angle - coarse.tip_angle, exact, 2e-4 * exact) << "a " << a << " phi " << phi;
    EXPECT_LT(fine.curvature_spread, 1e-3) << "a pure couple bends the rod into a circular arc";
  }
  // The Dottie number: theta = cos(theta) for a = 1 across the field.
  EXPECT_NEAR(exact_tip_angle(1.0, M_PI / 2), 0.7390851332151607, 1e-12);
}

TEST(MagnetLoad, RotatingFieldTurnsTheTipAndStaticModeRefusesTimeProfiles) {
  const char* rotating = R"({"maze": null, "loads": {"magnet": {"enabled": true, "rotation_rate": 1.0}},
                             "solver": {"mode": "static"}})";
  try {
    read_scene_text(rotating, "m.json");
    ADD_FAILURE() << "a rotating field in a static solve was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/loads/magnet/rotation_rate"), std::string::npos) << e.what();
  }
  MagnetSpec m;
  m.field = 2.0, m.angle = 0.0, m.ramp_time = 4.0, m.rotation_rate = 0.5;
  EXPECT_NEAR(m.field_at(2.0).norm(), 1.0, 1e-12) << "half way up the ramp";
  EXPECT_NEAR(std::atan2(m.field_at(2.0).y(), m.field_at(2.0).x()), 1.0, 1e-12);
  EXPECT_NEAR(m.field_at(10.0).norm(), 2.0, 1e-12);
}

TEST(SceneControl, AControlSectionWithoutARouteIsAnError) {
  try {
    read_scene_text(R"({"maze": null, "control": {"kp": 2}})", "c.json");
    ADD_FAILURE() << "a control section in a free-space scene was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("c.json: /control"), std::string::npos) << e.what();
  }
  // The canonical text of a free-space scene has no control section, so it reads back.
  const Scene s = read_scene_text(R"({"maze": null})", "c.json");
  EXPECT_NO_THROW(read_scene_text(scene_to_json(s), "c.json"));
}

}  // namespace
}  // namespace vascsim

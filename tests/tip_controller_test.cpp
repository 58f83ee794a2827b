// The feedforward PD tip controller (paper Algorithm 1) on a point-mass plant, without a stepper
// (STYLE.md example 10). References: the closed loop m e'' + Kd e' + Kp e = -d(t) has the steady
// sinusoidal amplitude A / sqrt((Kp - m w^2)^2 + (Kd w)^2) (any control text, e.g. Ogata, Modern
// Control Engineering, frequency response of a second-order system).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/control/tip_controller.h"

namespace vascsim {
namespace {

struct PointMassRun {
  double max_error = 0.0;        // m, over the whole run
  double late_amplitude = 0.0;   // m, max |error| over the last quarter
};

// Semi-implicit Euler on a point mass with quadratic drag, the controller's force applied each step.
PointMassRun simulate(const ControlSpec& spec, const TipPlant& plant, const Trajectory& path, double duration) {
  TipController controller(spec, path, plant);
  const double dt = 1e-5;
  Vec2 x = path.position(0.0), v = path.velocity(0.0);
  PointMassRun run;
  for (double t = 0.0; t < duration; t += dt) {
    const TipCommand c = controller.command(t, dt, x, v);
    const Vec2 drag = -plant.drag_coefficient * v.norm() * v;
    const Vec2 disturbance = controller.disturbance(t + dt);
    v += dt * (c.force + drag + disturbance) / plant.mass;
    x += dt * v;
    const double e = (path.position(t + dt) - x).norm();
    run.max_error = std::max(run.max_error, e);
    if (t > 0.75 * duration) run.late_amplitude = std::max(run.late_amplitude, e);
  }
  return run;
}

ControlSpec undisturbed() {
  ControlSpec s;
  s.disturbance.amplitude = 0.0;
  return s;
}

TEST(TipController, FeedforwardTracksAStraightPathWithDragExactly) {
  const Trajectory path({Vec2(0, 0), Vec2(1, 0)}, 0.0, 0.2);
  const TipPlant plant{0.005, 0.5 * 1025 * 1.0536 * M_PI * 4e-6};
  const auto run = simulate(undisturbed(), plant, path, 3.0);
  EXPECT_LT(run.max_error, 1e-5);
}

TEST(TipController, FeedforwardFollowsARoundedCorner) {
  // Through a 0.05 m arc at 0.05 m/s the centripetal acceleration is v^2/R = 0.05 m/s^2.
  const Trajectory path({Vec2(0, 0), Vec2(0.2, 0), Vec2(0.2, 0.2)}, 0.05, 0.05);
  const auto run = simulate(undisturbed(), TipPlant{0.005, 0.0}, path, path.duration());
  EXPECT_LT(run.max_error, 1e-4);
}

TEST(TipController, DisturbanceErrorMatchesSecondOrderResponse) {
  const Trajectory path({Vec2(0, 0), Vec2(10, 0)}, 0.0, 0.01);
  ControlSpec spec;  // defaults: Kp 4 N/m, Kd 0.4 N s/m, 2 mN at 5 rad/s
  const double m = 0.005, w = spec.disturbance.omega, A = spec.disturbance.amplitude;
  const double expected = A / std::hypot(spec.kp - m * w * w, spec.kd * w);
  const auto run = simulate(spec, TipPlant{m, 0.0}, path, 8.0);
  EXPECT_NEAR(run.late_amplitude, expected, 0.02 * expected);
}

TEST(TipController, HigherGainReducesDisturbanceError) {
  const Trajectory path({Vec2(0, 0), Vec2(10, 0)}, 0.0, 0.01);
  ControlSpec soft, stiff;
  stiff.kp = 4.0 * soft.kp;
  const TipPlant plant{0.005, 0.0};
  const double soft_error = simulate(soft, plant, path, 6.0).late_amplitude;
  const double stiff_error = simulate(stiff, plant, path, 6.0).late_amplitude;
  EXPECT_LT(stiff_error, 0.5 * soft_error);
}

TEST(TipController, KinematicModeImposesReferenceWhenOnTrack) {
  // Algorithm 1 with zero error: q_new = ref_q(t_i), v = (q_new - q) / dt.
  const Trajectory path({Vec2(0, 0), Vec2(1, 0)}, 0.0, 0.1);
  ControlSpec spec = undisturbed();
  spec.mode = ActuationMode::kKinematic;
  spec.kp = 0.5;
  spec.kd = 0.0;
  TipController controller(spec, path, TipPlant{0.005, 0.0});
  const double dt = 0.01;
  const TipCommand c = controller.command(1.0, dt, path.position(1.0 + dt), path.velocity(1.0));
  EXPECT_NEAR((c.position - path.position(1.0 + dt)).norm(), 0.0, 1e-12);
  // Off track by 1 cm across the path: Algorithm 1 commands ref + Kp e, e = ref - q = -1 cm, so
  // the command lies Kp of the error beyond the reference (pre-compensating a persistent offset).
  const TipCommand off = controller.command(1.0, dt, path.position(1.0 + dt) + Vec2(0, 0.01), path.velocity(1.0));
  EXPECT_NEAR(off.position.y(), -spec.kp * 0.01, 1e-12);
}

TEST(TipController, KinematicModeConvergesForAnyKdAndStep) {
  // The tip imposed where the controller commands, 1 cm off a straight path: the cross-track
  // error must never grow and must be gone after 3 s, for a derivative gain up to 0.4 s and steps
  // from 0.1 to 10 ms. The paper's explicit derivative term multiplied it by about 200 per step
  // at Kd = 0.4 s and dt = 2 ms (its loop gain Kd/dt on the controller's own last command).
  const Trajectory path({Vec2(0, 0), Vec2(1, 0)}, 0.0, 0.1);
  for (double kd : {0.0, 0.01, 0.4}) {
    for (double dt : {1e-4, 2e-3, 1e-2}) {
      ControlSpec spec = undisturbed();
      spec.mode = ActuationMode::kKinematic;
      spec.kp = 0.5;
      spec.kd = kd;
      TipController controller(spec, path, TipPlant{0.005, 0.0});
      Vec2 tip(0, 0.01), velocity(0, 0);
      double largest_later = 0.0;
      const int steps = static_cast<int>(std::lround(3.0 / dt));
      for (int i = 0; i < steps; ++i) {
        const TipCommand c = controller.command(i * dt, dt, tip, velocity);
        ASSERT_LE(std::abs(c.position.y()), std::abs(tip.y()) + 1e-15) << "kd " << kd << " dt " << dt << " step " << i;
        velocity = c.velocity;
        tip = c.position;
        if (i > steps / 2) largest_later = std::max(largest_later, std::abs(tip.y()));
      }
      EXPECT_LT(largest_later, 1e-4) << "kd " << kd << " dt " << dt;
    }
  }
}

TEST(TipController, FieldModePointsAlongThePathAhead) {
  const Trajectory path({Vec2(0, 0), Vec2(1, 0)}, 0.0, 0.1);
  ControlSpec spec = undisturbed();
  spec.mode = ActuationMode::kField;
  TipController controller(spec, path, TipPlant{0.005, 0.0});
  const TipCommand c = controller.command(0.0, 1e-3, Vec2(0, 0), Vec2(0, 0));
  EXPECT_NEAR(c.field.norm(), spec.field_strength, 1e-12);
  EXPECT_GT(c.field.x(), 0.99 * spec.field_strength);
}

}  // namespace
}  // namespace vascsim

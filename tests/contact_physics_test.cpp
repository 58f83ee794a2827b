// Wall contact and friction against closed-form references (docs/references.md):
//   - a rod resting on a wall under its weight: the contact forces balance the weight (statics);
//   - section 7, block on an incline: tan(theta) = 0.5, mu = 0.5 sticks, mu = 0.49 slides with
//     a = g (sin theta - mu cos theta) = 0.087743 m/s^2;
//   - section 7, rod on a rough floor pulled axially (Gazzola et al. 2018): no motion while
//     F <= mu m g, then a = (F - mu m g) / m.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/contact/wall_contact.h"
#include "sim/rod/loads.h"
#include "sim/run/compile.h"
#include "sim/step/stepper.h"

namespace vascsim {
namespace {

constexpr double kG = 9.81;

// A short PDMS rod (Table I section) lying along +x, its surface `gap` above a floor wall at y = 0.
struct FloorRig {
  Scene scene;
  Model model;
  ContactParams params;
  const WallContactModule* contact = nullptr;

  FloorRig(Vec2 gravity, double mu, double damping = 0.0) {
    scene.has_environment = false;
    scene.rod.nodes = 11;
    scene.rod.length = 0.1;
    scene.shape.start = Vec2(0.0, 0.0);
    scene.loads.gravity.enabled = true;
    scene.loads.gravity.acceleration = gravity;
    scene.loads.damping.enabled = damping > 0.0;
    scene.loads.damping.coefficient = damping;
    scene.solver.scheme = Scheme::kBackwardEuler;
    scene.solver.dt = 1e-3;
    scene.solver.rel_tol = 1e-9;
    scene.contact.friction = mu;
    model = *compile(scene);
    params = resolve_contact_params(scene.contact, model.rod);
    // The floor's surface sits half an activation distance below the rod's surface.
    const double floor = -(model.rod.outer_radius + 0.5 * params.g_hat);
    const std::vector<WallSegment> walls = {{Vec2(-10.0, floor - 0.01), Vec2(10.0, floor - 0.01), 0.02}};
    auto module = std::make_unique<WallContactModule>(walls, model.rod, params);
    contact = module.get();
    model.forces.push_back(std::move(module));
    if (mu > 0.0) model.forces.push_back(std::make_unique<WallFrictionModule>(walls, model.rod, params));
  }
  double mass() const { return model.rod.mass.sum(); }
  Vec2 mean_velocity(const State& s) const {
    Vec2 v = Vec2::Zero();
    for (int i = 0; i < model.nodes(); ++i) v += model.rod.mass[i] * s.velocity(i);
    return v / mass();
  }
  Vec2 contact_force(const State& s) const {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(model.dofs());
    ForceContext ctx;
    ctx.t = s.t;
    ctx.x = &s.x;
    ctx.v = &s.v;
    contact->add(ctx, f, nullptr);
    return f.reshaped(2, model.nodes()).rowwise().sum();
  }
  // Advances to time t_end; fails the test on a failed step.
  void advance(State& s, Workspace& ws, double t_end, const Controls& controls = {}) const {
    while (s.t < t_end - 1e-12) {
      const StepReport r = step(model, s, ws, controls, std::min(scene.solver.dt, t_end - s.t));
      ASSERT_TRUE(r.ok) << r.failure;
    }
  }
};

TEST(ContactPhysics, RestingRodContactBalancesItsWeightWithinOnePercent) {
  FloorRig rig(Vec2(0.0, -kG), 0.0, /*damping N s/m^2=*/0.05);
  State s = initial_state(rig.model);
  Workspace ws(rig.model);
  rig.advance(s, ws, 2.0);
  ASSERT_LT(rig.mean_velocity(s).norm(), 1e-6);
  const Vec2 contact = rig.contact_force(s);
  const double weight = rig.mass() * kG;
  EXPECT_NEAR(contact.y(), weight, 0.01 * weight);
  EXPECT_NEAR(contact.x(), 0.0, 1e-6 * weight);
}

// Incline: the floor stays horizontal and gravity tilts by theta, tan(theta) = 0.5.
Vec2 incline_gravity() {
  const double theta = std::atan(0.5);
  return Vec2(kG * std::sin(theta), -kG * std::cos(theta));
}

// The rod first settles onto the floor under the normal part of gravity alone, so that the
// incline starts from rest with the normal force already in balance (an initial bounce would
// start a slide that mu = tan(theta) can never stop: kinetic friction then equals the pull).
State settled_on_incline(const FloorRig& tilted) {
  FloorRig flat(Vec2(0.0, incline_gravity().y()), tilted.scene.contact.friction, 0.05);
  State s = initial_state(flat.model);
  Workspace ws(flat.model);
  flat.advance(s, ws, 1.0);
  s.v.setZero();
  s.t = 0.0;
  return s;
}

TEST(ContactPhysics, InclineSticksAtMuHalf) {
  FloorRig rig(incline_gravity(), 0.5);
  State s = settled_on_incline(rig);
  Workspace ws(rig.model);
  rig.advance(s, ws, 1.0);
  // Regularised friction creeps below the slip velocity instead of sticking exactly.
  EXPECT_LT(std::abs(rig.mean_velocity(s).x()), rig.params.slip_velocity);
  const double x0 = s.position(0).x();
  rig.advance(s, ws, 2.0);
  EXPECT_LT(std::abs(s.position(0).x() - x0), rig.params.slip_velocity * 1.0);
}

TEST(ContactPhysics, InclineSlidesAtMuPointFortyNineWithTheReferenceAcceleration) {
  FloorRig rig(incline_gravity(), 0.49);
  State s = settled_on_incline(rig);
  Workspace ws(rig.model);
  rig.advance(s, ws, 1.0);
  const double v1 = rig.mean_velocity(s).x();
  rig.advance(s, ws, 2.0);
  const double v2 = rig.mean_velocity(s).x();
  const double expected = 0.087743;  // docs/references.md section 7
  EXPECT_NEAR(v2 - v1, expected, 0.02 * expected);
}

TEST(ContactPhysics, RodPulledAlongAFloorSticksThenSlides) {
  const double mu = 0.3;
  for (double load : {0.9, 2.0}) {
    FloorRig rig(Vec2(0.0, -kG), mu);
    const double threshold = mu * rig.mass() * kG;
    PointLoadSpec pull;
    pull.node = -1;
    pull.force = Vec2(load * threshold, 0.0);
    rig.model.forces.push_back(std::make_unique<PointLoadModule>(rig.model.nodes(), std::vector<PointLoadSpec>{pull}));
    State s = initial_state(rig.model);
    Workspace ws(rig.model);
    rig.advance(s, ws, 0.5);
    const double v1 = rig.mean_velocity(s).x();
    rig.advance(s, ws, 1.5);
    const double v2 = rig.mean_velocity(s).x();
    if (load < 1.0) {
      EXPECT_LT(std::abs(v2), rig.params.slip_velocity) << "should stick at F = " << load << " mu m g";
    } else {
      const double expected = (load * threshold - threshold) / rig.mass();
      EXPECT_NEAR(v2 - v1, expected, 0.02 * expected) << "F = " << load << " mu m g";
    }
  }
}

}  // namespace
}  // namespace vascsim

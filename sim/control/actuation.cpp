#include "sim/control/actuation.h"

#include <algorithm>

#include "sim/control/tip_magnet_module.h"
#include "sim/control/tip_servo_module.h"

namespace vascsim {

namespace {

// Force mode: the PD-controlled magnetic force on the tip node(s), applied implicitly inside
// Newton (TipServoModule): at the step's end t + dt it acts with the reference's position and
// velocity at t + dt, so the force does not depend on the step size (a secant velocity over the
// step would, and error control would see that as an error that no step is short enough to fix).
class ForceActuation : public Actuation {
 public:
  explicit ForceActuation(const ControlSpec& spec) : spec_(spec) {}
  std::vector<std::shared_ptr<const ForceModule>> modules(int nodes) const override {
    return {std::make_shared<TipServoModule>(nodes)};
  }
  void set_controls(const TipCommand& c, const ActuationStep& s, Controls& controls) const override {
    TipServo& servo = controls.servo;
    servo.active = true;
    servo.first_node = s.nodes - std::min(spec_.actuated_nodes, s.nodes);
    servo.feedforward = c.feedforward;
    servo.velocity = c.reference_velocity;
    servo.position = c.reference - servo.velocity * s.dt;
    servo.kp = spec_.kp;
    servo.kd = spec_.kd;
  }

 protected:
  ControlSpec spec_;
};

// Field mode: the servo's force, plus the tip magnet's torque in the field the controller sets.
class FieldActuation : public ForceActuation {
 public:
  using ForceActuation::ForceActuation;
  std::vector<std::shared_ptr<const ForceModule>> modules(int nodes) const override {
    return {std::make_shared<TipServoModule>(nodes), std::make_shared<TipMagnetModule>(nodes, spec_.magnet_moment)};
  }
  void set_controls(const TipCommand& c, const ActuationStep& s, Controls& controls) const override {
    controls.field = c.field;
    ForceActuation::set_controls(c, s, controls);
  }
};

// Kinematic mode (paper III.B): the tip follows the commanded motion exactly, as a prescribed
// node; the force it reports is the controller's estimate of what that motion takes.
class KinematicActuation : public Actuation {
 public:
  std::vector<std::shared_ptr<const ForceModule>> modules(int) const override { return {}; }
  void set_controls(const TipCommand& c, const ActuationStep& s, Controls& controls) const override {
    const Vec2 end = c.position + s.tip_offset;
    controls.targets.push_back({s.nodes - 1, s.tip, (end - s.tip) / s.dt});
  }
  void logged_force(const TipCommand& last, Eigen::Ref<Eigen::VectorXd> f) const override {
    f.tail<2>() = last.force;
  }
};

// No tip actuation: the tip goes where the body takes it (a catheter pushed from its root).
class NoActuation : public Actuation {
 public:
  std::vector<std::shared_ptr<const ForceModule>> modules(int) const override { return {}; }
  void set_controls(const TipCommand&, const ActuationStep&, Controls&) const override {}
};

}  // namespace

std::shared_ptr<const Actuation> make_actuation(const ControlSpec& spec) {
  switch (spec.mode) {
    case ActuationMode::kNone: return std::make_shared<NoActuation>();
    case ActuationMode::kForce: return std::make_shared<ForceActuation>(spec);
    case ActuationMode::kField: return std::make_shared<FieldActuation>(spec);
    case ActuationMode::kKinematic: return std::make_shared<KinematicActuation>();
  }
  return std::make_shared<ForceActuation>(spec);
}

}  // namespace vascsim

#include "sim/control/tip_controller.h"

#include <cmath>

namespace vascsim {

TipController::TipController(const ControlSpec& spec, const Trajectory& trajectory, const TipPlant& plant)
    : spec_(spec), trajectory_(trajectory), plant_(plant) {}

Vec2 TipController::disturbance(double t) const {
  return spec_.disturbance.amplitude * std::sin(spec_.disturbance.omega * t) * spec_.disturbance.direction;
}

TipCommand TipController::command(double t, double dt, const Vec2& tip_position, const Vec2& tip_velocity) const {
  TipCommand c;
  const double t_next = t + dt;
  const double tau = reference_time(t_next);
  c.reference = trajectory_.position(tau);
  // Before the reference starts and after it ends the target is at rest.
  const bool moving = tau > 0.0 && tau < trajectory_.duration();
  c.reference_velocity = moving ? trajectory_.velocity(tau) : Vec2::Zero();
  const Vec2 reference_acceleration = moving ? trajectory_.acceleration(tau) : Vec2::Zero();
  // Algorithm 1: errors against the committed state of the previous step.
  c.error = c.reference - tip_position;
  const Vec2 velocity_error = c.reference_velocity - tip_velocity;

  if (spec_.mode == ActuationMode::kKinematic) {
    // Algorithm 1 lines 7-10: q_new = ref_q + Kp e + Kd de/dt, v_new = (q_new - q) / dt. Kp is
    // dimensionless and Kd in seconds here: the correction is a position. The velocity error is
    // taken at the end of the step, v_ref - v_new, not from the last step as the paper writes it:
    // the tip is imposed, so its last velocity is this controller's own last command, and the
    // explicit term fed it back with the gain Kd/dt (unstable once Kd > dt (1 - Kp) / 2, any Kd
    // at small steps). Solved for q_new with a = Kd/dt, the error shrinks by (a - Kp)/(1 + a) per
    // step whatever the step; Kd then acts as a lag of time constant Kd/(1 + Kp).
    const double a = spec_.kd / dt;
    c.position = (c.reference + spec_.kp * c.error + spec_.kd * c.reference_velocity + a * tip_position) / (1.0 + a);
    c.velocity = (c.position - tip_position) / dt;
    // Reported actuation force (paper III.B): what drives the tip along its commanded motion.
    const double speed = c.velocity.norm();
    c.force = plant_.mass * (c.velocity - tip_velocity) / dt + plant_.drag_coefficient * speed * c.velocity;
    return c;
  }
  // Force and field modes: feedforward (reference acceleration and drag at the reference speed)
  // plus PD on the error. The feedforward alone moves an undisturbed, unloaded tip exactly along
  // the reference; the PD terms reject the disturbance and the pull of the body.
  const double reference_speed = c.reference_velocity.norm();
  c.feedforward = plant_.mass * reference_acceleration + plant_.drag_coefficient * reference_speed * c.reference_velocity;
  c.force = c.feedforward + spec_.kp * c.error + spec_.kd * velocity_error;
  if (spec_.mode == ActuationMode::kField) {
    // Point the field where the path heads a short way ahead; the dipole torque m x B then turns
    // the tip into the channel before the body reaches the corner.
    const double lookahead = std::max(4.0 * dt, 0.5);  // s
    Vec2 heading = trajectory_.position(tau + lookahead) - tip_position;
    if (heading.norm() < 1e-12) heading = c.reference_velocity;
    if (heading.norm() > 1e-12) c.field = spec_.field_strength * heading.normalized();
  }
  return c;
}

}  // namespace vascsim

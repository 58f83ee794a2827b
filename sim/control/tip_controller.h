// The trajectory-following controller of the paper's Algorithm 1 (decentralised feedforward PD on
// the tip), computed BEFORE each step from the committed state, so it can be tested without a
// stepper. It only reads the reference trajectory and the tip's state; what it returns is applied
// by the actuation module (force and field modes) or imposed as the tip's motion (kinematic mode).
#pragma once

#include "sim/env/geometry.h"
#include "sim/env/trajectory.h"
#include "sim/scene/scene.h"

namespace vascsim {

// What the controller needs to know about the plant for its feedforward terms.
struct TipPlant {
  double mass = 0.0;              // kg, mass the tip force accelerates (feedforward m a_ref)
  double drag_coefficient = 0.0;  // kg/m, c in f = -c |v| v (1/2 rho A Cd), 0 without drag
};

struct TipCommand {
  Vec2 reference = Vec2::Zero();           // m, reference tip position at the step's end time
  Vec2 reference_velocity = Vec2::Zero();  // m/s
  Vec2 error = Vec2::Zero();               // m, reference - tip at the start of the step
  // Force and field modes: the total magnetic force on the tip node(s) if the PD terms act on the
  // state at the start of the step, N; `feedforward` is its part that does not depend on the state.
  // The stepper applies feedforward + PD implicitly instead (TipServo). Kinematic mode: the
  // force estimate of paper III.B (drag compensation plus the PD correction).
  Vec2 force = Vec2::Zero();
  Vec2 feedforward = Vec2::Zero();
  // Kinematic mode: the tip's imposed position and velocity at the step's end, m and m/s.
  Vec2 position = Vec2::Zero();
  Vec2 velocity = Vec2::Zero();
  // Field mode: the uniform field B (T), chosen to turn the tip towards where the path goes.
  Vec2 field = Vec2::Zero();
};

class TipController {
 public:
  TipController(const ControlSpec& spec, const Trajectory& trajectory, const TipPlant& plant);

  // Command for the step from t to t + dt, given the committed tip state at t.
  TipCommand command(double t, double dt, const Vec2& tip_position, const Vec2& tip_velocity) const;
  // The disturbance the plant receives at time t (force in N or position offset in m).
  Vec2 disturbance(double t) const;
  // The disturbance as a displacement of the tip (m) when it is one (disturbance kind
  // "position"), else zero.
  Vec2 position_disturbance(double t) const {
    return spec_.disturbance.kind == DisturbanceKind::kPosition ? disturbance(t) : Vec2::Zero();
  }
  // Reference time on the trajectory for simulation time t (the reference may start late).
  double reference_time(double t) const { return t - spec_.lead_time; }
  const ControlSpec& spec() const { return spec_; }

 private:
  ControlSpec spec_;
  const Trajectory& trajectory_;
  TipPlant plant_;
};

}  // namespace vascsim

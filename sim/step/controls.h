// Controls: the inputs a controller sets BEFORE each step (STYLE.md example 10), held constant
// over the step. The stepper reads them; a controller can be tested without a stepper.
//   - targets move nodes kinematically: x(t) = position + velocity (t - time) during the step,
//     so an adaptive retry with a shorter dt stays on the commanded motion.
#pragma once

#include <vector>

#include "sim/env/geometry.h"

namespace vascsim {

struct NodeForce {
  int node = 0;               // 0-based; negative counts from the tip (-1 = tip)
  Vec2 force = Vec2::Zero();  // N
};

struct NodeTarget {
  int node = 0;                  // 0-based; negative counts from the tip
  Vec2 position = Vec2::Zero();  // m, at Controls::time
  Vec2 velocity = Vec2::Zero();  // m/s
};

// The magnetic tip servo (force and field actuation modes): on the nodes `first_node` to the tip,
// F = feedforward + kp (r(t) - x_mean) + kd (velocity - v_mean), split equally, with the
// reference r(t) = position + velocity (t - Controls::time). The PD terms are evaluated at the
// end of the step, inside Newton (implicitly), as a continuous controller acts; evaluated at
// the start of the step they diverge once kd dt / m > 2, which a light tip reaches at once.
struct TipServo {
  bool active = false;
  int first_node = 0;                 // first actuated node; the tip is the last
  Vec2 feedforward = Vec2::Zero();    // N
  Vec2 position = Vec2::Zero();       // m, reference at Controls::time
  Vec2 velocity = Vec2::Zero();       // m/s, reference velocity over the step
  double kp = 0.0;                    // N/m
  double kd = 0.0;                    // N s/m
};

struct Controls {
  double time = 0.0;  // s, time at which `targets` positions hold (usually State::t)
  std::vector<NodeTarget> targets;
  TipServo servo;
  // Wall contact forces decided outside Newton (the paper's iterative penalty contact mode).
  std::vector<NodeForce> wall_forces;
  Vec2 field = Vec2::Zero();  // T, uniform magnetic field on the tip magnet (field actuation mode)
};

}  // namespace vascsim

// Controls: the inputs a controller sets BEFORE each step (STYLE.md example 10), held constant
// over the step. The stepper reads them; a controller can be tested without a stepper.
//   - forces act on nodes through ControlForceModule (log channel force/actuation);
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

struct Controls {
  double time = 0.0;  // s, time at which `targets` positions hold (usually State::t)
  std::vector<NodeForce> forces;
  std::vector<NodeTarget> targets;
};

}  // namespace vascsim

// How the controller's command reaches the rod: one implementation per actuation mode (scene
// control.mode: force, field, kinematic), behind one interface. Each says which force modules
// compile() adds, what a step's Controls carry, and what the log and the statistics report as
// the magnetic force, so the run loop never checks the mode itself.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "sim/control/tip_controller.h"
#include "sim/scene/scene.h"
#include "sim/step/controls.h"
#include "sim/step/force_module.h"

namespace vascsim {

// What the run knows at the start of a step, beside the controller's command.
struct ActuationStep {
  double dt = 0.0;                     // s
  int nodes = 0;
  Vec2 tip = Vec2::Zero();             // m, the committed tip position
  Vec2 tip_offset = Vec2::Zero();      // m, a position disturbance at the step's end (kinematic)
};

class Actuation {
 public:
  virtual ~Actuation() = default;
  // The force modules this mode needs, for a rod of `nodes` nodes.
  virtual std::vector<std::shared_ptr<const ForceModule>> modules(int nodes) const = 0;
  // Writes the command into the step's controls.
  virtual void set_controls(const TipCommand& command, const ActuationStep& step, Controls& controls) const = 0;
  // The magnetic force per node (2N, N) to log and report at a committed state: `modules_force`
  // arrives as the sum of this mode's modules; a mode without modules puts its estimate there.
  virtual void logged_force(const TipCommand& last, Eigen::Ref<Eigen::VectorXd> modules_force) const {
    (void)last;
    (void)modules_force;
  }
};

// The actuation of `spec.mode`.
std::shared_ptr<const Actuation> make_actuation(const ControlSpec& spec);

}  // namespace vascsim

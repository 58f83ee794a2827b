// Applies Controls::servo: the PD-controlled magnetic force on the tip node(s), implicitly
// (see TipServo). With k actuated nodes and x_mean their mean position,
//   F_i = (f_ff + kp (r - x_mean) + kd (v_r - v_mean)) / k,
//   K_ij = (kp + kd dv_dx) / k^2 I   for i, j actuated (at most 3 nodes, to stay in the band).
// Channel force/actuation.
#pragma once

#include "sim/log/channel_names.h"
#include "sim/step/force_module.h"

namespace vascsim {

class TipServoModule : public ForceModule {
 public:
  explicit TipServoModule(int nodes) : nodes_(nodes) {}
  std::string channel() const override { return channel::kActuationForce; }
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;
  static constexpr int kMaxActuatedNodes = 3;

 private:
  int nodes_;
};

}  // namespace vascsim

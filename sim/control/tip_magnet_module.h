// The tip magnet as a force module (field actuation mode): the Zeeman energy of
// tip_magnet_energy.h on the distal edge, in the field the controller set in Controls::field.
// Channel force/actuation (the torque appears as a force couple on the last two nodes).
#pragma once

#include "sim/control/tip_magnet_energy.h"
#include "sim/log/channel_names.h"
#include "sim/step/force_module.h"

namespace vascsim {

class TipMagnetModule : public ForceModule {
 public:
  TipMagnetModule(int nodes, double moment) : nodes_(nodes), moment_(moment) {}
  std::string channel() const override { return channel::kActuationForce; }
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override {
    if (!ctx.controls || ctx.controls->field.isZero()) return;
    const int first = 2 * (nodes_ - 2);
    const EdgeEnergy e = tip_magnet_energy(ctx.x->segment<2>(first), ctx.x->segment<2>(first + 2), moment_,
                                           ctx.load_scale * ctx.controls->field);
    force.segment<4>(first) -= e.gradient;
    if (stiffness) stiffness->add_block<4>(first, e.hessian);
  }

 private:
  int nodes_;
  double moment_;  // A m^2
};

}  // namespace vascsim

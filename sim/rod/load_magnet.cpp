#include "sim/control/tip_magnet_energy.h"
#include "sim/rod/loads.h"

namespace vascsim {

void MagnetLoadModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const {
  const Vec2 field = ctx.load_scale * spec_.field_at(ctx.t);
  if (field.isZero()) return;
  const int first = 2 * (nodes_ - 2);
  const EdgeEnergy e = tip_magnet_energy(ctx.x->segment<2>(first), ctx.x->segment<2>(first + 2), spec_.moment, field);
  force.segment<4>(first) -= e.gradient;
  if (stiffness) stiffness->add_block<4>(first, e.hessian);
}

}  // namespace vascsim

#include "sim/log/channel_names.h"
#include "sim/rod/loads.h"

namespace vascsim {

std::string GravityModule::channel() const { return channel::kExternalForce; }

// Constant in x: no stiffness.
void GravityModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix*) const {
  const Vec2 g = ctx.load_scale * g_;
  for (int i = 0; i < mass_.size(); ++i) force.segment<2>(2 * i) += mass_[i] * g;
}

}  // namespace vascsim

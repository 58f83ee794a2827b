#include "sim/log/channel_names.h"
#include "sim/rod/loads.h"

namespace vascsim {

std::string ControlForceModule::channel() const { return channel::kActuationForce; }

void ControlForceModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix*) const {
  if (!ctx.controls) return;
  for (const auto& f : ctx.controls->forces) {
    const int node = f.node < 0 ? f.node + nodes_ : f.node;
    if (node < 0 || node >= nodes_) continue;
    force.segment<2>(2 * node) += ctx.load_scale * f.force;
  }
}

}  // namespace vascsim

#include "sim/contact/paper_contact.h"

#include <algorithm>

namespace vascsim {

void ExplicitWallForceModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix*) const {
  if (!ctx.controls) return;
  for (const auto& f : ctx.controls->wall_forces)
    if (f.node >= 0 && f.node < nodes_) force.segment<2>(2 * f.node) += f.force;
}

PaperContactUpdate paper_contact_update(const WallDistanceField& walls, double rod_radius, double gain,
                                        const Eigen::VectorXd& x, std::vector<NodeForce>& forces) {
  PaperContactUpdate out;
  const int nodes = static_cast<int>(x.size() / 2);
  forces.resize(static_cast<std::size_t>(nodes));
  const double reach = std::min(walls.max_query_radius(), 4.0 * rod_radius);
  WallHit hit;
  out.settled = true;
  for (int i = 0; i < nodes; ++i) {
    NodeForce& f = forces[static_cast<std::size_t>(i)];
    f.node = i;
    if (!walls.nearest(x.segment<2>(2 * i), reach, hit)) {
      f.force.setZero();  // far from every wall: no contact
      continue;
    }
    const double gap = hit.distance - rod_radius;  // < 0: the rod's surface is inside the wall
    if (gap < 0.0) {
      out.settled = false;
      out.max_depth = std::max(out.max_depth, -gap);
    }
    // Projected update of the force along the current normal: up by K_f per metre of depth,
    // down by K_f per metre of clearance, never pulling (magnitude >= 0).
    const double magnitude = std::max(0.0, f.force.dot(hit.normal) - gain * gap);
    f.force = magnitude * hit.normal;
  }
  return out;
}

}  // namespace vascsim

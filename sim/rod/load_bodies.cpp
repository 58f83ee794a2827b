#include "sim/rod/loads.h"
#include "sim/step/banded_matrix.h"
#include "sim/step/model.h"

namespace vascsim {

BodyDragModule::BodyDragModule(int nodes, const std::vector<BodySpec>& bodies) : bodies_(bodies) {
  for (auto& b : bodies_) b.node = resolve_node(b.node, nodes);
}

void BodyDragModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const {
  for (const auto& b : bodies_) {
    const Vec2 v = ctx.v->segment<2>(2 * b.node);
    const double speed = v.norm();
    force.segment<2>(2 * b.node) -= (b.linear_drag + b.quadratic_drag * speed) * v;
    if (stiffness && ctx.dv_dx > 0.0) {
      Eigen::Matrix2d k = (b.linear_drag + b.quadratic_drag * speed) * Eigen::Matrix2d::Identity();
      if (speed > 0.0) k += b.quadratic_drag * v * v.transpose() / speed;
      stiffness->add_block<2>(2 * b.node, ctx.dv_dx * k);
    }
  }
}

}  // namespace vascsim

#include <cmath>

#include "sim/log/channel_names.h"
#include "sim/rod/loads.h"

namespace vascsim {

QuadraticDragModule::QuadraticDragModule(const RodModel& rod, const DragSpec& spec) {
  const double half_rho_cd = 0.5 * spec.fluid_density * spec.drag_coefficient;
  if (spec.area == DragArea::kNodes) {
    c_ = half_rho_cd * 2.0 * rod.outer_radius * rod.voronoi;
  } else {
    c_ = Eigen::VectorXd::Zero(rod.nodes);
    c_[rod.nodes - 1] = half_rho_cd * M_PI * rod.outer_radius * rod.outer_radius;
  }
}

std::string QuadraticDragModule::channel() const { return channel::kDragForce; }

void QuadraticDragModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force,
                              BandedMatrix* stiffness) const {
  const Eigen::VectorXd& v = *ctx.v;
  for (int i = 0; i < c_.size(); ++i) {
    if (c_[i] == 0.0) continue;
    const Vec2 vi = v.segment<2>(2 * i);
    const double speed = vi.norm();
    force.segment<2>(2 * i) -= c_[i] * speed * vi;
    if (stiffness && speed > 0.0) {
      Eigen::Matrix2d k = c_[i] * ctx.dv_dx * (speed * Eigen::Matrix2d::Identity() + vi * vi.transpose() / speed);
      stiffness->add_block<2>(2 * i, k);
    }
  }
}

}  // namespace vascsim

#include <cmath>

#include "sim/log/channel_names.h"
#include "sim/rod/loads.h"

namespace vascsim {

PointLoadModule::PointLoadModule(int nodes, const std::vector<PointLoadSpec>& loads) : loads_(loads), nodes_(nodes) {
  for (auto& l : loads_)
    if (l.node < 0) l.node += nodes;
}

std::string PointLoadModule::channel() const { return channel::kExternalForce; }

double PointLoadModule::profile(const PointLoadSpec& load, double t) {
  switch (load.profile) {
    case LoadProfile::kConstant: return 1.0;
    case LoadProfile::kRamp: return load.ramp_time > 0.0 ? std::min(1.0, t / load.ramp_time) : 1.0;
    case LoadProfile::kSine: return std::sin(2.0 * M_PI * load.frequency * t + load.phase);
  }
  return 1.0;
}

void PointLoadModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const {
  const Eigen::VectorXd& x = *ctx.x;
  for (const auto& l : loads_) {
    const double s = ctx.load_scale * profile(l, ctx.t);
    force.segment<2>(2 * l.node) += s * l.force;
    if (l.moment == 0.0) continue;
    // The edge ending at the node (edge 0 for node 0), a -> b.
    const int a = l.node == 0 ? 0 : l.node - 1;
    const Vec2 e = x.segment<2>(2 * a + 2) - x.segment<2>(2 * a);
    const double r = e.squaredNorm();
    const double m = s * l.moment;
    const Vec2 fb = m * Vec2(-e.y(), e.x()) / r;
    force.segment<2>(2 * a) -= fb;
    force.segment<2>(2 * a + 2) += fb;
    if (stiffness) {
      // K = -dF/dx = -M d2theta/dx2 (F = M dtheta/dx); d2theta/de2 as in elastic_energy.h.
      Eigen::Matrix2d h;
      h << 2.0 * e.x() * e.y(), e.y() * e.y() - e.x() * e.x(), e.y() * e.y() - e.x() * e.x(), -2.0 * e.x() * e.y();
      h *= -m / (r * r);
      Eigen::Matrix4d k;
      k << h, -h, -h, h;
      stiffness->add_block<4>(2 * a, k);
    }
  }
}

}  // namespace vascsim

#include "sim/rod/loads.h"

namespace vascsim {

void ViscousDampingModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force,
                               BandedMatrix* stiffness) const {
  const Eigen::VectorXd& v = *ctx.v;
  for (int i = 0; i < c_.size(); ++i) {
    force.segment<2>(2 * i) -= c_[i] * v.segment<2>(2 * i);
    if (stiffness) {
      stiffness->add_diagonal(2 * i, c_[i] * ctx.dv_dx);
      stiffness->add_diagonal(2 * i + 1, c_[i] * ctx.dv_dx);
    }
  }
}

}  // namespace vascsim

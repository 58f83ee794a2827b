#include "sim/control/tip_servo_module.h"

#include <algorithm>

namespace vascsim {

void TipServoModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const {
  if (!ctx.controls || !ctx.controls->servo.active) return;
  const TipServo& s = ctx.controls->servo;
  const int first = std::max(s.first_node, nodes_ - kMaxActuatedNodes);
  const int k = nodes_ - first;
  Vec2 x_mean = Vec2::Zero(), v_mean = Vec2::Zero();
  for (int i = first; i < nodes_; ++i) {
    x_mean += ctx.x->segment<2>(2 * i);
    v_mean += ctx.v->segment<2>(2 * i);
  }
  x_mean /= k;
  v_mean /= k;
  const Vec2 reference = s.position + s.velocity * (ctx.t - ctx.controls->time);
  const Vec2 total = ctx.load_scale * s.feedforward + s.kp * (reference - x_mean) + s.kd * (s.velocity - v_mean);
  for (int i = first; i < nodes_; ++i) force.segment<2>(2 * i) += total / k;
  if (!stiffness) return;
  const double diagonal = (s.kp + s.kd * ctx.dv_dx) / (k * k);
  Eigen::Matrix<double, 6, 6> block = Eigen::Matrix<double, 6, 6>::Zero();
  for (int a = 0; a < k; ++a)
    for (int b = 0; b < k; ++b) block.block<2, 2>(2 * a, 2 * b) = diagonal * Eigen::Matrix2d::Identity();
  if (k == 1) stiffness->add_block<2>(2 * first, Eigen::Matrix2d(block.block<2, 2>(0, 0)));
  else if (k == 2) stiffness->add_block<4>(2 * first, Eigen::Matrix4d(block.block<4, 4>(0, 0)));
  else stiffness->add_block<6>(2 * first, block);
}

}  // namespace vascsim

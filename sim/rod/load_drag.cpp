#include <algorithm>
#include <cmath>
#include <memory>

#include "sim/log/channel_names.h"
#include "sim/rod/loads.h"

namespace vascsim {

namespace {

// Unit tangents at the nodes of the polyline x + h v (2N; m, m/s, s), into `tangents` (2 x N):
// the mean direction of a node's two edges, or its one edge at the ends and where the rod folds
// back on itself (the mean vanishes there). Each edge's direction is computed once, and no moved
// copy of the rod is made on this hot path.
void node_tangents(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double h, Eigen::Matrix2Xd& tangents) {
  const int nodes = static_cast<int>(x.size() / 2);
  tangents.resize(2, nodes);
  Vec2 behind(1.0, 0.0);
  for (int e = 0; e + 1 < nodes; ++e) {
    Vec2 d = x.segment<2>(2 * e + 2) - x.segment<2>(2 * e);
    if (h != 0.0) d += h * (v.segment<2>(2 * e + 2) - v.segment<2>(2 * e));
    const double length = d.norm();
    const Vec2 ahead = length > 0.0 ? Vec2(d / length) : Vec2(1.0, 0.0);
    if (e == 0) {
      tangents.col(0) = ahead;
    } else {
      const Vec2 mean = behind + ahead;
      const double mean_length = mean.norm();
      tangents.col(e) = mean_length > 1e-9 ? Vec2(mean / mean_length) : ahead;
    }
    behind = ahead;
  }
  tangents.col(nodes - 1) = behind;
}

}  // namespace

QuadraticDragModule::QuadraticDragModule(const RodModel& rod, const DragSpec& spec) {
  const double half_rho = 0.5 * spec.fluid_density;
  cross_flow_ = spec.area == DragArea::kNodes;
  if (cross_flow_) {
    const Eigen::VectorXd area = 2.0 * rod.outer_radius * rod.voronoi;  // m^2, projected
    c_ = half_rho * spec.drag_coefficient * area;
    c_tangential_ = half_rho * spec.tangential_coefficient * area;
  } else {
    c_ = Eigen::VectorXd::Zero(rod.nodes);
    c_[rod.nodes - 1] = half_rho * spec.drag_coefficient * M_PI * rod.outer_radius * rod.outer_radius;
    c_tangential_ = c_;
  }
}

std::string QuadraticDragModule::channel() const { return channel::kDragForce; }

std::unique_ptr<ModuleCache> QuadraticDragModule::make_cache() const {
  if (!cross_flow_) return nullptr;
  return std::make_unique<DragTangentCache>();
}

const Eigen::Matrix2Xd& QuadraticDragModule::step_tangents(const State& start, double h, DragTangentCache& cache) const {
  if (h == cache.h && start.x.size() == cache.start_x.size() && start.x == cache.start_x && start.v == cache.start_v)
    return cache.tangents;
  node_tangents(start.x, start.v, h, cache.tangents);
  cache.start_x = start.x;
  cache.start_v = start.v;
  cache.h = h;
  return cache.tangents;
}

void QuadraticDragModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force,
                              BandedMatrix* stiffness) const {
  if (cross_flow_) {
    add_cross_flow(ctx, force, stiffness);
  } else {
    add_isotropic(ctx, force, stiffness);
  }
}

void QuadraticDragModule::add_isotropic(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force,
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

void QuadraticDragModule::add_cross_flow(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force,
                                         BandedMatrix* stiffness) const {
  const Eigen::VectorXd& v = *ctx.v;
  // The tangents' configuration (loads.h): the step's start carried to its end.
  const double h = ctx.start ? ctx.t - ctx.start->t : 0.0;  // s, the step (0: a committed state)
  const int nodes = static_cast<int>(c_.size());
  DragTangentCache scratch;
  const Eigen::Matrix2Xd* tangents = &scratch.tangents;
  if (h > 0.0) {
    tangents = &step_tangents(*ctx.start, h, cache_or(ctx, scratch));
  } else {
    node_tangents(*ctx.x, v, 0.0, scratch.tangents);
  }
  for (int i = 0; i < nodes; ++i) {
    const Vec2 t = tangents->col(i);
    const Vec2 n(-t.y(), t.x());
    const Vec2 vi = v.segment<2>(2 * i);
    const double vt = vi.dot(t), vn = vi.dot(n);
    force.segment<2>(2 * i) -= c_[i] * std::abs(vn) * vn * n + c_tangential_[i] * std::abs(vt) * vt * t;
    if (stiffness) {
      Eigen::Matrix2d k = 2.0 * ctx.dv_dx * (c_[i] * std::abs(vn) * n * n.transpose() + c_tangential_[i] * std::abs(vt) * t * t.transpose());
      stiffness->add_block<2>(2 * i, k);
    }
  }
}

}  // namespace vascsim

#include "sim/contact/wall_contact.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "sim/contact/barrier.h"

namespace vascsim {

namespace {

// Projects a symmetric block onto the positive semi-definite cone (IPC's per-pair projection):
// the barrier's curvature term b' hess(d) is negative where the distance is convex, and an
// indefinite Newton matrix would let the solver walk uphill.
template <int Dim>
Eigen::Matrix<double, Dim, Dim> project_psd(const Eigen::Matrix<double, Dim, Dim>& m) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, Dim, Dim>> eig;
  // 2x2 (a node against a wall, nearly every pair) in closed form: the iterative QR it replaces
  // was 4 % of a traversal's time.
  if constexpr (Dim == 2) eig.computeDirect(m);
  else eig.compute(m);
  const auto clamped = eig.eigenvalues().cwiseMax(0.0);
  return eig.eigenvectors() * clamped.asDiagonal() * eig.eigenvectors().transpose();
}

double max_edge_length(const RodModel& rod) { return rod.rest_length.size() ? rod.rest_length.maxCoeff() : 0.0; }

}  // namespace

std::shared_ptr<const ContactGeometry> make_contact_geometry(const std::vector<WallSegment>& walls, const RodModel& rod,
                                                             const ContactParams& params) {
  return std::make_shared<const ContactGeometry>(walls, params.rod_radius, params.g_hat, 2.0 * max_edge_length(rod));
}

ContactNeighbours& run_neighbours(const ForceContext& ctx, const ContactGeometry& geometry, ContactNeighbours& fallback) {
  return ctx.shared ? ctx.shared->of<ContactNeighboursCache>(&geometry).lists : fallback;
}

struct WallFrictionModule::Cache : ModuleCache {
  Eigen::VectorXd start;          // m, the start state the pairs were found for
  std::vector<LaggedPair> pairs;
};

WallContactModule::WallContactModule(std::shared_ptr<const ContactGeometry> geometry, const ContactParams& params)
    : params_(params), geometry_(std::move(geometry)) {}

// E = sum over pairs of b(gap); gap = d(p, a, b) - t/2 - r, so
//   F = -b'(gap) grad d,   K = b''(gap) grad d grad d^T + b'(gap) hess d   (projected to PSD).
void WallContactModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const {
  ContactNeighbours scratch;
  geometry_->for_each_pair(*ctx.x, stiffness != nullptr, [&](const ContactPair& pair) {
    const BarrierValue b = contact_barrier(pair.gap, params_.g_hat, params_.kappa);
    if (b.first == 0.0) return;
    if (!pair.is_edge) {
      const Eigen::Vector2d grad = pair.geometry.gradient.head<2>();
      force.segment<2>(pair.first_dof) -= b.first * grad;
      if (stiffness) {
        const Eigen::Matrix2d k = b.second * grad * grad.transpose() + b.first * pair.geometry.hessian.block<2, 2>(0, 0);
        stiffness->add_block<2>(pair.first_dof, project_psd<2>(k));
      }
    } else {
      const Eigen::Vector4d grad = pair.geometry.gradient.tail<4>();
      force.segment<4>(pair.first_dof) -= b.first * grad;
      if (stiffness) {
        const Eigen::Matrix4d k = b.second * grad * grad.transpose() + b.first * pair.geometry.hessian.block<4, 4>(2, 2);
        stiffness->add_block<4>(pair.first_dof, project_psd<4>(k));
      }
    }
  }, run_neighbours(ctx, *geometry_, scratch));
}

double WallContactModule::energy(const Eigen::VectorXd& x) const {
  double e = 0.0;
  ContactNeighbours neighbours;
  geometry_->for_each_pair(x, false, [&](const ContactPair& pair) {
    e += contact_barrier(pair.gap, params_.g_hat, params_.kappa).energy;
  }, neighbours);
  return e;
}

double WallContactModule::max_step_fraction(const ForceContext& ctx, const Eigen::VectorXd& dx) const {
  ContactNeighbours scratch;
  return geometry_->max_step_fraction(*ctx.x, dx, 0.8, run_neighbours(ctx, *geometry_, scratch));
}

bool WallContactModule::defined_at(const ForceContext& ctx) const {
  ContactNeighbours scratch;
  return geometry_->min_pair_gap(*ctx.x, run_neighbours(ctx, *geometry_, scratch)) > 0.0;
}

WallFrictionModule::WallFrictionModule(std::shared_ptr<const ContactGeometry> geometry, const ContactParams& params)
    : params_(params), geometry_(std::move(geometry)) {}

std::unique_ptr<ModuleCache> WallFrictionModule::make_cache() const { return std::make_unique<Cache>(); }

const std::vector<WallFrictionModule::LaggedPair>& WallFrictionModule::lagged_pairs(const Eigen::VectorXd& start, Cache& c,
                                                                                    ContactNeighbours& lists) const {
  if (start.size() == c.start.size() && start == c.start) return c.pairs;
  c.start = start;
  c.pairs.clear();
  geometry_->for_each_pair(start, false, [&](const ContactPair& pair) {
    const double lambda = -contact_barrier(pair.gap, params_.g_hat, params_.kappa).first;  // N
    if (lambda > 0.0) c.pairs.push_back({pair.first_dof, lambda, Eigen::Vector2d(-pair.normal.y(), pair.normal.x())});
  }, lists, /*nodes_only=*/true);
  return c.pairs;
}

void WallFrictionModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const {
  // Friction opposes sliding: with v = 0 (statics) f1(0) = 0 and it vanishes by itself. Not
  // skipped when dv_dx = 0, which is also how a frame's forces at a committed state are asked for.
  if (!ctx.start) return;
  const double eps = params_.slip_velocity;
  Cache scratch;
  ContactNeighbours scratch_lists;
  for (const LaggedPair& pair : lagged_pairs(ctx.start->x, cache_or(ctx, scratch), run_neighbours(ctx, *geometry_, scratch_lists))) {
    const double vt = pair.tangent.dot(ctx.v->segment<2>(pair.first_dof));
    const double y = std::abs(vt) / eps;
    const double f1 = y < 1.0 ? 2.0 * y - y * y : 1.0;
    const double scale = params_.friction * pair.lambda;
    force.segment<2>(pair.first_dof) -= scale * f1 * (vt >= 0.0 ? 1.0 : -1.0) * pair.tangent;
    if (stiffness && y < 1.0) {
      const double slope = scale * (2.0 - 2.0 * y) / eps;  // d|F|/d|v_t|
      stiffness->add_block<2>(pair.first_dof, Eigen::Matrix2d(slope * ctx.dv_dx * pair.tangent * pair.tangent.transpose()));
    }
  }
}

}  // namespace vascsim

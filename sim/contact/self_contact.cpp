#include "sim/contact/self_contact.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "sim/contact/barrier.h"
#include "sim/contact/point_segment_distance.h"
#include "sim/step/banded_matrix.h"

namespace vascsim {

namespace {

// A node is not tested against its own edges or their neighbours: along the rod they are held
// apart by the rod itself, and a bend sharper than that is the bending energy's business.
bool adjacent(int node, int edge) { return node >= edge - 1 && node <= edge + 2; }

}  // namespace

SelfContactModule::SelfContactModule(const RodModel& rod, const ContactParams& params)
    : nodes_(rod.nodes), thickness_(2.0 * rod.outer_radius), g_hat_(params.g_hat), kappa_(params.kappa) {}

std::vector<std::pair<int, int>> SelfContactModule::candidate_pairs(const Eigen::VectorXd& x, double reach) const {
  // Sweep and prune along x: each edge's x-interval, grown by `reach`, against the nodes' x.
  std::vector<int> order(static_cast<std::size_t>(nodes_));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return x[2 * a] < x[2 * b] || (x[2 * a] == x[2 * b] && a < b); });
  std::vector<double> sorted_x(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) sorted_x[k] = x[2 * order[k]];
  std::vector<std::pair<int, int>> pairs;
  for (int e = 0; e + 1 < nodes_; ++e) {
    const double lo = std::min(x[2 * e], x[2 * e + 2]) - reach, hi = std::max(x[2 * e], x[2 * e + 2]) + reach;
    const double ylo = std::min(x[2 * e + 1], x[2 * e + 3]) - reach, yhi = std::max(x[2 * e + 1], x[2 * e + 3]) + reach;
    for (auto it = std::lower_bound(sorted_x.begin(), sorted_x.end(), lo); it != sorted_x.end() && *it <= hi; ++it) {
      const int node = order[static_cast<std::size_t>(it - sorted_x.begin())];
      if (adjacent(node, e)) continue;
      if (x[2 * node + 1] < ylo || x[2 * node + 1] > yhi) continue;
      pairs.emplace_back(node, e);
    }
  }
  std::sort(pairs.begin(), pairs.end());  // the same order every time: deterministic sums
  return pairs;
}

void SelfContactModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const {
  const Eigen::VectorXd& x = *ctx.x;
  for (const auto& [node, edge] : candidate_pairs(x, thickness_ + g_hat_)) {
    const PointSegmentDistance d = point_segment_distance(x.segment<2>(2 * node), x.segment<2>(2 * edge),
                                                          x.segment<2>(2 * edge + 2), stiffness != nullptr);
    const double gap = d.distance - thickness_;
    if (gap >= g_hat_) continue;
    const BarrierValue b = contact_barrier(std::max(gap, 1e-300), g_hat_, kappa_);
    const int dofs[6] = {2 * node, 2 * node + 1, 2 * edge, 2 * edge + 1, 2 * edge + 2, 2 * edge + 3};
    for (int r = 0; r < 6; ++r) force[dofs[r]] -= b.first * d.gradient[r];
    if (!stiffness) continue;
    Eigen::Matrix<double, 6, 6> h = b.second * d.gradient * d.gradient.transpose() + b.first * d.hessian;
    // Positive semi-definite projection: clamp the negative eigenvalues to zero.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(h);
    h = eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).asDiagonal() * eig.eigenvectors().transpose();
    for (int r = 0; r < 6; ++r)
      for (int c = 0; c < 6; ++c) {
        const int i = dofs[r], j = dofs[c];
        if (i < j) continue;  // lower triangle
        if (i - j <= BandedMatrix::kHalfBandwidth) stiffness->lower(i, j) += h(r, c);
        else if (ctx.off_band) ctx.off_band->emplace_back(i, j, h(r, c));
      }
  }
}

double SelfContactModule::max_step_fraction(const ForceContext& ctx, const Eigen::VectorXd& dx) const {
  const Eigen::VectorXd& x = *ctx.x;
  double motion = 0.0;
  for (int i = 0; i < nodes_; ++i) motion = std::max(motion, dx.segment<2>(2 * i).norm());
  if (motion == 0.0) return 1.0;
  double alpha = 1.0;
  // A pair can close by at most twice the largest motion: only pairs within that can limit.
  for (const auto& [node, edge] : candidate_pairs(x, thickness_ + 2.0 * motion)) {
    const double gap = point_segment_distance(x.segment<2>(2 * node), x.segment<2>(2 * edge), x.segment<2>(2 * edge + 2), false)
                           .distance -
                       thickness_;
    const double closing = dx.segment<2>(2 * node).norm() +
                           std::max(dx.segment<2>(2 * edge).norm(), dx.segment<2>(2 * edge + 2).norm());
    if (closing > 0.0 && gap > 0.0) alpha = std::min(alpha, 0.8 * gap / closing);
  }
  return alpha;
}

}  // namespace vascsim

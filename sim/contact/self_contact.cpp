#include "sim/contact/self_contact.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "sim/contact/barrier.h"
#include "sim/contact/point_segment_distance.h"
#include "sim/step/banded_matrix.h"

namespace vascsim {

SelfContactModule::SelfContactModule(const RodModel& rod, const ContactParams& params)
    : nodes_(rod.nodes), thickness_(2.0 * rod.outer_radius), g_hat_(params.g_hat), kappa_(params.kappa) {
  arc_.assign(static_cast<std::size_t>(nodes_), 0.0);
  for (int i = 1; i < nodes_; ++i) arc_[static_cast<std::size_t>(i)] = arc_[static_cast<std::size_t>(i - 1)] + rod.rest_length[i - 1];
  // Straight, two points of the rod this far apart along it are this far apart in space: closer
  // ones would start inside each other's barrier (a fine mesh has edges much shorter than the
  // rod's thickness). Half as much again covers the bend a rod can make between them.
  exclusion_ = 1.5 * (thickness_ + g_hat_);
  // A margin of a quarter of the barrier's reach keeps the list below the exclusion, so a
  // straight stretch of rod, however finely meshed, puts no pairs in it.
  list_reach_ = 1.25 * (thickness_ + g_hat_);
}

struct SelfContactModule::Cache : ModuleCache {
  Eigen::VectorXd listed_at;                   // m, the positions the list was searched at
  std::vector<std::pair<int, int>> listed;     // candidate_pairs(listed_at, list_reach_)
  std::vector<std::pair<int, int>> filtered;   // the last call's pairs
};

std::unique_ptr<ModuleCache> SelfContactModule::make_cache() const { return std::make_unique<Cache>(); }

const std::vector<std::pair<int, int>>& SelfContactModule::pairs_within(const Eigen::VectorXd& x, double reach,
                                                                       Cache& cache) const {
  // A node-edge pair's bounding-box separation changes by at most twice the largest node motion.
  double moved = INFINITY;
  if (cache.listed_at.size() == x.size()) {
    moved = 0.0;
    for (int i = 0; i < nodes_; ++i) moved = std::max(moved, (x.segment<2>(2 * i) - cache.listed_at.segment<2>(2 * i)).norm());
  }
  if (reach + 2.0 * moved > list_reach_ * (1.0 - 1e-9)) {
    if (reach > list_reach_ * (1.0 - 1e-9)) {  // wider than any list: search afresh
      cache.filtered = candidate_pairs(x, reach);
      return cache.filtered;
    }
    cache.listed = candidate_pairs(x, list_reach_);
    cache.listed_at = x;
  }
  // The test candidate_pairs makes, on both axes (inclusive), so the same pairs in the same order.
  cache.filtered.clear();
  for (const auto& pair : cache.listed) {
    const int node = pair.first, e = pair.second;
    bool inside = true;
    for (int axis = 0; axis < 2 && inside; ++axis) {
      const double lo = std::min(x[2 * e + axis], x[2 * e + 2 + axis]) - reach;
      const double hi = std::max(x[2 * e + axis], x[2 * e + 2 + axis]) + reach;
      inside = x[2 * node + axis] >= lo && x[2 * node + axis] <= hi;
    }
    if (inside) cache.filtered.push_back(pair);
  }
  return cache.filtered;
}

bool SelfContactModule::adjacent(int node, int edge) const {
  if (node >= edge - 1 && node <= edge + 2) return true;
  const double along = node <= edge ? arc_[static_cast<std::size_t>(edge)] - arc_[static_cast<std::size_t>(node)]
                                    : arc_[static_cast<std::size_t>(node)] - arc_[static_cast<std::size_t>(edge + 1)];
  return along < exclusion_;
}

std::vector<std::pair<int, int>> SelfContactModule::candidate_pairs(const Eigen::VectorXd& x, double reach) const {
  // Sweep and prune along the longer side of the rod's bounding box (a rod along y would put
  // every node in every edge's x-interval): each edge's interval on that axis, grown by
  // `reach`, against the nodes sorted on it, then the other axis checked.
  const Eigen::Map<const Eigen::Matrix<double, 2, Eigen::Dynamic>> p(x.data(), 2, nodes_);
  const Eigen::Vector2d extent = p.rowwise().maxCoeff() - p.rowwise().minCoeff();
  const int a = extent.x() >= extent.y() ? 0 : 1, b = 1 - a;
  std::vector<int> order(static_cast<std::size_t>(nodes_));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int i, int j) { return p(a, i) < p(a, j) || (p(a, i) == p(a, j) && i < j); });
  std::vector<double> sorted(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = p(a, order[k]);
  std::vector<std::pair<int, int>> pairs;
  for (int e = 0; e + 1 < nodes_; ++e) {
    const double lo = std::min(p(a, e), p(a, e + 1)) - reach, hi = std::max(p(a, e), p(a, e + 1)) + reach;
    const double blo = std::min(p(b, e), p(b, e + 1)) - reach, bhi = std::max(p(b, e), p(b, e + 1)) + reach;
    for (auto it = std::lower_bound(sorted.begin(), sorted.end(), lo); it != sorted.end() && *it <= hi; ++it) {
      const int node = order[static_cast<std::size_t>(it - sorted.begin())];
      if (adjacent(node, e) || p(b, node) < blo || p(b, node) > bhi) continue;
      pairs.emplace_back(node, e);
    }
  }
  std::sort(pairs.begin(), pairs.end());  // the same order every time: deterministic sums
  return pairs;
}

void SelfContactModule::add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const {
  const Eigen::VectorXd& x = *ctx.x;
  Cache scratch;
  for (const auto& [node, edge] : pairs_within(x, thickness_ + g_hat_, cache_or(ctx, scratch))) {
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

std::optional<SelfContactModule::Overlap> SelfContactModule::first_overlap(const Eigen::VectorXd& x) const {
  for (const auto& [node, edge] : candidate_pairs(x, thickness_)) {
    const double d = point_segment_distance_value(x.segment<2>(2 * node), x.segment<2>(2 * edge), x.segment<2>(2 * edge + 2));
    if (d <= thickness_) return Overlap{node, edge, d};
  }
  return std::nullopt;
}

bool SelfContactModule::defined_at(const ForceContext& ctx) const { return !first_overlap(*ctx.x); }

double SelfContactModule::max_step_fraction(const ForceContext& ctx, const Eigen::VectorXd& dx) const {
  const Eigen::VectorXd& x = *ctx.x;
  double motion = 0.0;
  for (int i = 0; i < nodes_; ++i) motion = std::max(motion, dx.segment<2>(2 * i).norm());
  if (motion == 0.0) return 1.0;
  double alpha = 1.0;
  // A pair can close by at most twice the largest motion: only pairs within that can limit.
  Cache scratch;
  for (const auto& [node, edge] : pairs_within(x, thickness_ + 2.0 * motion, cache_or(ctx, scratch))) {
    const double gap =
        point_segment_distance_value(x.segment<2>(2 * node), x.segment<2>(2 * edge), x.segment<2>(2 * edge + 2)) - thickness_;
    const double closing = dx.segment<2>(2 * node).norm() +
                           std::max(dx.segment<2>(2 * edge).norm(), dx.segment<2>(2 * edge + 2).norm());
    if (closing > 0.0 && gap > 0.0) alpha = std::min(alpha, 0.8 * gap / closing);
  }
  return alpha;
}

}  // namespace vascsim

// Rod self-contact (contact.self): the IPC barrier of barrier.h between every node and every
// rod edge it is not part of or next to, nor closer to along the rod than 1.5 times the
// thickness and activation distance, at a gap of distance - 2 r_o (the two surfaces). In 2D
// two segments come closest at an end of one of them, so node-edge pairs see every edge-edge
// approach. Its Hessian couples nodes far apart along the rod: those entries fall outside the
// Newton matrix's band and go to ForceContext::off_band, which makes Newton solve that step with
// a sparse factorisation (sim/step/sparse_solve.h) instead of the banded one. Each pair's 6x6
// Hessian is projected onto the positive semi-definite cone (as IPC does), so Newton keeps a
// descent direction. Pairs are found by a sort on x (sweep and prune), so a rod that does not
// touch itself costs O(N log N) per search, and a search's pairs are kept (a Verlet list, in the
// run's cache) with a margin: until some node has moved half the margin, calls filter them
// instead of sorting again, and find the very pairs a search would, in the same order, so the
// forces are the same bit for bit. Channel force/contact.
#pragma once

#include <optional>
#include <vector>

#include "sim/contact/contact_params.h"
#include "sim/log/channel_names.h"
#include "sim/step/force_module.h"

namespace vascsim {

class SelfContactModule : public ForceModule {
 public:
  SelfContactModule(const RodModel& rod, const ContactParams& params);
  std::string channel() const override { return channel::kContactForce; }
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;
  // Keeps every pair's gap open: a step may close at most 80 % of any gap, bounded by how fast the
  // gap can shrink (the node's and the farther edge end's displacement).
  double max_step_fraction(const ForceContext& ctx, const Eigen::VectorXd& dx) const override;
  bool defined_at(const ForceContext& ctx) const override;
  std::unique_ptr<ModuleCache> make_cache() const override;

  // A node and an edge (its first node) of positions `x` closer than the rod's thickness: the
  // rod overlaps itself there, where the barrier is not defined. None if it does not.
  struct Overlap {
    int node, edge;
    double distance;  // m, between the centre lines
  };
  std::optional<Overlap> first_overlap(const Eigen::VectorXd& x) const;
  double thickness() const { return thickness_; }
  // Node-edge pairs (node, first node of the edge) whose distance may be below `reach` (m).
  std::vector<std::pair<int, int>> candidate_pairs(const Eigen::VectorXd& x, double reach) const;

 private:
  struct Cache;
  // Whether a node and an edge are too close along the rod to be a contact pair.
  bool adjacent(int node, int edge) const;
  // candidate_pairs(x, reach), from the cache's list while it covers `reach`, else searched.
  const std::vector<std::pair<int, int>>& pairs_within(const Eigen::VectorXd& x, double reach, Cache& cache) const;

  int nodes_;
  double thickness_;  // m, 2 r_o
  double g_hat_, kappa_;
  std::vector<double> arc_;  // m, (N), rest arc length from the root to each node
  double exclusion_ = 0.0;   // m
  double list_reach_ = 0.0;  // m, reach of the kept list: the barrier's plus the margin
};

}  // namespace vascsim

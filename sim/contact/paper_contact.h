// The paper's contact (II.D), done right, for reproduction and comparison: contact forces are
// decided OUTSIDE the Newton solve. After a trial step, every node inside a wall gets its contact
// force raised by K_f times its depth along the wall normal, nodes that left the wall get it
// lowered (never below zero), and the step is solved again from the same start, until no node is
// inside a wall or the iteration cap is reached. Unlike the authors' code the force is not
// re-added on every Newton iteration, it acts outward, and it is carried to the next step as the
// starting guess (a resting contact keeps its force).
#pragma once

#include <vector>

#include "sim/contact/contact_pairs.h"
#include "sim/log/channel_names.h"
#include "sim/step/controls.h"
#include "sim/step/force_module.h"

namespace vascsim {

// Applies Controls::wall_forces. Channel force/contact.
class ExplicitWallForceModule : public ForceModule {
 public:
  explicit ExplicitWallForceModule(int nodes) : nodes_(nodes) {}
  std::string channel() const override { return channel::kContactForce; }
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;

 private:
  int nodes_;
};

struct PaperContactUpdate {
  double max_depth = 0.0;  // m, deepest node inside a wall before the update
  bool settled = false;    // no node inside a wall
};

// One push-out iteration: updates `forces` (one per node, N) from the node gaps at positions x.
PaperContactUpdate paper_contact_update(const WallDistanceField& walls, double rod_radius, double gain,
                                        const Eigen::VectorXd& x, std::vector<NodeForce>& forces);

}  // namespace vascsim

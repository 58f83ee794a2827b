// Implicit wall contact (the default contact mode): the IPC barrier (barrier.h) on every
// node-wall and corner-edge pair (contact_pairs.h), with its gradient and Hessian inside the
// Newton solve, and a step-length cap that keeps every gap open. Large time steps stay stable
// and nothing ever passes through a wall. Channel force/contact.
#pragma once

#include <memory>

#include "sim/contact/contact_pairs.h"
#include "sim/contact/contact_params.h"
#include "sim/log/channel_names.h"
#include "sim/step/force_module.h"

namespace vascsim {

// The geometry contact, friction and the run's statistics share: reach g_hat, the rod's radius
// and edges up to twice the longest rest edge.
std::shared_ptr<const ContactGeometry> make_contact_geometry(const std::vector<WallSegment>& walls, const RodModel& rod,
                                                             const ContactParams& params);

// The neighbour lists of a run for one geometry, shared by its users (SharedCaches, keyed by the
// geometry): `fallback` when the context has no shared caches.
struct ContactNeighboursCache : ModuleCache {
  ContactNeighbours lists;
};
ContactNeighbours& run_neighbours(const ForceContext& ctx, const ContactGeometry& geometry, ContactNeighbours& fallback);

class WallContactModule : public ForceModule {
 public:
  WallContactModule(std::shared_ptr<const ContactGeometry> geometry, const ContactParams& params);
  // With a geometry of its own (tests).
  WallContactModule(const std::vector<WallSegment>& walls, const RodModel& rod, const ContactParams& params)
      : WallContactModule(make_contact_geometry(walls, rod, params), params) {}
  std::string channel() const override { return channel::kContactForce; }
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;
  double max_step_fraction(const ForceContext& ctx, const Eigen::VectorXd& dx) const override;
  bool defined_at(const ForceContext& ctx) const override;
  // The barrier energy at positions x (J): what add() differentiates.
  double energy(const Eigen::VectorXd& x) const;

  const ContactGeometry& geometry() const { return *geometry_; }

 private:
  ContactParams params_;
  std::shared_ptr<const ContactGeometry> geometry_;
};

// Regularised Coulomb friction between rod nodes and walls (paper V.B), lagged as in IPC: the
// normal force magnitude lambda and the tangent t of each node-wall pair come from the state at
// the start of the step, and
//   F = -mu lambda f1(|v_t| / eps) sign(v_t) t,   v_t = t . v,
//   f1(y) = 2 y - y^2 for y < 1, 1 beyond,
// so friction is viscous-like below the slip velocity eps (stick) and Coulomb above it (slip).
// Its Jacobian mu lambda f1'(|v_t|/eps)/eps t t^T dv_dx is symmetric and PSD. Corner-edge pairs
// carry no friction (docs/contact.md). Channel force/friction.
class WallFrictionModule : public ForceModule {
 public:
  WallFrictionModule(std::shared_ptr<const ContactGeometry> geometry, const ContactParams& params);
  WallFrictionModule(const std::vector<WallSegment>& walls, const RodModel& rod, const ContactParams& params)
      : WallFrictionModule(make_contact_geometry(walls, rod, params), params) {}
  std::string channel() const override { return channel::kFrictionForce; }
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;
  std::unique_ptr<ModuleCache> make_cache() const override;

 private:
  struct LaggedPair {
    int first_dof;
    double lambda;            // N, normal force at the start of the step
    Eigen::Vector2d tangent;  // unit, along the wall
  };
  // The pairs at the start of the step, kept in the run's cache: every Newton iteration of a
  // step asks for the same start state, so they are found once per step.
  struct Cache;
  const std::vector<LaggedPair>& lagged_pairs(const Eigen::VectorXd& start, Cache& cache, ContactNeighbours& lists) const;

  ContactParams params_;
  std::shared_ptr<const ContactGeometry> geometry_;
};

}  // namespace vascsim

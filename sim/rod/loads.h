// The load modules a scene can switch on (LoadSpec), each a ForceModule in its own file:
// gravity, point forces and moments, viscous damping and quadratic fluid drag. Signs: each adds
// the force acting ON the rod; the stepper's residual is M a - F, so a force along +x
// accelerates the rod along +x (tested in rod_dynamics_test.cpp, RodDynamics.ExternalForceSign;
// the paper's code and dismech-rods had this backwards).
#pragma once

#include <vector>

#include "sim/log/channel_names.h"
#include "sim/rod/rod_model.h"
#include "sim/step/force_module.h"

namespace vascsim {

// m_i g on every node (N). Channel force/external.
class GravityModule : public ForceModule {
 public:
  GravityModule(const RodModel& rod, const Vec2& acceleration) : mass_(rod.mass), g_(acceleration) {}
  std::string channel() const override;
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;

 private:
  Eigen::VectorXd mass_;  // (N), kg
  Vec2 g_;                // m/s^2
};

// Dead point forces and moments with a time profile (PointLoadSpec). A moment M on edge
// e = x_b - x_a is the dead-load potential -M theta(e), theta = atan2(e_y, e_x):
//   F_b = M (-e_y, e_x)/|e|^2 = -F_a,  K = -M d2theta/de2 (mapped onto the two nodes).
// Channel force/external.
class PointLoadModule : public ForceModule {
 public:
  PointLoadModule(int nodes, const std::vector<PointLoadSpec>& loads);
  std::string channel() const override;
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;
  // The profile's factor at time t (1 for constant).
  static double profile(const PointLoadSpec& load, double t);

 private:
  std::vector<PointLoadSpec> loads_;  // node indices resolved to 0..N-1
  int nodes_;
};

// A magnet on the distal edge in the scene's uniform field (MagnetSpec): the Zeeman energy
// -m B . t of sim/control/tip_magnet_energy.h, t the edge's unit direction, as a couple on the
// last two nodes with its exact Hessian. The field scales with load_scale in statics.
// Channel force/magnet.
class MagnetLoadModule : public ForceModule {
 public:
  MagnetLoadModule(int nodes, const MagnetSpec& spec) : nodes_(nodes), spec_(spec) {}
  std::string channel() const override { return channel::kMagnetForce; }
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;

 private:
  int nodes_;
  MagnetSpec spec_;
};

// The drag of lumped bodies (BodySpec) on their nodes, f = -c1 v - c2 |v| v, with the velocity
// Jacobian -df/dv = c1 I + c2 (|v| I + v v^T / |v|) mapped through dv/dx. Channel force/drag.
// (The bodies' mass is added to the rod's lumped masses when the Model is built.)
class BodyDragModule : public ForceModule {
 public:
  BodyDragModule(int nodes, const std::vector<BodySpec>& bodies);
  std::string channel() const override { return channel::kDragForce; }
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;

 private:
  std::vector<BodySpec> bodies_;  // node indices resolved to 0..N-1
};

// Viscous damping f_i = -c dl_i v_i; K += c dl_i dv_dx I. Channel force/damping.
class ViscousDampingModule : public ForceModule {
 public:
  ViscousDampingModule(const RodModel& rod, double coefficient) : c_(coefficient * rod.voronoi) {}
  std::string channel() const override { return channel::kDampingForce; }
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;

 private:
  Eigen::VectorXd c_;  // (N), N s/m
};

// Quadratic drag (paper II.C, docs/references.md section 4), c = 1/2 rho Cd A:
//  - tip (the paper): the tip node only, isotropic, f = -c |v| v, -df/dv = c (|v| I + v v^T / |v|);
//  - nodes (paper V.A's refinement: a rod meets more resistance moving sideways than along
//    itself): every node, the cross-flow principle with separate normal and tangential
//    coefficients, f = -c_n |v.n| (v.n) n - c_t |v.t| (v.t) t, -df/dv = 2 c_n |v.n| n n^T +
//    2 c_t |v.t| t t^T, where t is the node's unit tangent of the step's start extrapolated
//    along its velocity to the step's end, x_start + h v_start: independent of the
//    iterate, so the Jacobian stays exact and symmetric, and off by O(h^2) only. Until issue 16
//    t was the start's own tangent, off by the rod's rotation within a step, which made the whole
//    run first order in dt (maze_body_drag, body deviation at dt 1e-2: 0.62 mm, now 0.34 mm;
//    tests/drag_convergence_test.cpp).
// Both Jacobians are symmetric, positive semi-definite and 0 at v = 0. Channel force/drag.
class QuadraticDragModule : public ForceModule {
 public:
  QuadraticDragModule(const RodModel& rod, const DragSpec& spec);
  std::string channel() const override;
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;
  std::unique_ptr<ModuleCache> make_cache() const override;
  // kg/m, per node: c_i of the tip mode, or the normal c_n,i of the nodes mode (0 without drag).
  const Eigen::VectorXd& coefficients() const { return c_; }
  // kg/m, per node, c_t,i: along the rod in the nodes mode; equal to coefficients() in the tip mode.
  const Eigen::VectorXd& tangential_coefficients() const { return c_tangential_; }

 private:
  void add_isotropic(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const;
  void add_cross_flow(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const;
  // The tangents of a step (start carried h along its velocity), kept in the run's cache: every
  // Newton iterate of the step asks for the same ones (a third of the module's cost otherwise).
  struct DragTangentCache : ModuleCache {
    Eigen::VectorXd start_x, start_v;  // m, m/s: the step's start they were computed for
    double h = -1.0;                   // s
    Eigen::Matrix2Xd tangents;         // 2 x N, unit
  };
  const Eigen::Matrix2Xd& step_tangents(const State& start, double h, DragTangentCache& cache) const;

  bool cross_flow_ = false;
  Eigen::VectorXd c_;             // (N), kg/m
  Eigen::VectorXd c_tangential_;  // (N), kg/m
};

}  // namespace vascsim

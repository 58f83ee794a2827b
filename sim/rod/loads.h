// The load modules a scene can switch on (LoadSpec), each a ForceModule in its own file:
// gravity, point forces and moments, viscous damping, quadratic fluid drag, and the controller's
// node forces. Signs: each adds the force acting ON the rod; the stepper's residual is
// M a - F, so a force along +x accelerates the rod along +x (tested in loads_test.cpp; the
// paper's code and dismech-rods had this backwards).
#pragma once

#include <vector>

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
//   F_b = M (-e_y, e_x)/|e|^2 = -F_a,  K = M d2theta/de2 (mapped onto the two nodes).
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

// Viscous damping f_i = -c dl_i v_i; K += c dl_i dv_dx I. Channel force/damping.
class ViscousDampingModule : public ForceModule {
 public:
  ViscousDampingModule(const RodModel& rod, double coefficient) : c_(coefficient * rod.voronoi) {}
  std::string channel() const override { return "force/damping"; }
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;

 private:
  Eigen::VectorXd c_;  // (N), N s/m
};

// Quadratic drag f_i = -c_i |v_i| v_i, c_i = 1/2 rho Cd A_i (paper II.C, refs section 4).
//   -df/dv = c_i (|v| I + v v^T / |v|)  (symmetric, positive semi-definite; 0 at v = 0)
// Channel force/drag.
class QuadraticDragModule : public ForceModule {
 public:
  QuadraticDragModule(const RodModel& rod, const DragSpec& spec);
  std::string channel() const override;
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;
  const Eigen::VectorXd& coefficients() const { return c_; }

 private:
  Eigen::VectorXd c_;  // (N), kg/m, 0 on nodes without drag
};

// The controller's node forces (Controls::forces), e.g. the magnetic tip force of issue 4.
// Channel force/actuation.
class ControlForceModule : public ForceModule {
 public:
  explicit ControlForceModule(int nodes) : nodes_(nodes) {}
  std::string channel() const override;
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override;

 private:
  int nodes_;
};

}  // namespace vascsim

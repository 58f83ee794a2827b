// The two elastic element energies of the planar Discrete Elastic Rod (Jawed's course notes;
// docs/references.md preamble), as pure functions returning energy, gradient and Hessian of one
// element. Inline because the assembler calls them once per node per Newton iteration.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "sim/env/geometry.h"

namespace vascsim {

struct StretchElement {
  double energy = 0.0;                 // J
  Eigen::Matrix<double, 4, 1> gradient;  // N, d/d(x0 y0 x1 y1)
  Eigen::Matrix<double, 4, 4> hessian;   // N/m
};

struct BendElement {
  double energy = 0.0;                 // J
  Eigen::Matrix<double, 6, 1> gradient;  // N, d/d(x0 y0 x1 y1 x2 y2)
  Eigen::Matrix<double, 6, 6> hessian;   // N/m
};

// Stretching of edge e = x1 - x0, l = |e|:
//   E = 1/2 EA l0 (l/l0 - 1)^2 = EA/(2 l0) (l - l0)^2
//   dE/de = EA/l0 (l - l0) u,            u = e/l
//   d2E/de2 = EA/l0 [u u^T + (1 - l0/l)(I - u u^T)]
// and x0 enters with the opposite sign of x1. Under compression (l < l0) the transverse part is
// negative: the buckling tests rely on it.
inline StretchElement stretch_energy(const Vec2& x0, const Vec2& x1, double ea, double rest_length) {
  const Vec2 e = x1 - x0;
  const double l = e.norm();
  const Vec2 u = e / l;
  const double k = ea / rest_length;
  StretchElement out;
  out.energy = 0.5 * k * (l - rest_length) * (l - rest_length);
  const Vec2 g = k * (l - rest_length) * u;
  out.gradient << -g, g;
  const Eigen::Matrix2d uu = u * u.transpose();
  const Eigen::Matrix2d h = k * (uu + (1.0 - rest_length / l) * (Eigen::Matrix2d::Identity() - uu));
  out.hessian << h, -h, -h, h;
  return out;
}

// Turning angle of the polyline x0-x1-x2: phi = atan2(e1 x e2, e1 . e2), e1 = x1-x0, e2 = x2-x1,
// counter-clockwise positive, in (-pi, pi].
inline double turning_angle(const Vec2& x0, const Vec2& x1, const Vec2& x2) {
  const Vec2 e1 = x1 - x0, e2 = x2 - x1;
  return std::atan2(e1.x() * e2.y() - e1.y() * e2.x(), e1.dot(e2));
}

// Discrete curvature kappa = 2 tan(phi/2) (dimensionless; kappa / dl_voronoi ~ 1/R).
inline double discrete_curvature(const Vec2& x0, const Vec2& x1, const Vec2& x2) {
  return 2.0 * std::tan(0.5 * turning_angle(x0, x1, x2));
}

// Bending at the hinge x1 between edges e1 = x1 - x0 and e2 = x2 - x1:
//   E = EI / (2 dl) (kappa - kappa0)^2,  kappa = 2 tan(phi/2),  phi = theta(e2) - theta(e1)
// Derivatives through the edge angles theta(e) = atan2(e_y, e_x):
//   dtheta/de = (-e_y, e_x)/|e|^2,  d2theta/de2 = [[2 e_x e_y, e_y^2 - e_x^2], [., -2 e_x e_y]]/|e|^4
//   dkappa/dphi = 1 + kappa^2/4 =: k1,  d2kappa/dphi2 = k1 kappa / 2
//   dE/dphi = EI/dl (kappa - kappa0) k1,  d2E/dphi2 = EI/dl [k1^2 + (kappa - kappa0) k1 kappa/2]
//   grad E = dE/dphi grad phi,  Hess E = d2E/dphi2 grad phi grad phi^T + dE/dphi Hess phi
// with phi's node derivatives from x0 -> -e1, x1 -> e1 - e2, x2 -> e2 (Hess phi has no e1-e2
// cross term). Using angles rather than the cross/dot form keeps the Hessian short.
inline BendElement bend_energy(const Vec2& x0, const Vec2& x1, const Vec2& x2, double ei, double voronoi_length,
                               double rest_kappa) {
  const Vec2 e1 = x1 - x0, e2 = x2 - x1;
  const double r1 = e1.squaredNorm(), r2 = e2.squaredNorm();
  // 2 tan(phi/2) = 2 sin(phi) / (1 + cos(phi)) = 2 (e1 x e2) / (|e1||e2| + e1 . e2): no atan2
  // or tan in the hot loop (the same value as discrete_curvature(), to round-off).
  const double cross = e1.x() * e2.y() - e1.y() * e2.x();
  const double kappa = 2.0 * cross / (std::sqrt(r1 * r2) + e1.dot(e2));
  const double k1 = 1.0 + 0.25 * kappa * kappa;
  const double c = ei / voronoi_length;
  const double dk = kappa - rest_kappa;
  const double dE = c * dk * k1;
  const double d2E = c * (k1 * k1 + dk * k1 * 0.5 * kappa);

  const Vec2 g1 = Vec2(e1.y(), -e1.x()) / r1;  // dphi/de1 = -dtheta(e1)/de1
  const Vec2 g2 = Vec2(-e2.y(), e2.x()) / r2;  // dphi/de2 = dtheta(e2)/de2
  Eigen::Matrix<double, 6, 1> gphi;
  gphi << -g1, g1 - g2, g2;
  auto theta_hessian = [](const Vec2& e, double r) {
    const double r4 = r * r;
    Eigen::Matrix2d h;
    h << 2.0 * e.x() * e.y(), e.y() * e.y() - e.x() * e.x(), e.y() * e.y() - e.x() * e.x(), -2.0 * e.x() * e.y();
    return Eigen::Matrix2d(h / r4);
  };
  const Eigen::Matrix2d a = -theta_hessian(e1, r1);  // d2phi/de1^2
  const Eigen::Matrix2d b = theta_hessian(e2, r2);   // d2phi/de2^2

  BendElement out;
  out.energy = 0.5 * c * dk * dk;
  out.gradient = dE * gphi;
  out.hessian.noalias() = d2E * gphi * gphi.transpose();
  out.hessian.block<2, 2>(0, 0) += dE * a;
  out.hessian.block<2, 2>(0, 2) -= dE * a;
  out.hessian.block<2, 2>(2, 0) -= dE * a;
  out.hessian.block<2, 2>(2, 2) += dE * (a + b);
  out.hessian.block<2, 2>(2, 4) -= dE * b;
  out.hessian.block<2, 2>(4, 2) -= dE * b;
  out.hessian.block<2, 2>(4, 4) += dE * b;
  return out;
}

}  // namespace vascsim

// The two elastic element energies of the planar Discrete Elastic Rod (Jawed's course notes;
// docs/references.md preamble), as pure functions returning energy, gradient and Hessian of one
// element. Inline because the assembler (sim/step/elastic_assembly.cpp) calls these very
// functions once per edge and hinge in every Newton iteration: what the tests check is what runs.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "sim/env/geometry.h"

namespace vascsim {

// The Hessians come in the factored form the elements have, which the assembler scatters into
// the band without forming the dense blocks (the hot loop); hessian() forms them for tests.
struct StretchElement {
  double energy = 0.0;                   // J
  Eigen::Matrix<double, 4, 1> gradient;  // N, d/d(x0 y0 x1 y1)
  Eigen::Matrix2d block;                 // N/m, d2E/de2: Hessian = [block -block; -block block]
  Eigen::Matrix<double, 4, 4> hessian() const {
    Eigen::Matrix<double, 4, 4> h;
    h << block, -block, -block, block;
    return h;
  }
};

struct BendElement {
  double energy = 0.0;                   // J
  Eigen::Matrix<double, 6, 1> gradient;  // N, d/d(x0 y0 x1 y1 x2 y2)
  // Hessian = d2E gphi gphi^T + [a -a 0; -a a+b -b; 0 -b b]: gphi = dphi/dx, d2E = d2E/dphi2 (N m),
  // a and b = dE/dphi times d2phi/de1^2 and d2phi/de2^2 (N/m).
  Eigen::Matrix<double, 6, 1> gphi;
  double d2E = 0.0;
  Eigen::Matrix2d a, b;
  Eigen::Matrix<double, 6, 6> hessian() const {
    Eigen::Matrix<double, 6, 6> h = d2E * gphi * gphi.transpose();
    h.block<2, 2>(0, 0) += a;
    h.block<2, 2>(0, 2) -= a;
    h.block<2, 2>(2, 0) -= a;
    h.block<2, 2>(2, 2) += a + b;
    h.block<2, 2>(2, 4) -= b;
    h.block<2, 2>(4, 2) -= b;
    h.block<2, 2>(4, 4) += b;
    return h;
  }
};

// One edge e = x1 - x0 with the lengths its elements need, computed once per edge: an edge
// serves one stretch element and two bending hinges.
struct EdgeGeometry {
  Vec2 e = Vec2::Zero();         // m
  double length = 0.0;           // m, |e|
  double inverse_length2 = 0.0;  // 1/m^2, 1/|e|^2
  static EdgeGeometry of(const Vec2& e) {
    const double r = e.squaredNorm();
    return {e, std::sqrt(r), 1.0 / r};
  }
};

// Stretching of edge e = x1 - x0, l = |e|, with k = EA/l0 (RodModel::stretch_stiffness):
//   E = 1/2 EA l0 (l/l0 - 1)^2 = k/2 (l - l0)^2
//   dE/de = k (l - l0) u,            u = e/l
//   d2E/de2 = k [u u^T + (1 - l0/l)(I - u u^T)]
// and x0 enters with the opposite sign of x1. Under compression (l < l0) the transverse part is
// negative: the buckling tests rely on it.
inline StretchElement stretch_element(const EdgeGeometry& edge, double k, double rest_length) {
  const double l = edge.length, inverse_l = l * edge.inverse_length2;
  const Vec2 u = edge.e * inverse_l;
  const double f = k * (l - rest_length);
  StretchElement out;
  out.energy = 0.5 * k * (l - rest_length) * (l - rest_length);
  out.gradient << -f * u, f * u;
  const double t = k * (1.0 - rest_length * inverse_l), along = k - t;  // transverse and axial stiffness
  out.block << along * u.x() * u.x() + t, along * u.x() * u.y(), along * u.x() * u.y(), along * u.y() * u.y() + t;
  return out;
}

inline StretchElement stretch_energy(const Vec2& x0, const Vec2& x1, double ea, double rest_length) {
  return stretch_element(EdgeGeometry::of(x1 - x0), ea / rest_length, rest_length);
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
// c = EI/dl is RodModel::bend_stiffness of the hinge's node.
inline BendElement bend_element(const EdgeGeometry& edge1, const EdgeGeometry& edge2, double c, double rest_kappa) {
  const double x1 = edge1.e.x(), y1 = edge1.e.y(), x2 = edge2.e.x(), y2 = edge2.e.y();
  const double ir1 = edge1.inverse_length2, ir2 = edge2.inverse_length2;
  // 2 tan(phi/2) = 2 sin(phi) / (1 + cos(phi)) = 2 (e1 x e2) / (|e1||e2| + e1 . e2): no atan2
  // or tan in the hot loop (the same value as discrete_curvature(), to round-off).
  const double cross = x1 * y2 - y1 * x2, dot = x1 * x2 + y1 * y2;
  const double kappa = 2.0 * cross / (edge1.length * edge2.length + dot);
  const double k1 = 1.0 + 0.25 * kappa * kappa;
  const double dk = kappa - rest_kappa;
  const double dE = c * dk * k1;
  const double d2E = c * (k1 * k1 + dk * k1 * 0.5 * kappa);

  const double g1x = y1 * ir1, g1y = -x1 * ir1;  // dphi/de1 = -dtheta(e1)/de1
  const double g2x = -y2 * ir2, g2y = x2 * ir2;  // dphi/de2 = dtheta(e2)/de2
  BendElement out;
  out.gphi << -g1x, -g1y, g1x - g2x, g1y - g2y, g2x, g2y;
  out.d2E = d2E;
  // dE times d2phi/de1^2 = -dE d2theta/de1^2, and dE times d2phi/de2^2 = dE d2theta/de2^2.
  const double q1 = dE * ir1 * ir1, q2 = dE * ir2 * ir2;
  out.a << -2.0 * x1 * y1 * q1, (x1 * x1 - y1 * y1) * q1, (x1 * x1 - y1 * y1) * q1, 2.0 * x1 * y1 * q1;
  out.b << 2.0 * x2 * y2 * q2, (y2 * y2 - x2 * x2) * q2, (y2 * y2 - x2 * x2) * q2, -2.0 * x2 * y2 * q2;
  out.energy = 0.5 * c * dk * dk;
  out.gradient = dE * out.gphi;
  return out;
}

inline BendElement bend_energy(const Vec2& x0, const Vec2& x1, const Vec2& x2, double ei, double voronoi_length,
                               double rest_kappa) {
  return bend_element(EdgeGeometry::of(x1 - x0), EdgeGeometry::of(x2 - x1), ei / voronoi_length, rest_kappa);
}

}  // namespace vascsim

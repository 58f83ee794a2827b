// A permanent magnet rigidly embedded in the distal edge, its moment along the edge tangent, in
// a uniform field B (paper V.A's refinement of the point force). Zeeman energy
//   E = -m B . t,  t = e / |e|,  e = x_tip - x_prev,
//   dE/de = -(m / l) (I - t t^T) B,
//   d2E/de2 = (m / l^3) (B e^T + e B^T + (B.e) I - 3 (B.e) e e^T / l^2),
// which is the torque m x B turning the tip edge towards the field; no net force (uniform field).
// Derivatives with respect to (x_prev, x_tip) are (-dE/de, dE/de) and [[H, -H], [-H, H]].
#pragma once

#include <Eigen/Core>

namespace vascsim {

struct EdgeEnergy {
  double energy = 0.0;                   // J
  Eigen::Matrix<double, 4, 1> gradient;  // dE / d(x_prev, y_prev, x_tip, y_tip), N
  Eigen::Matrix4d hessian;               // N/m, symmetric
};

inline EdgeEnergy tip_magnet_energy(const Eigen::Vector2d& x_prev, const Eigen::Vector2d& x_tip, double moment,
                                    const Eigen::Vector2d& field) {
  const Eigen::Vector2d e = x_tip - x_prev;
  const double l = e.norm();
  const Eigen::Vector2d t = e / l;
  const double Be = field.dot(e);
  EdgeEnergy out;
  out.energy = -moment * field.dot(t);
  const Eigen::Vector2d g = -(moment / l) * (field - t * t.dot(field));
  out.gradient << -g, g;
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  const Eigen::Matrix2d h = (moment / (l * l * l)) *
                            (field * e.transpose() + e * field.transpose() + Be * I - 3.0 * Be * e * e.transpose() / (l * l));
  out.hessian << h, -h, -h, h;
  return out;
}

}  // namespace vascsim

// RodModel: the constant, compiled description of the planar Discrete Elastic Rod (paper II.B):
// stiffnesses, rest lengths, Voronoi lengths, lumped masses, rest curvatures and the initial node
// positions. Built once from the scene's RodSpec and ShapeSpec; the stepper only reads it.
// Node i has degrees of freedom 2i (x) and 2i+1 (y); edge i joins nodes i and i+1.
#pragma once

#include <Eigen/Core>

#include "sim/scene/scene.h"

namespace vascsim {

struct RodModel {
  int nodes = 0;
  double length = 0.0;        // m, root-to-tip length of the free rod (see ClampKind::kCentred)
  double edge_length = 0.0;   // m, uniform rest edge length dl
  double outer_radius = 0.0;  // m
  double inner_radius = 0.0;  // m
  double ea = 0.0;            // N, stretching stiffness E pi (ro^2 - ri^2)
  double ei = 0.0;            // N m^2, bending stiffness E pi (ro^4 - ri^4) / 4
  double linear_density = 0.0;  // kg/m, rho pi (ro^2 - ri^2)
  Eigen::VectorXd rest_length;  // (N-1), m, per edge
  Eigen::VectorXd voronoi;      // (N), m, half of each adjacent edge: the node's share of the rod
  Eigen::VectorXd mass;         // (N), kg, lumped: linear_density * voronoi
  Eigen::VectorXd rest_kappa;   // (N), -, discrete rest curvature 2 tan(phi0/2); 0 at both ends
  Eigen::VectorXd stretch_stiffness;  // (N-1), N/m, EA / l0 per edge
  Eigen::VectorXd bend_stiffness;     // (N), N m, EI / dl_voronoi per node (0 at both ends: no hinge)
  Eigen::VectorXd x_initial;    // (2N), m, node positions at t = 0, interleaved x0 y0 x1 y1 ...
};

// The node positions of an arc (or straight line) with N nodes and uniform chord `dl`, starting
// at `first`, the first chord heading along `direction` (rad), each next one turned by the
// chord angle of `curvature` (1/m).
Eigen::VectorXd arc_positions(int nodes, double dl, const Vec2& first, double direction, double curvature);

// Compiles the rod. With a centred clamp the first edge straddles shape.start and the tip lies at
// `length` from it along the rod (docs/references.md section 0), so dl = L/(N-1.5); otherwise dl = L/(N-1).
RodModel build_rod_model(const RodSpec& rod, const ShapeSpec& shape, ClampKind clamp);

}  // namespace vascsim

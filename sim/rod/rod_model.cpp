#include "sim/rod/rod_model.h"

#include <cmath>

namespace vascsim {

// Chords of length dl inscribed in a circle of radius 1/curvature turn by 2 asin(dl k / 2) each.
// The turn is capped below pi: an edge folded exactly back has infinite bending energy.
double chord_turn(double dl, double curvature) {
  const double turn = 2.0 * std::asin(std::min(1.0, std::abs(0.5 * dl * curvature)));
  return std::copysign(std::min(turn, 0.95 * M_PI), curvature);
}

// Chord i heads direction + i turn: `direction` is the first edge's heading (the clamped edge's,
// with either clamp), not the arc's tangent at node 0, which is half a turn behind it (until
// issue 16 the chords started from the tangent, so a clamp locked in a tilt of asin(kappa dl/2)).
Eigen::VectorXd arc_positions(int nodes, double dl, const Vec2& first, double direction, double curvature) {
  Eigen::VectorXd x(2 * nodes);
  const double turn = chord_turn(dl, curvature);
  Vec2 p = first;
  for (int i = 0; i < nodes; ++i) {
    x.segment<2>(2 * i) = p;
    const double h = direction + i * turn;
    p += dl * Vec2(std::cos(h), std::sin(h));
  }
  return x;
}

RodModel build_rod_model(const RodSpec& spec, const ShapeSpec& shape, ClampKind clamp) {
  RodModel m;
  const int n = spec.nodes;
  m.nodes = n;
  m.length = spec.length;
  m.outer_radius = spec.outer_radius;
  m.inner_radius = spec.inner_radius;
  const double ro2 = spec.outer_radius * spec.outer_radius, ri2 = spec.inner_radius * spec.inner_radius;
  const double area = M_PI * (ro2 - ri2);
  m.ea = spec.youngs_modulus * area;
  m.ei = spec.youngs_modulus * M_PI * (ro2 * ro2 - ri2 * ri2) / 4.0;
  m.linear_density = spec.density * area;
  const bool centred = clamp == ClampKind::kCentred;
  const double dl = centred ? spec.length / (n - 1.5) : spec.length / (n - 1);
  m.edge_length = dl;
  m.rest_length = Eigen::VectorXd::Constant(n - 1, dl);
  m.voronoi = Eigen::VectorXd::Constant(n, dl);
  m.voronoi[0] = m.voronoi[n - 1] = 0.5 * dl;
  m.mass = m.linear_density * m.voronoi;

  const double rest_turn = chord_turn(dl, shape.rest_curvature);
  m.rest_kappa = Eigen::VectorXd::Zero(n);
  m.rest_kappa.segment(1, n - 2).setConstant(2.0 * std::tan(0.5 * rest_turn));
  m.stretch_stiffness = m.ea * m.rest_length.cwiseInverse();
  m.bend_stiffness = Eigen::VectorXd::Zero(n);
  for (int i = 1; i + 1 < n; ++i) m.bend_stiffness[i] = m.ei / m.voronoi[i];

  Vec2 first = shape.start;
  if (centred) first -= 0.5 * dl * Vec2(std::cos(shape.direction), std::sin(shape.direction));
  m.x_initial = arc_positions(n, dl, first, shape.direction, shape.initial_curvature);
  return m;
}

}  // namespace vascsim

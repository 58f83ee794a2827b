// Scenes for the rod validation tests: the paper's rod (Table I) as a cantilever or free rod in
// free space, with the knobs the tests turn.
#pragma once

#include <gtest/gtest.h>

#include "sim/run/compile.h"
#include "sim/scene/scene.h"
#include "sim/step/statics.h"

namespace vascsim::test {

// A horizontal cantilever along +x from the origin, centred clamp (docs/references.md section 0), static mode.
inline Scene cantilever(int nodes) {
  Scene s;
  s.has_environment = false;
  s.rod.nodes = nodes;
  s.boundary.clamp = ClampKind::kCentred;
  s.solver.mode = SolveMode::kStatic;
  s.solver.rel_tol = 1e-10;
  return s;
}

// The cantilever with a tip magnet of 0.01 A m^2 in a uniform field of `field` T at `angle` rad
// from +x (loads.magnet; a = m B L / EI = 289 at 1 T for the paper's rod).
inline Scene tip_magnet_cantilever(int nodes, double field, double angle) {
  Scene s = cantilever(nodes);
  s.loads.magnet.enabled = true;
  s.loads.magnet.moment = 0.01;
  s.loads.magnet.field = field;
  s.loads.magnet.angle = angle;
  return s;
}

// Three collinear nodes along +x with the first edge clamped: node 2 on the last edge moving along
// the axis is an exactly linear spring k = EA/l0 (docs/references.md section 5) with mass
// m = rho A l0 / 2, and k/m = 2 E / (rho l0^2) = (2 pi)^2 by the choice of E. Node 2 rests at x = 1 m.
inline Scene axial_oscillator(Scheme scheme, double newton_rel_tol = 1e-12) {
  Scene s;
  s.has_environment = false;
  s.rod.nodes = 3;
  s.rod.length = 1.0;
  s.rod.density = 1000.0;
  const double l0 = 0.5;  // m, edge length
  s.rod.youngs_modulus = 2.0 * 3.14159265358979323846 * 3.14159265358979323846 * s.rod.density * l0 * l0;
  s.boundary.clamp = ClampKind::kFirstEdge;
  s.solver.scheme = scheme;
  s.solver.rel_tol = newton_rel_tol;
  return s;
}

// The static equilibrium of a (static mode) scene; a failed solve fails the calling test.
inline State static_equilibrium(const Scene& scene, StaticReport* report = nullptr) {
  const Model model = *compile(scene);
  State state = initial_state(model);
  Workspace ws(model);
  const StaticReport r = solve_static(model, state, ws, Controls{});
  EXPECT_TRUE(r.ok) << r.failure;
  if (report) *report = r;
  return state;
}

inline double bending_stiffness(const RodSpec& r) {
  const double ro2 = r.outer_radius * r.outer_radius, ri2 = r.inner_radius * r.inner_radius;
  return r.youngs_modulus * 3.14159265358979323846 * (ro2 * ro2 - ri2 * ri2) / 4.0;
}

}  // namespace vascsim::test

// Scenes for the rod validation tests: the paper's rod (Table I) as a cantilever or free rod in
// free space, with the knobs the tests turn.
#pragma once

#include "sim/scene/scene.h"

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

inline double bending_stiffness(const RodSpec& r) {
  const double ro2 = r.outer_radius * r.outer_radius, ri2 = r.inner_radius * r.inner_radius;
  return r.youngs_modulus * 3.14159265358979323846 * (ro2 * ro2 - ri2 * ri2) / 4.0;
}

}  // namespace vascsim::test

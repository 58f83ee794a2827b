// A tip magnet in a uniform field against the closed form of docs/references.md
// section 8: a cantilever whose tip dipole m lies along the tip tangent, in a field B at angle
// psi to the undeformed axis, is an arc whose tip angle solves phi = beta sin(psi - phi),
// beta = m B L / EI; for psi = 90 degrees and beta = 1, phi = 0.739085133 rad.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/control/tip_magnet_module.h"
#include "sim/run/compile.h"
#include "sim/step/statics.h"
#include "tests/rod_test_scenes.h"

namespace vascsim {
namespace {

double tip_angle_for_beta_one(int nodes) {
  Scene scene = test::cantilever(nodes);
  Model model = *compile(scene);
  const double ei = test::bending_stiffness(scene.rod);
  const double field = 1.0;                            // T, along +y (psi = 90 degrees)
  const double moment = ei / (scene.rod.length * field);  // beta = m B L / EI = 1
  model.forces.push_back(std::make_unique<TipMagnetModule>(model.nodes(), moment));
  Controls controls;
  controls.field = Vec2(0.0, field);
  State state = initial_state(model);
  Workspace ws(model);
  const StaticReport r = solve_static(model, state, ws, controls);
  EXPECT_TRUE(r.ok) << r.failure;
  const Vec2 edge = state.position(nodes - 1) - state.position(nodes - 2);
  return std::atan2(edge.y(), edge.x());
}

TEST(TipMagnet, CantileverTipAngleConvergesToTheArcSolution) {
  // The magnet sits on the last edge, whose direction is the tangent half an edge before the
  // tip, so the edge angle converges to phi at first order in dl; Richardson extrapolation of
  // two resolutions removes that term.
  const double reference = 0.739085133;  // docs/references.md section 8
  const int coarse_nodes = 21, fine_nodes = 41;
  const double coarse = tip_angle_for_beta_one(coarse_nodes);
  const double fine = tip_angle_for_beta_one(fine_nodes);
  const double ratio = (fine_nodes - 1.5) / (coarse_nodes - 1.5);  // dl_coarse / dl_fine (centred clamp)
  const double extrapolated = (ratio * fine - coarse) / (ratio - 1.0);
  EXPECT_NEAR(fine, reference, 0.02 * reference);
  EXPECT_LT(std::abs(fine - reference), 0.6 * std::abs(coarse - reference));
  EXPECT_NEAR(extrapolated, reference, 1e-3 * reference);
}

}  // namespace
}  // namespace vascsim

// Whether a static equilibrium's stability is decided (sim/step/stability_margin.h). The margin's
// eigenvalue is checked against Eigen's dense symmetric eigensolver (the eigenvalue of least
// magnitude of the free block), and the decision on columns: a column past buckling (Timoshenko &
// Gere, Theory of Elastic Stability, 1961, section 2.7: P_cr = pi^2 EI / (4 L^2) clamped-free)
// has one negative eigenvalue; at 81 nodes it is counted, at 10001 nodes it lies within the
// matrix's round-off, and the solve must say the stability is not decided instead of calling the
// straight column stable.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "sim/run/compile.h"
#include "sim/step/banded_ldlt.h"
#include "sim/step/model.h"
#include "sim/step/newton.h"
#include "sim/step/stability_margin.h"
#include "sim/step/statics.h"
#include "tests/rod_test_scenes.h"

namespace vascsim {
namespace {

using test::bending_stiffness;
using test::cantilever;

// A centred-clamp cantilever with a dead tip load `axial` P_cr along +x and `lateral` P_cr along
// +y, without the stable branch: the equilibrium the load path reaches.
Scene loaded_column(int nodes, double axial, double lateral) {
  Scene scene = cantilever(nodes);
  scene.solver.stable_branch = false;
  const double ei = bending_stiffness(scene.rod), l = scene.rod.length;
  const double p_cr = M_PI * M_PI * ei / (4 * l * l);
  PointLoadSpec tip;
  tip.force = Vec2(axial * p_cr, lateral * p_cr);
  scene.loads.point_loads.push_back(tip);
  return scene;
}

StaticReport solve(const Scene& scene) {
  StaticReport r;
  test::static_equilibrium(scene, &r);
  return r;
}

// The margin at the equilibrium against the dense eigenvalues of the free degrees of freedom.
void expect_margin_matches_dense(const Scene& scene) {
  const Model model = *compile(scene);
  State state = initial_state(model);
  Workspace ws(model);
  ASSERT_TRUE(solve_static(model, state, ws, Controls{}).ok);
  NewtonProblem p;
  const Controls controls;
  p.controls = &controls;
  assemble(model, p, state.x, ws, true);
  const BandedMatrix stiffness = ws.jacobian;
  BandedMatrix factor = stiffness;
  ASSERT_TRUE(banded_block_ldlt_factor(factor).ok);
  const StabilityMargin margin = stability_margin(stiffness, factor, ws.fixed);

  const Eigen::MatrixXd dense = stiffness.to_dense();
  std::vector<int> free;
  for (int d = 0; d < dense.rows(); ++d)
    if (!ws.fixed[static_cast<std::size_t>(d)]) free.push_back(d);
  Eigen::MatrixXd block(free.size(), free.size());
  for (std::size_t i = 0; i < free.size(); ++i)
    for (std::size_t j = 0; j < free.size(); ++j) block(i, j) = dense(free[i], free[j]);
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(block).eigenvalues();
  double nearest_zero = eigenvalues[0];
  for (int i = 1; i < eigenvalues.size(); ++i)
    if (std::abs(eigenvalues[i]) < std::abs(nearest_zero)) nearest_zero = eigenvalues[i];
  EXPECT_NEAR(margin.eigenvalue, nearest_zero, 1e-8 * std::abs(nearest_zero));
  EXPECT_TRUE(margin.decided());
  EXPECT_LT(margin.round_off, 1e-6 * std::abs(nearest_zero));
}

TEST(StabilityMargin, EigenvalueNearestZeroMatchesDenseSolver) {
  expect_margin_matches_dense(loaded_column(41, 0.0, -2.0));   // a bent cantilever: definite
  expect_margin_matches_dense(loaded_column(41, -1.5, 0.0));   // a straight column past buckling: one negative
}

TEST(StabilityMargin, CoarseColumnPastBucklingIsDecidedUnstable) {
  const StaticReport r = solve(loaded_column(81, -1.5, 0.0));
  EXPECT_EQ(r.negative_pivots, 1);
  EXPECT_FALSE(r.stability_undecided);
  EXPECT_LT(r.smallest_eigenvalue, 0.0);
}

TEST(StabilityMargin, FineColumnPastBucklingIsNeverCalledStable) {
  const StaticReport r = solve(loaded_column(10001, -1.5, 0.0));
  EXPECT_TRUE(r.negative_pivots > 0 || r.stability_undecided)
      << "negative pivots " << r.negative_pivots << ", eigenvalue " << r.smallest_eigenvalue << " N/m, round-off "
      << r.eigenvalue_round_off << " N/m";
}

}  // namespace
}  // namespace vascsim

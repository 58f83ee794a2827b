// The elastic element energies (sim/rod/elastic_energy.h): analytic gradient and Hessian against
// central finite differences, Hessian symmetry, invariance under rigid motion, and the course
// values of docs/references.md section 6.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include <Eigen/Geometry>

#include "sim/rod/elastic_energy.h"
#include "sim/rod/rod_model.h"
#include "sim/step/elastic_assembly.h"
#include "tests/compare_matrices.h"

namespace vascsim {
namespace {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

Vec2 node(const Eigen::VectorXd& q, int i) { return q.segment<2>(2 * i); }

double stretch_e(const Eigen::VectorXd& q) { return stretch_energy(node(q, 0), node(q, 1), 3.0, 0.7).energy; }
double bend_e(const Eigen::VectorXd& q, double k0) {
  return bend_energy(node(q, 0), node(q, 1), node(q, 2), 2.0, 0.3, k0).energy;
}

// Central differences of f, with step h.
template <typename F>
Eigen::VectorXd fd_gradient(F f, Eigen::VectorXd q, double h) {
  Eigen::VectorXd g(q.size());
  for (int i = 0; i < q.size(); ++i) {
    const double q0 = q[i];
    q[i] = q0 + h;
    const double fp = f(q);
    q[i] = q0 - h;
    const double fm = f(q);
    q[i] = q0;
    g[i] = (fp - fm) / (2 * h);
  }
  return g;
}

// Relative to the expected values' size (at least 1).
::testing::AssertionResult close(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double tol) {
  return test::matrices_near(a, b, tol * std::max(1.0, b.cwiseAbs().maxCoeff()));
}

TEST(StretchEnergy, GradientAndHessianMatchFiniteDifferences) {
  Eigen::VectorXd q(4);
  for (const Vec<4>& p : {Vec<4>(0.1, 0.2, 0.9, -0.3), Vec<4>(0.0, 0.0, 0.3, 0.1) /* compressed */}) {
    q = p;
    const StretchElement s = stretch_energy(node(q, 0), node(q, 1), 3.0, 0.7);
    EXPECT_TRUE(close(s.gradient, fd_gradient(stretch_e, q, 1e-6), 1e-8));
    Eigen::MatrixXd h(4, 4);
    for (int j = 0; j < 4; ++j) {
      auto gj = [&](const Eigen::VectorXd& r) { return stretch_energy(node(r, 0), node(r, 1), 3.0, 0.7).gradient[j]; };
      h.row(j) = fd_gradient(gj, q, 1e-6).transpose();
    }
    EXPECT_TRUE(close(s.hessian(), h, 1e-7));
    EXPECT_TRUE(close(s.hessian(), s.hessian().transpose(), 1e-15));
  }
}

TEST(BendEnergy, GradientAndHessianMatchFiniteDifferences) {
  Eigen::VectorXd q(6);
  // A gentle bend, a sharp one (~150 degrees), and one with rest curvature.
  const Vec<6> shapes[] = {Vec<6>(0.0, 0.0, 0.3, 0.05, 0.6, 0.0), Vec<6>(0.0, 0.0, 0.3, 0.0, 0.05, 0.12),
                           Vec<6>(0.1, -0.2, 0.35, 0.1, 0.5, 0.45)};
  for (double k0 : {0.0, 0.4}) {
    for (const auto& shape : shapes) {
      q = shape;
      const BendElement b = bend_energy(node(q, 0), node(q, 1), node(q, 2), 2.0, 0.3, k0);
      auto e = [&](const Eigen::VectorXd& r) { return bend_e(r, k0); };
      EXPECT_TRUE(close(b.gradient, fd_gradient(e, q, 1e-6), 1e-7));
      Eigen::MatrixXd h(6, 6);
      for (int j = 0; j < 6; ++j) {
        auto gj = [&](const Eigen::VectorXd& r) {
          return bend_energy(node(r, 0), node(r, 1), node(r, 2), 2.0, 0.3, k0).gradient[j];
        };
        h.row(j) = fd_gradient(gj, q, 1e-6).transpose();
      }
      EXPECT_TRUE(close(b.hessian(), h, 1e-6));
      EXPECT_TRUE(close(b.hessian(), b.hessian().transpose(), 1e-14));
    }
  }
}

// Rigid motions (translation, rotation) leave both energies unchanged; their generators lie in
// the Hessian's null space only at equilibrium, but the gradient is always orthogonal to them.
TEST(ElasticEnergy, InvariantUnderRigidMotion) {
  const Vec<6> q(0.1, -0.2, 0.35, 0.1, 0.5, 0.45);
  const double angle = 0.7;
  const Eigen::Matrix2d r = Eigen::Rotation2Dd(angle).toRotationMatrix();
  const Vec2 shift(3.0, -1.5);
  Vec<6> moved;
  for (int i = 0; i < 3; ++i) moved.segment<2>(2 * i) = r * q.segment<2>(2 * i) + shift;
  const BendElement b0 = bend_energy(q.segment<2>(0), q.segment<2>(2), q.segment<2>(4), 2.0, 0.3, 0.2);
  const BendElement b1 = bend_energy(moved.segment<2>(0), moved.segment<2>(2), moved.segment<2>(4), 2.0, 0.3, 0.2);
  EXPECT_NEAR(b0.energy, b1.energy, 1e-13);
  const StretchElement s0 = stretch_energy(q.segment<2>(0), q.segment<2>(2), 3.0, 0.2);
  const StretchElement s1 = stretch_energy(moved.segment<2>(0), moved.segment<2>(2), 3.0, 0.2);
  EXPECT_NEAR(s0.energy, s1.energy, 1e-13);
  // The gradient rotates with the rod and sums to zero (no net force), with no net moment.
  Vec2 sum = Vec2::Zero();
  double moment = 0.0;
  for (int i = 0; i < 3; ++i) {
    const Vec2 g = b0.gradient.segment<2>(2 * i);
    sum += g;
    moment += q[2 * i] * g.y() - q[2 * i + 1] * g.x();
    EXPECT_TRUE(close(b1.gradient.segment<2>(2 * i), r * g, 1e-12));
  }
  EXPECT_NEAR(sum.norm(), 0.0, 1e-12);
  EXPECT_NEAR(moment, 0.0, 1e-12);
  // Translations are in the Hessian's null space.
  Vec<6> tx, ty;
  tx << 1, 0, 1, 0, 1, 0;
  ty << 0, 1, 0, 1, 0, 1;
  EXPECT_NEAR((b0.hessian() * tx).norm(), 0.0, 1e-10);
  EXPECT_NEAR((b0.hessian() * ty).norm(), 0.0, 1e-10);
}

// docs/references.md section 6 (UCLA MAE 263F course values).
TEST(ElasticEnergy, MatchesCourseUnitVectors) {
  const Vec<6> q(0.0062, -0.0420, 0.0500, -0.0661, 0.0938, -0.0420);
  const BendElement b = bend_energy(q.segment<2>(0), q.segment<2>(2), q.segment<2>(4), 7.8540e-4, 0.05, 0.0);
  Vec<6> expected;
  expected << -0.217151, -0.394657, 0, 0.789314, 0.217151, -0.394657;
  EXPECT_TRUE(close(-b.gradient, expected, 2e-6));
  const StretchElement s = stretch_energy(q.segment<2>(0), q.segment<2>(2), 3.1416e3, 0.05);
  Vec<4> expected_s(0.412899, -0.227189, -0.412899, 0.227189);
  EXPECT_TRUE(close(s.gradient, expected_s, 2e-6));
}

TEST(ElasticEnergy, CurvatureIsTwoTanHalfTurn) {
  // A right angle: phi = pi/2, kappa = 2 tan(pi/4) = 2, counter-clockwise positive.
  EXPECT_NEAR(discrete_curvature(Vec2(0, 0), Vec2(1, 0), Vec2(1, 1)), 2.0, 1e-15);
  EXPECT_NEAR(discrete_curvature(Vec2(0, 0), Vec2(1, 0), Vec2(1, -1)), -2.0, 1e-15);
}

// The hand-written assembly (sim/step/elastic_assembly.cpp) against the sum of the element
// functions tested above, on a rod with uneven edges, rest curvature and a random bent shape.
TEST(ElasticAssembly, EqualsTheSumOfTheElementFunctions) {
  RodSpec spec;
  spec.nodes = 9;
  ShapeSpec shape;
  shape.rest_curvature = 3.0;
  RodModel rod = build_rod_model(spec, shape, ClampKind::kNone);
  std::srand(5);
  for (int e = 0; e + 1 < rod.nodes; ++e) rod.rest_length[e] *= 1.0 + 0.2 * (std::rand() / double(RAND_MAX) - 0.5);
  rod.stretch_stiffness = rod.ea * rod.rest_length.cwiseInverse();  // the constant the model derives
  Eigen::VectorXd x = rod.x_initial + 0.01 * Eigen::VectorXd::Random(2 * rod.nodes);
  const int dofs = 2 * rod.nodes;

  Eigen::VectorXd want_gradient = Eigen::VectorXd::Zero(dofs);
  Eigen::MatrixXd want_hessian = Eigen::MatrixXd::Zero(dofs, dofs);
  for (int e = 0; e + 1 < rod.nodes; ++e) {
    const StretchElement s = stretch_energy(node(x, e), node(x, e + 1), rod.ea, rod.rest_length[e]);
    want_gradient.segment<4>(2 * e) += s.gradient;
    want_hessian.block<4, 4>(2 * e, 2 * e) += s.hessian();
  }
  for (int i = 1; i + 1 < rod.nodes; ++i) {
    const BendElement b = bend_energy(node(x, i - 1), node(x, i), node(x, i + 1), rod.ei, rod.voronoi[i], rod.rest_kappa[i]);
    want_gradient.segment<6>(2 * i - 2) += b.gradient;
    want_hessian.block<6, 6>(2 * i - 2, 2 * i - 2) += b.hessian();
  }

  ElasticScratch scratch(rod);
  Eigen::VectorXd gradient(dofs);
  BandedMatrix hessian(dofs);
  assemble_elastic(rod, x, scratch, gradient, &hessian);
  EXPECT_LT((gradient - want_gradient).lpNorm<Eigen::Infinity>(), 1e-10 * want_gradient.lpNorm<Eigen::Infinity>());
  EXPECT_LT((hessian.to_dense() - want_hessian).lpNorm<Eigen::Infinity>(), 1e-10 * want_hessian.lpNorm<Eigen::Infinity>());
  ASSERT_GT(std::abs(want_gradient[5]), 0.0) << "the shape must be stressed";
}

}  // namespace
}  // namespace vascsim

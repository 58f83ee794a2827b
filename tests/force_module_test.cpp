// Every force module against its own force: the Newton matrix it adds is minus the Jacobian of
// its force along the time scheme, K = -(dF/dx + dv_dx dF/dv) with v = (x - x_hat) dv_dx,
// checked by central finite differences; that Jacobian is symmetric and within the band the
// solver stores (|i - j| <= 5). One rig per module, each in a state where its force is active.
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>

#include "sim/contact/paper_contact.h"
#include "sim/contact/wall_contact.h"
#include "sim/control/tip_magnet_module.h"
#include "sim/control/tip_servo_module.h"
#include "sim/rod/loads.h"
#include "tests/compare_matrices.h"

namespace vascsim {
namespace {

constexpr int kNodes = 6;

RodModel bent_rod() {
  RodSpec spec;
  spec.nodes = kNodes;
  spec.length = 0.02;
  ShapeSpec shape;
  return build_rod_model(spec, shape, ClampKind::kNone);
}

// The state a module is evaluated at: positions, the start of the step (for lagged quantities),
// the step's controls and the scheme's dv/dx.
struct Rig {
  std::shared_ptr<const ForceModule> module;
  Eigen::VectorXd x;      // (2N), m
  Eigen::VectorXd v;      // (2N), m/s at x
  State start;
  Controls controls;
  double dv_dx = 500.0;   // 1/s: backward Euler at dt = 2 ms
};

// A gently curved configuration with velocities, near the origin.
Rig base_rig(std::shared_ptr<const ForceModule> module) {
  Rig r;
  r.module = std::move(module);
  r.x.resize(2 * kNodes);
  r.v.resize(2 * kNodes);
  for (int i = 0; i < kNodes; ++i) {
    r.x.segment<2>(2 * i) = Vec2(0.004 * i, 0.0005 * std::sin(0.9 * i));
    r.v.segment<2>(2 * i) = Vec2(0.002 + 0.001 * std::cos(i), -0.003 + 0.0004 * i);
  }
  r.start.x = r.x - r.v / r.dv_dx;  // where the step began
  r.start.v = r.v;
  return r;
}

struct ModuleCase {
  std::string name;
  std::function<Rig()> make;
};

std::vector<ModuleCase> module_cases() {
  const RodModel rod = bent_rod();
  const ContactParams contact{rod.outer_radius, 1e-3, 0.01, 0.3, 1e-2};
  // A floor just under the rod: nodes 0..5 at gaps within the barrier's reach.
  const std::vector<WallSegment> floor = {{Vec2(-1, -rod.outer_radius - 6e-4), Vec2(1, -rod.outer_radius - 6e-4), 0.0}};
  std::vector<ModuleCase> cases;
  cases.push_back({"gravity", [rod] { return base_rig(std::make_shared<GravityModule>(rod, Vec2(0.3, -9.81))); }});
  cases.push_back({"point_force_and_moment", [] {
                     PointLoadSpec a, b;
                     a.node = -1;
                     a.force = Vec2(1e-3, 2e-3);
                     b.node = 2;
                     b.moment = 3e-5;
                     return base_rig(std::make_shared<PointLoadModule>(kNodes, std::vector<PointLoadSpec>{a, b}));
                   }});
  // Each load alone too, with time profiles: the stiffness must carry the same factor
  // load_scale * profile(t) as the force (the rigs run at load_scale 0.7, t = 0.5 s). The moment
  // acts on the edge ending at its node, edge 0 for node 0.
  cases.push_back({"point_force_ramp", [] {
                     PointLoadSpec a;
                     a.node = -1;
                     a.force = Vec2(-2e-3, 1e-3);
                     a.profile = LoadProfile::kRamp;
                     a.ramp_time = 2.0;
                     return base_rig(std::make_shared<PointLoadModule>(kNodes, std::vector<PointLoadSpec>{a}));
                   }});
  cases.push_back({"point_moment_tip_sine", [] {
                     PointLoadSpec m;
                     m.node = -1;
                     m.moment = -4e-5;
                     m.profile = LoadProfile::kSine;
                     m.frequency = 0.3;
                     m.phase = 0.4;
                     return base_rig(std::make_shared<PointLoadModule>(kNodes, std::vector<PointLoadSpec>{m}));
                   }});
  cases.push_back({"point_moment_root", [] {
                     PointLoadSpec m;
                     m.node = 0;
                     m.moment = 2e-5;
                     return base_rig(std::make_shared<PointLoadModule>(kNodes, std::vector<PointLoadSpec>{m}));
                   }});
  cases.push_back({"viscous_damping", [rod] { return base_rig(std::make_shared<ViscousDampingModule>(rod, 0.4)); }});
  cases.push_back({"drag_tip", [rod] {
                     DragSpec d;
                     d.enabled = true;
                     d.area = DragArea::kTipFrontal;
                     return base_rig(std::make_shared<QuadraticDragModule>(rod, d));
                   }});
  cases.push_back({"drag_nodes", [rod] {
                     DragSpec d;
                     d.enabled = true;
                     return base_rig(std::make_shared<QuadraticDragModule>(rod, d));
                   }});
  cases.push_back({"tip_servo", [] {
                     Rig r = base_rig(std::make_shared<TipServoModule>(kNodes));
                     TipServo& s = r.controls.servo;
                     s.active = true;
                     s.first_node = kNodes - 3;
                     s.feedforward = Vec2(1e-4, -2e-4);
                     s.position = Vec2(0.03, 0.001);
                     s.velocity = Vec2(0.05, 0.0);
                     s.kp = 4.0;
                     s.kd = 0.3;
                     return r;
                   }});
  cases.push_back({"tip_magnet", [] {
                     Rig r = base_rig(std::make_shared<TipMagnetModule>(kNodes, 1e-3));
                     r.controls.field = Vec2(0.02, 0.05);
                     return r;
                   }});
  cases.push_back({"wall_contact", [rod, contact, floor] {
                     return base_rig(std::make_shared<WallContactModule>(floor, rod, contact));
                   }});
  cases.push_back({"wall_friction", [rod, contact, floor] {
                     Rig r = base_rig(std::make_shared<WallFrictionModule>(floor, rod, contact));
                     // Sliding slower than the slip velocity on some nodes (the stick regime has stiffness).
                     for (int i = 0; i < kNodes; ++i) r.v[2 * i] = (i % 2 ? 0.004 : 0.03) * (i < 3 ? 1 : -1);
                     r.start.x = r.x - r.v / r.dv_dx;
                     return r;
                   }});
  cases.push_back({"explicit_wall_force", [] {
                     Rig r = base_rig(std::make_shared<ExplicitWallForceModule>(kNodes));
                     r.controls.wall_forces = {{1, Vec2(0.0, 2e-3)}, {-1, Vec2(-1e-3, 0.0)}};
                     return r;
                   }});
  return cases;
}

class ForceModuleJacobian : public ::testing::TestWithParam<ModuleCase> {};

// F at x, with the velocity the scheme implies there.
Eigen::VectorXd force_at(const Rig& r, const Eigen::VectorXd& x, BandedMatrix* k = nullptr) {
  const Eigen::VectorXd x_hat = r.x - r.v / r.dv_dx;
  const Eigen::VectorXd v = (x - x_hat) * r.dv_dx;
  ForceContext ctx;
  ctx.t = 0.5;
  ctx.x = &x;
  ctx.v = &v;
  ctx.dv_dx = r.dv_dx;
  ctx.load_scale = 0.7;  // a static load increment: applied loads and their stiffness scale alike
  ctx.controls = &r.controls;
  ctx.start = &r.start;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(x.size());
  r.module->add(ctx, f, k);
  return f;
}

TEST_P(ForceModuleJacobian, StiffnessIsMinusTheForceJacobianSymmetricAndBanded) {
  const Rig r = GetParam().make();
  const int n = static_cast<int>(r.x.size());
  BandedMatrix k(n);
  const Eigen::VectorXd f = force_at(r, r.x, &k);
  ASSERT_TRUE(f.allFinite());
  ASSERT_GT(f.norm(), 0.0) << "the rig must make the force act";
  // Central differences: 1e-8 m balances truncation (the barrier is stiff at 1e-4 m gaps) and
  // round-off (1e-10 m loses the contact force to cancellation).
  const double h = 1e-8;
  Eigen::MatrixXd jacobian(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd up = r.x, down = r.x;
    up[j] += h;
    down[j] -= h;
    jacobian.col(j) = (force_at(r, up) - force_at(r, down)) / (2 * h);
  }
  const Eigen::MatrixXd expected = -jacobian;
  const double scale = std::max(expected.cwiseAbs().maxCoeff(), 1e-3 * f.cwiseAbs().maxCoeff() / 1e-3);
  EXPECT_TRUE(test::matrices_near(k.to_dense(), expected, 1e-5 * scale)) << GetParam().name;
  EXPECT_TRUE(test::matrices_near(expected, expected.transpose(), 1e-5 * scale)) << GetParam().name << ": not symmetric";
  Eigen::MatrixXd outside = expected;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (std::abs(i - j) <= BandedMatrix::kHalfBandwidth) outside(i, j) = 0.0;
  EXPECT_TRUE(test::matrices_near(outside, Eigen::MatrixXd::Zero(n, n), 1e-9 * scale)) << GetParam().name << ": outside the band";
}

INSTANTIATE_TEST_SUITE_P(EveryModule, ForceModuleJacobian, ::testing::ValuesIn(module_cases()),
                         [](const ::testing::TestParamInfo<ModuleCase>& info) { return info.param.name; });

}  // namespace
}  // namespace vascsim

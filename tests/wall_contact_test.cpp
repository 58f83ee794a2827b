// Implicit wall contact and the tip magnet as element energies: forces are minus the gradient of
// the energy (central finite differences) and the step cap keeps every gap open. (The Newton
// matrix of every module against its force Jacobian: force_module_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>

#include "sim/contact/wall_contact.h"
#include "sim/control/tip_magnet_energy.h"
#include "tests/compare_matrices.h"

namespace vascsim {
namespace {

RodModel three_node_rod() {
  RodSpec spec;
  spec.nodes = 3;
  spec.length = 0.02;
  ShapeSpec shape;
  return build_rod_model(spec, shape, ClampKind::kNone);
}

Eigen::VectorXd contact_force(const WallContactModule& m, const Eigen::VectorXd& x, BandedMatrix* k = nullptr) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(x.size());
  ForceContext ctx;
  ctx.x = &x;
  ctx.v = &x;
  m.add(ctx, f, k);
  return f;
}

TEST(WallContact, ForceIsMinusEnergyGradientForNodesAndCorners) {
  const RodModel rod = three_node_rod();
  const ContactParams params{2e-3, 1e-3, 0.01, 0.0, 1e-4};
  // A thick wall whose rounded end pokes between the rod's nodes, and a thin wall under node 0.
  const std::vector<WallSegment> walls = {{Vec2(0.01, 0.0035), Vec2(0.01, 0.05), 0.002},
                                          {Vec2(-0.05, -0.0025), Vec2(0.05, -0.0025), 0.0}};
  WallContactModule module(walls, rod, params);
  Eigen::VectorXd x(6);
  x << 0.0, 0.0003, 0.0098, 0.0, 0.0198, 0.0003;
  ASSERT_GT(module.energy(x), 0.0) << "the configuration must touch both walls";
  const Eigen::VectorXd f = contact_force(module, x);
  const double h = 1e-8;
  for (int i = 0; i < 6; ++i) {
    Eigen::VectorXd up = x, down = x;
    up[i] += h;
    down[i] -= h;
    const double fd = -(module.energy(up) - module.energy(down)) / (2 * h);
    EXPECT_NEAR(f[i], fd, 1e-6 * f.cwiseAbs().maxCoeff()) << "dof " << i;
  }
  // The corner above the middle node pushes it down, the floor pushes the end nodes up.
  EXPECT_LT(f[3], 0.0);
  EXPECT_GT(f[1], 0.0);
}

// Neighbour lists kept between calls must never hide a pair: a rod wandering through a
// thick-walled maze, in small and large moves, sees exactly the pairs and the step cap that
// fresh (empty) lists find at every position, and the smallest gap among them.
TEST(WallContact, ReusedNeighbourListsFindTheSamePairsAsAFreshSearch) {
  std::vector<WallSegment> walls = {{Vec2(0, 0), Vec2(0.2, 0), 0.02}, {Vec2(0.2, 0), Vec2(0.2, 0.2), 0.02},
                                    {Vec2(0.1, 0.05), Vec2(0.1, 0.15), 0.02}, {Vec2(0, 0.2), Vec2(0.2, 0.2), 0.0}};
  for (int i = 1; i < 8; ++i)  // round pillars: corners that only edges touch
    for (int j = 1; j < 8; ++j) walls.push_back({Vec2(0.025 * i, 0.025 * j), Vec2(0.025 * i, 0.025 * j), 0.006});
  const double radius = 0.002, reach = 0.001, edge = 0.01;
  const ContactGeometry geometry(walls, radius, reach, edge);
  ContactNeighbours reused;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0), jiggle(-1.0, 1.0);
  const int nodes = 8;
  Eigen::VectorXd x(2 * nodes);
  int pairs_seen = 0, edge_pairs_seen = 0;
  Eigen::VectorXd shape(2 * nodes);
  for (int trial = 0; trial < 3000; ++trial) {
    if (trial % 300 == 0) {  // a fresh rod somewhere in the box
      const Vec2 start(0.02 + 0.16 * unit(rng), 0.02 + 0.16 * unit(rng));
      const double angle = 6.283 * unit(rng);
      for (int i = 0; i < nodes; ++i) shape.segment<2>(2 * i) = start + 0.9 * edge * i * Vec2(std::cos(angle), std::sin(angle));
    }
    // The rod drifts as a whole (edges keep their length, as a rod's do), mostly in small moves
    // and sometimes beyond the lists' margin, with a little independent noise per node.
    const double size = trial % 7 == 0 ? 4e-3 : 2e-4;  // m
    const Vec2 drift(size * jiggle(rng), size * jiggle(rng));
    for (int i = 0; i < nodes; ++i) shape.segment<2>(2 * i) += drift;
    for (int i = 0; i < 2 * nodes; ++i) x[i] = shape[i] + 2e-4 * jiggle(rng);
    std::vector<std::tuple<int, bool, double>> got, want;
    geometry.for_each_pair(x, false, [&](const ContactPair& p) { got.emplace_back(p.first_dof, p.is_edge, p.gap); }, reused);
    ContactNeighbours fresh;
    geometry.for_each_pair(x, false, [&](const ContactPair& p) { want.emplace_back(p.first_dof, p.is_edge, p.gap); }, fresh);
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    ASSERT_EQ(got, want) << "trial " << trial;
    // The distance-only smallest gap (frame checks, statistics) is the smallest visited pair's.
    double smallest = std::numeric_limits<double>::infinity();
    for (const auto& pair : want) smallest = std::min(smallest, std::get<2>(pair));
    if (std::isinf(smallest))
      ASSERT_EQ(geometry.min_pair_gap(x, reused), smallest) << "trial " << trial;
    else
      ASSERT_NEAR(geometry.min_pair_gap(x, reused), smallest, 1e-15) << "trial " << trial;
    // The step cap reads the same lists for small moves and the grids for large ones.
    Eigen::VectorXd dx(2 * nodes);
    // m, per coordinate: beyond and up to the lists' margin for a move, reach + skin/2 = 4 mm
    // (skin 2 (r + reach), contact_pairs.cpp), a node moving up to sqrt 2 times this.
    const double move = trial % 3 == 0 ? 6e-3 : 2.8e-3;
    for (int i = 0; i < 2 * nodes; ++i) dx[i] = move * jiggle(rng);
    ContactNeighbours fresh_for_step;
    ASSERT_EQ(geometry.max_step_fraction(x, dx, 0.5, reused), geometry.max_step_fraction(x, dx, 0.5, fresh_for_step))
        << "trial " << trial;
    pairs_seen += static_cast<int>(want.size());
    for (const auto& pair : want) edge_pairs_seen += std::get<1>(pair);
  }
  EXPECT_GT(pairs_seen, 100) << "the walk must actually touch walls";
  EXPECT_GT(edge_pairs_seen, 100) << "and wall corners between nodes";
}

// The grids are sized for the rod's longest rest edge; an edge stretched far beyond it still
// finds a wall corner near its middle third (closed form: centre distance minus both radii).
TEST(WallContact, EdgeStretchedBeyondTheDeclaredLengthStillMeetsCorners) {
  const std::vector<WallSegment> pillar = {{Vec2(0.05, 0.0), Vec2(0.05, 0.0), 0.006}};  // radius 3 mm
  const double radius = 0.002, reach = 0.001, declared_edge = 0.01;
  Eigen::VectorXd x(4);
  x << 0.0, 0.0055, 0.5, 0.0055;  // one 0.5 m edge, 5.5 mm above the pillar's centre
  std::vector<std::pair<bool, double>> pairs;
  ContactNeighbours neighbours;
  ContactGeometry(pillar, radius, reach, declared_edge)
      .for_each_pair(x, false, [&](const ContactPair& p) { pairs.emplace_back(p.is_edge, p.gap); }, neighbours);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_TRUE(pairs[0].first);
  EXPECT_NEAR(pairs[0].second, 0.0055 - 0.003 - radius, 1e-15);
}

// A node sliding along a wall it presses on feels kinetic friction mu * N against its motion,
// also when asked at a committed state (ForceContext::at, dv_dx = 0): that is how frames are
// logged, and a log once showed zero friction throughout a run whose rod slid on walls.
TEST(WallFriction, OpposesSlidingAtACommittedState) {
  const RodModel rod = three_node_rod();
  const ContactParams params{2e-3, 1e-3, 0.01, 0.3, 1e-4};
  const std::vector<WallSegment> floor = {{Vec2(-0.05, -0.0025), Vec2(0.05, -0.0025), 0.0}};
  const WallContactModule contact(floor, rod, params);
  const WallFrictionModule friction(floor, rod, params);
  State state;
  state.x.resize(6);
  state.x << 0.0, 0.0003, 0.0098, 0.003, 0.0198, 0.003;  // node 0 within reach of the floor
  state.v.setZero(6);
  state.v[0] = 0.01;  // m/s along +x, far above the slip velocity
  const Controls controls;
  const ForceContext ctx = ForceContext::at(state, controls);
  Eigen::VectorXd normal = Eigen::VectorXd::Zero(6), tangential = Eigen::VectorXd::Zero(6);
  contact.add(ctx, normal, nullptr);
  friction.add(ctx, tangential, nullptr);
  ASSERT_GT(normal[1], 0.0) << "the floor must push node 0 up";
  EXPECT_NEAR(tangential[0], -0.3 * normal[1], 1e-12 * normal[1]);
  EXPECT_EQ(tangential[1], 0.0);
  EXPECT_EQ(tangential.tail<4>().norm(), 0.0) << "nodes 1 and 2 touch nothing";
}

// Contact and friction on one geometry keep one set of neighbour lists in a run (SharedCaches,
// keyed by the geometry): friction at the committed state reuses the lists contact built, and
// both give what they give on lists of their own.
TEST(WallFriction, SharesContactsNeighbourListsInARun) {
  const RodModel rod = three_node_rod();
  const ContactParams params{2e-3, 1e-3, 0.01, 0.3, 1e-4};
  const std::vector<WallSegment> floor = {{Vec2(-0.05, -0.0025), Vec2(0.05, -0.0025), 0.0}};
  const auto geometry = make_contact_geometry(floor, rod, params);
  const WallContactModule contact(geometry, params);
  const WallFrictionModule friction(geometry, params);
  State state;
  state.x.resize(6);
  state.x << 0.0, 0.0003, 0.0098, 0.003, 0.0198, 0.003;
  state.v.setZero(6);
  state.v[0] = 0.01;
  const Controls controls;
  SharedCaches shared;
  ForceContext ctx = ForceContext::at(state, controls);
  ctx.shared = &shared;
  Eigen::VectorXd normal = Eigen::VectorXd::Zero(6), tangential = Eigen::VectorXd::Zero(6);
  contact.add(ctx, normal, nullptr);
  const ContactNeighbours& lists = shared.of<ContactNeighboursCache>(geometry.get()).lists;
  ASSERT_EQ(lists.anchor, state.x) << "contact built the run's lists at its positions";
  const std::vector<int> walls_of_nodes = lists.node_walls;
  friction.add(ctx, tangential, nullptr);
  EXPECT_EQ(&lists, &shared.of<ContactNeighboursCache>(geometry.get()).lists);
  EXPECT_EQ(lists.node_walls, walls_of_nodes) << "friction at the same positions must not rebuild them";
  {
    // Friction reads these lists, not lists of its own: emptied (still anchored here), it finds
    // no wall and so no friction.
    SharedCaches emptied;
    ContactNeighbours& none = emptied.of<ContactNeighboursCache>(geometry.get()).lists;
    none = lists;
    std::fill(none.node_begin.begin(), none.node_begin.end(), 0);
    none.node_walls.clear();
    ForceContext ctx_emptied = ForceContext::at(state, controls);
    ctx_emptied.shared = &emptied;
    Eigen::VectorXd no_friction = Eigen::VectorXd::Zero(6);
    friction.add(ctx_emptied, no_friction, nullptr);
    ASSERT_GT(tangential.norm(), 0.0) << "with the lists, node 0 slides on the floor";
    EXPECT_EQ(no_friction.norm(), 0.0);
  }
  // The same forces as without shared caches.
  const ForceContext alone = ForceContext::at(state, controls);
  Eigen::VectorXd normal_alone = Eigen::VectorXd::Zero(6), tangential_alone = Eigen::VectorXd::Zero(6);
  contact.add(alone, normal_alone, nullptr);
  friction.add(alone, tangential_alone, nullptr);
  EXPECT_EQ(normal, normal_alone);
  EXPECT_EQ(tangential, tangential_alone);
  ASSERT_GT(normal[1], 0.0);
  // Another owner has an entry of its own.
  EXPECT_NE(&shared.of<ContactNeighboursCache>(&rod).lists, &lists);
}

// The smallest gap over the straight move from x to x + dx, sampled finely (m).
double smallest_gap_along(const WallContactModule& module, const Eigen::VectorXd& x, const Eigen::VectorXd& dx) {
  double gap = module.geometry().min_gap(x, 1.0);
  for (int k = 1; k <= 200; ++k) gap = std::min(gap, module.geometry().min_gap(x + (k / 200.0) * dx, 1.0));
  return gap;
}

// The cap keeps every gap open all along the move, not only at its end (a move that could close
// a gap keeps a share, 1 - 0.8, of it): a barrier must never see a closed gap.
TEST(WallContact, StepCapKeepsEveryGapOpen) {
  const RodModel rod = three_node_rod();
  const ContactParams params{2e-3, 5e-4, 0.01, 0.0, 1e-4};
  const std::vector<WallSegment> walls = {{Vec2(-1, -0.01), Vec2(1, -0.01), 0.004},
                                          {Vec2(0.01, 0.004), Vec2(0.01, 1.0), 0.0}};
  WallContactModule module(walls, rod, params);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n(0.0, 0.02);
  Eigen::VectorXd x(6);
  x << 0.0, 0.0, 0.01, -0.001, 0.02, 0.0;
  ForceContext ctx;
  ctx.x = &x;
  ASSERT_GT(module.geometry().min_gap(x, 1.0), 0.0);
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::VectorXd dx(6);
    for (int i = 0; i < 6; ++i) dx[i] = n(rng);
    const double alpha = module.max_step_fraction(ctx, dx);
    ASSERT_GE(alpha, 0.0);
    ASSERT_LE(alpha, 1.0);
    EXPECT_GT(smallest_gap_along(module, x, alpha * dx), 0.0) << "trial " << trial;
  }
}

// A rod lying along a floor, or an edge passing under a wall's corner, may slide far in one step: the
// cap bounds how close a move comes to a wall, not how long it is (a bound by the move's length
// cut the steps of a rod sliding along a wall and cost Newton iterations, docs/contact.md). A
// move towards the wall is still cut.
TEST(WallContact, StepCapLetsTheRodSlideAlongAWallAndPastACorner) {
  const RodModel rod = three_node_rod();  // 0.02 m long, outer radius 2 mm
  const ContactParams params{2e-3, 5e-4, 0.01, 0.0, 1e-4};
  // A floor whose surface is 0.3 mm below the rod's, and a wall ending 0.4 mm above the rod's
  // middle edge's surface at x = 0.005 (its end is a corner).
  const double r = rod.outer_radius;
  const std::vector<WallSegment> walls = {{Vec2(-1, -r - 3e-4), Vec2(1, -r - 3e-4), 0.0},
                                          {Vec2(0.005, r + 4e-4), Vec2(0.005, 1.0), 0.0}};
  WallContactModule module(walls, rod, params);
  Eigen::VectorXd x(6);
  x << 0.0, 0.0, 0.01, 0.0, 0.02, 0.0;
  ForceContext ctx;
  ctx.x = &x;
  ASSERT_NEAR(module.geometry().min_gap(x, 1.0), 3e-4, 1e-12);
  Eigen::VectorXd along(6), towards(6);
  // 2.5 mm along the floor (8x the gap; within the neighbour lists' reach), the first edge under
  // the corner all the way.
  along << 2.5e-3, 0.0, 2.5e-3, 0.0, 2.5e-3, 0.0;
  towards << 0.0, -3.5e-4, 0.0, -3.5e-4, 0.0, -3.5e-4;  // through the floor
  EXPECT_EQ(module.max_step_fraction(ctx, along), 1.0);
  EXPECT_GT(smallest_gap_along(module, x, along), 0.2 * 3e-4);
  const double cut = module.max_step_fraction(ctx, towards);
  EXPECT_LT(cut, 1.0);
  EXPECT_GT(smallest_gap_along(module, x, cut * towards), 0.2 * 3e-4 * (1 - 1e-9));
}

TEST(TipMagnet, GradientAndHessianMatchFiniteDifferencesAndTorque) {
  const Eigen::Vector2d a(0.1, 0.2), b(0.13, 0.21), field(0.3, -0.7);
  const double moment = 0.05;
  const EdgeEnergy e = tip_magnet_energy(a, b, moment, field);
  Eigen::Vector4d y;
  y << a, b;
  const double h = 1e-7;
  for (int i = 0; i < 4; ++i) {
    Eigen::Vector4d up = y, down = y;
    up[i] += h;
    down[i] -= h;
    const auto eu = tip_magnet_energy(up.head<2>(), up.tail<2>(), moment, field);
    const auto ed = tip_magnet_energy(down.head<2>(), down.tail<2>(), moment, field);
    EXPECT_NEAR(e.gradient[i], (eu.energy - ed.energy) / (2 * h), 1e-6 * e.gradient.norm());
    EXPECT_TRUE(test::matrices_near(e.hessian.col(i), (eu.gradient - ed.gradient) / (2 * h), 1e-5 * e.hessian.norm()));
  }
  EXPECT_TRUE(test::matrices_near(e.hessian, e.hessian.transpose(), 1e-12 * e.hessian.norm()));
  // A uniform field exerts no net force, and the moment of the edge forces is the torque m x B.
  EXPECT_LT((e.gradient.head<2>() + e.gradient.tail<2>()).norm(), 1e-12);
  const Eigen::Vector2d t = (b - a).normalized();
  const Eigen::Vector2d force_on_tip = -e.gradient.tail<2>();
  const Eigen::Vector2d arm = b - a;
  const double torque = arm.x() * force_on_tip.y() - arm.y() * force_on_tip.x();
  EXPECT_NEAR(torque, moment * (t.x() * field.y() - t.y() * field.x()), 1e-12);
}

}  // namespace
}  // namespace vascsim

// Supports per axis (boundary.supports: a node held in x only or y only) against a reference
// the code did not produce: a simply supported Euler-Bernoulli beam under its own weight, pinned
// at one end and on a roller at the other, sags at mid-span by 5 w L^4 / (384 EI) (Timoshenko &
// Gere, Mechanics of Materials, table of beam deflections), w = rho A g per metre. The roller lets
// its end slide inwards as the beam bends; a pin there instead would stretch it.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "sim/io/log_metadata.h"
#include "sim/io/run_log.h"
#include "sim/io/scene_reader.h"
#include "sim/run/run.h"
#include "sim/run/compile.h"
#include "sim/scene/input_error.h"
#include "sim/step/model.h"
#include "sim/step/statics.h"
#include "tests/rod_test_scenes.h"

namespace vascsim {
namespace {

struct Sag {
  double mid_span;      // m, deflection of the middle node across the beam
  double roller_along;  // m, displacement of the roller along the beam (negative: inwards)
  double roller_across; // m, displacement of the roller across the beam (held: 0)
};

// A beam along `direction` (0: +x, pi/2: +y), gravity across it; the roller holds the coordinate
// across the beam.
Sag simply_supported(double direction, int nodes, double g) {
  Scene scene = test::cantilever(nodes);
  scene.boundary.clamp = ClampKind::kNone;
  scene.shape.direction = direction;
  scene.boundary.pinned = {0};
  const bool along_x = direction == 0.0;
  scene.boundary.supports = {{-1, along_x ? SupportAxis::kY : SupportAxis::kX}};
  scene.loads.gravity.enabled = true;
  scene.loads.gravity.acceleration = along_x ? Vec2(0.0, -g) : Vec2(-g, 0.0);
  const Eigen::VectorXd x0 = initial_state(*compile(scene)).x;
  const State state = test::static_equilibrium(scene);
  const int mid = nodes / 2, tip = nodes - 1;
  const int across = along_x ? 1 : 0, along = 1 - across;
  return {state.x[2 * mid + across] - x0[2 * mid + across], state.x[2 * tip + along] - x0[2 * tip + along],
          state.x[2 * tip + across] - x0[2 * tip + across]};
}

TEST(Supports, RollerAndPinCarryABeamThatSagsAsEulerBernoulliSays) {
  const RodSpec rod;
  const double area = M_PI * (rod.outer_radius * rod.outer_radius - rod.inner_radius * rod.inner_radius);
  const double ei = test::bending_stiffness(rod), l = rod.length;
  const double g = 0.002;  // m/s^2: a small load, linear regime (sag 0.17 % of the span)
  const double exact = 5 * rod.density * area * g * std::pow(l, 4) / (384 * ei);
  for (const double direction : {0.0, M_PI / 2}) {  // a roller (holds y), then a slider (holds x)
    const Sag coarse = simply_supported(direction, 41, g), fine = simply_supported(direction, 81, g);
    EXPECT_NEAR(-fine.mid_span, exact, 5e-3 * exact) << "direction " << direction;
    EXPECT_LT(std::abs(-fine.mid_span - exact), std::abs(-coarse.mid_span - exact) + 1e-3 * exact) << "converges";
    EXPECT_EQ(fine.roller_across, 0.0) << "the held coordinate does not move";
    // An inextensible beam's chord shortens by (1/2) integral (y')^2 dx, 2.487 (sag / L)^2 L for this
    // shape (the quartic deflection curve, (1/2) (3.2)^2 (16/7 - 8 + 36/5 + 2 - 4 + 1)): the roller slides inwards by that.
    EXPECT_LT(fine.roller_along, 0.0);
    EXPECT_NEAR(-fine.roller_along, 2.487 * exact * exact / l, 0.1 * 2.487 * exact * exact / l);
  }
}

TEST(Supports, ReadWriteAndErrors) {
  const Scene s = read_scene_text(R"({"maze": null, "boundary": {"supports": [{"node": -1, "hold": "x"}]}})", "s.json");
  ASSERT_EQ(s.boundary.supports.size(), 1u);
  EXPECT_EQ(s.boundary.supports[0].axis, SupportAxis::kX);
  EXPECT_EQ(read_scene_text(scene_to_json(s), "s.json").boundary.supports[0].axis, SupportAxis::kX);
  try {
    read_scene_text(R"({"maze": null, "boundary": {"supports": [{"node": 2, "hold": "z"}]}})", "s.json");
    ADD_FAILURE() << "hold z accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/boundary/supports/0/hold"), std::string::npos) << e.what();
  }
  Scene twice = s;
  twice.boundary.pinned = {-1};
  EXPECT_THROW(compile(twice), InputError) << "a node pinned and supported";
}

// A run's log says how its rod is held, node indices counted from the root, so pictures can draw
// the clamp and supports (render/frame_painter.cpp); a log of a rod held by nothing says nothing.
TEST(Supports, TheLogSaysHowTheRodIsHeld) {
  Scene scene = test::cantilever(12);
  scene.solver.mode = SolveMode::kDynamic;
  scene.boundary.clamp = ClampKind::kFirstEdge;
  scene.boundary.pinned = {5};
  scene.boundary.supports = {{-1, SupportAxis::kX}, {-3, SupportAxis::kY}};
  scene.boundary.prescribed = {{-4, Vec2(0.01, 0.0), Vec2::Zero(), 0.0}};
  const std::string text = run_log_header(vascsim::Run(compile(scene))).metadata;
  const BoundarySpec holds = read_log_metadata(text, "frames.vlog").boundary;
  EXPECT_EQ(holds.clamp, ClampKind::kFirstEdge);
  EXPECT_EQ(holds.pinned, std::vector<int>{5});
  ASSERT_EQ(holds.supports.size(), 2u);
  EXPECT_EQ(holds.supports[0].node, 11);
  EXPECT_EQ(holds.supports[0].axis, SupportAxis::kX);
  EXPECT_EQ(holds.supports[1].node, 9);
  EXPECT_EQ(holds.supports[1].axis, SupportAxis::kY);
  ASSERT_EQ(holds.prescribed.size(), 1u);
  EXPECT_EQ(holds.prescribed[0].node, 8);
  EXPECT_EQ(holds.prescribed[0].velocity, Vec2(0.01, 0.0));

  scene.boundary = BoundarySpec{};
  scene.boundary.pinned = {0};
  scene.loads.gravity.enabled = true;
  const BoundarySpec pinned = read_log_metadata(run_log_header(vascsim::Run(compile(scene))).metadata, "frames.vlog").boundary;
  EXPECT_EQ(pinned.clamp, ClampKind::kNone);
  EXPECT_EQ(pinned.pinned, std::vector<int>{0});

  scene.boundary = BoundarySpec{};
  const std::string free_rod = run_log_header(vascsim::Run(compile(scene))).metadata;
  EXPECT_TRUE(read_log_metadata(free_rod, "frames.vlog").boundary.empty());
  EXPECT_FALSE(nlohmann::json::parse(free_rod).contains("boundary")) << "a rod held by nothing adds a key to its log";

  // A newer writer may add keys (a 3D rod's supports, say): an older reader draws what it knows
  // rather than refusing the log, while a scene with the same key is refused as a typo.
  const char* newer = R"({"rod": {"outer_radius": 0.001, "length": 0.2, "inner_radius": 0.0005},
      "boundary": {"clamp": "first_edge", "twist": "locked", "supports": [{"node": 3, "hold": "x", "hold_z": true}],
                   "prescribed": [{"node": 4, "velocity": [0.01, 0], "angular_velocity": 2}]}})";
  const LogMetadata read_newer = read_log_metadata(newer, "frames.vlog");
  EXPECT_EQ(read_newer.rod_outer_radius, 0.001);
  EXPECT_EQ(read_newer.boundary.clamp, ClampKind::kFirstEdge);
  ASSERT_EQ(read_newer.boundary.supports.size(), 1u);
  EXPECT_EQ(read_newer.boundary.supports[0].axis, SupportAxis::kX);
  ASSERT_EQ(read_newer.boundary.prescribed.size(), 1u);
  EXPECT_EQ(read_newer.boundary.prescribed[0].velocity, Vec2(0.01, 0.0));
  try {
    read_scene_text(R"({"format": "vascsim-scene/1", "boundary": {"clamp": "first_edge", "twist": "locked"}})",
                    "scene.json");
    ADD_FAILURE() << "a scene's unknown boundary key was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/boundary/twist: unknown key"), std::string::npos) << e.what();
  }

  // A log's boundary is checked as it is read, naming the field.
  for (const char* bad : {R"({"boundary": {"pinned": ["a"]}})", R"({"boundary": {"supports": [{"node": 2, "hold": "z"}]}})",
                          R"({"boundary": {"clamp": "glued"}})"}) {
    try {
      read_log_metadata(bad, "run/frames.vlog");
      ADD_FAILURE() << "read " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("run/frames.vlog (metadata): /boundary/"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace vascsim

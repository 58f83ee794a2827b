// Dense output (sim/step/dense_output.h) and the frames an error-controlled run writes from it:
//   - the cubic Hermite interpolant against motions the code did not produce: exact for a cubic
//     in time, and for x = sin(w t) its error shrinks as h^4 in position and h^3 in velocity (the
//     interpolation error of a cubic Hermite, e.g. Burden & Faires, Numerical Analysis, 3.4);
//   - a run's steps no longer depend on its frame rate: the same scene at two output intervals
//     takes the same steps, ends in the same state, and writes the same frames at common times;
//   - a body bouncing off a wall inside a step: where the interpolant would reach into the wall,
//     the step lands on the frame instead, and no frame has a closed gap.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <vector>

#include "sim/contact/contact_pairs.h"
#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/run/navigation.h"
#include "sim/run/run.h"
#include "sim/step/dense_output.h"
#include "tests/rod_test_scenes.h"

namespace vascsim {
namespace {

// A one-degree-of-freedom State of position x and velocity v at time t.
State point(double t, double x, double v) {
  State s;
  s.t = t;
  s.x = Eigen::VectorXd::Constant(1, x);
  s.v = Eigen::VectorXd::Constant(1, v);
  return s;
}

TEST(DenseOutput, ExactForCubicMotion) {
  // x(t) = 0.3 - 2 t + 5 t^2 - 7 t^3 (m), over a step from 0.1 s to 0.35 s.
  const auto x = [](double t) { return 0.3 - 2 * t + 5 * t * t - 7 * t * t * t; };
  const auto v = [](double t) { return -2 + 10 * t - 21 * t * t; };
  const State a = point(0.1, x(0.1), v(0.1)), b = point(0.35, x(0.35), v(0.35));
  for (const double t : {0.1, 0.13, 0.2, 0.31, 0.35}) {
    const State s = interpolate_in_step(a, b, t);
    EXPECT_EQ(s.t, t);
    EXPECT_NEAR(s.x[0], x(t), 1e-14) << "t = " << t;
    EXPECT_NEAR(s.v[0], v(t), 1e-13) << "t = " << t;
  }
}

TEST(DenseOutput, ErrorShrinksAsHToTheFourthInPositionAndCubedInVelocity) {
  const double w = 3.0;  // rad/s
  std::vector<double> hs = {0.2, 0.1, 0.05}, position_errors, velocity_errors;
  for (const double h : hs) {
    double ex = 0.0, ev = 0.0;
    for (int k = 0; k < 20; ++k) {  // steps along a period, frames at 0.3 and 0.7 of each
      const double t0 = 0.1 * k;
      const State a = point(t0, std::sin(w * t0), w * std::cos(w * t0));
      const State b = point(t0 + h, std::sin(w * (t0 + h)), w * std::cos(w * (t0 + h)));
      for (const double f : {0.3, 0.7}) {
        const double t = t0 + f * h;
        const State s = interpolate_in_step(a, b, t);
        ex = std::max(ex, std::abs(s.x[0] - std::sin(w * t)));
        ev = std::max(ev, std::abs(s.v[0] - w * std::cos(w * t)));
      }
    }
    position_errors.push_back(ex);
    velocity_errors.push_back(ev);
  }
  for (std::size_t i = 1; i < hs.size(); ++i) {
    const double px = std::log2(position_errors[i - 1] / position_errors[i]);
    const double pv = std::log2(velocity_errors[i - 1] / velocity_errors[i]);
    EXPECT_NEAR(px, 4.0, 0.3) << "h " << hs[i];
    EXPECT_NEAR(pv, 3.0, 0.3) << "h " << hs[i];
  }
}

// Every frame a run writes, by time (s): all its values.
struct FramesByTime : FrameSink {
  std::map<double, std::vector<double>> frames;
  void write(double t, const std::vector<double>& values) override { frames[t] = values; }
};

// The axial oscillator under error control, pulled from rest, with frames every `interval`.
RunStatistics run_oscillator(double interval, FramesByTime& sink, State& end) {
  Scene scene = test::axial_oscillator(Scheme::kBdf2, 1e-13);
  scene.solver.adaptive = StepControl::kError;
  scene.solver.rtol = 1e-3;
  scene.solver.atol_position = 0.0;
  scene.solver.atol_velocity = 1.0;
  scene.solver.dt = 1e-4;
  scene.run.duration = 2.0;
  scene.run.output_interval = interval;
  PointLoadSpec pull;
  pull.node = 2;
  pull.force = Vec2(0.1, 0.0);  // N: about 4 mm of swing
  scene.loads.point_loads.push_back(pull);
  Run run(compile(scene));
  EXPECT_TRUE(run.run(sink)) << run.statistics().failure;
  end = run.state();
  return run.statistics();
}

TEST(DenseOutput, StepsDoNotDependOnTheFrameRate) {
  FramesByTime coarse, fine;
  State coarse_end, fine_end;
  const RunStatistics a = run_oscillator(0.1, coarse, coarse_end);
  const RunStatistics b = run_oscillator(0.002, fine, fine_end);
  ASSERT_EQ(coarse.frames.size(), 21u);
  ASSERT_EQ(fine.frames.size(), 1001u);
  // Longer steps than frames: most fine frames lie inside a step.
  ASSERT_GT(b.dt_max, 5 * 0.002);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.newton_iterations, b.newton_iterations);
  EXPECT_EQ(coarse_end.x, fine_end.x);
  EXPECT_EQ(coarse_end.v, fine_end.v);
  // The coarse run's frames are among the fine run's: the same interpolants at the same times.
  int shared = 0;
  for (const auto& [t, values] : coarse.frames) {
    const auto it = fine.frames.lower_bound(t - 1e-9);
    ASSERT_TRUE(it != fine.frames.end() && std::abs(it->first - t) < 1e-9) << "no fine frame at t = " << t;
    ASSERT_EQ(values.size(), it->second.size());
    for (std::size_t k = 0; k < values.size(); ++k) EXPECT_NEAR(values[k], it->second[k], 1e-12 * (1 + std::abs(values[k]))) << "t " << t;
    ++shared;
  }
  EXPECT_EQ(shared, 21);
}

// maze_default at the fast preset, its undamped body bouncing off the walls, with a frame every
// 2 ms: a few of its steps hold a bounce whose interpolant reaches into a wall, and those steps
// land on the frame instead, so that no frame has a closed gap. (Checked to fail: with every
// interpolated frame accepted, frames inside the walls appear.) The frames' contact forces are
// interpolated between solved states, so none exceeds the largest the steps met (evaluated at
// the interpolated positions, the barrier's steepness made spikes: 37 mN here against 19 mN).
TEST(DenseOutput, AFrameThatInterpolationWouldPutIntoAWallLandsAStepInstead) {
  Scene input = read_scene_file(std::string(VASCSIM_SOURCE_DIR) + "/scenes/maze_default.json");
  apply_solver_preset("fast", input.solver);
  input.run.output_interval = 2e-3;
  const std::shared_ptr<const Model> model = compile(input);
  vascsim::Run run(model);
  struct Gaps : FrameSink {
    const ContactGeometry* geometry = nullptr;
    int nodes = 0;
    std::size_t contact_offset = 0;  // where force/contact starts in a frame's values
    double min_gap = 1.0;            // m
    double contact_force_max = 0.0;  // N, largest per-node wall force in any frame
    std::size_t frames = 0;
    void write(double, const std::vector<double>& values) override {
      const Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(values.data(), 2 * nodes);
      min_gap = std::min(min_gap, geometry->min_gap(x, 1e-3));
      for (int i = 0; i < nodes; ++i)
        contact_force_max = std::max(contact_force_max, std::hypot(values[contact_offset + 2 * i], values[contact_offset + 2 * i + 1]));
      ++frames;
    }
  } gaps;
  gaps.geometry = model->navigation->contact_geometry.get();
  gaps.nodes = model->nodes();
  for (const LogChannel& c : run.channels()) {
    if (c.name == "force/contact") break;
    gaps.contact_offset += c.count;
  }
  ASSERT_LT(gaps.contact_offset, 100u * gaps.nodes) << "no force/contact channel";
  ASSERT_TRUE(run.run(gaps)) << run.statistics().failure;
  const RunStatistics& s = run.statistics();
  EXPECT_EQ(gaps.frames, static_cast<std::size_t>(std::lround(input.run.duration / 2e-3)) + 1);
  EXPECT_GT(s.dt_max, 5 * 2e-3) << "the steps were no longer than the frames";
  EXPECT_GT(s.steps_cut_to_frames, 0) << "no interpolated frame was refused: the test no longer covers it";
  EXPECT_GT(gaps.min_gap, 0.0) << "a frame has the rod inside a wall";
  EXPECT_GT(gaps.contact_force_max, 0.0);
  EXPECT_LE(gaps.contact_force_max, s.contact_force_max * (1 + 1e-12)) << "a frame's contact force exceeds every solved state's";
}

}  // namespace
}  // namespace vascsim

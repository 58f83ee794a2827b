// Error control's Newton stop (SolverSpec::newton_stop_share, sim/step/newton.cpp): Newton ends
// when its next correction is within a share of the step's error tolerance, and applies it. On
// the damped traversal (scenes/maze_body_drag.json, where the body's positions converge) it must
// save Newton iterations without moving the body further from a reference run with a 100x
// tighter tolerance than the residual test alone leaves it. Stopping without applying the last
// correction fails the second check: its error has the same sign at every step and adds up
// (about 3x the body deviation at the fast preset, docs/solver.md "Newton's stop").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/run/run.h"

namespace vascsim {
namespace {

constexpr double kDuration = 32.0;  // s: two thirds of the traversal, with most of its wall contacts

class PositionSink : public FrameSink {
 public:
  explicit PositionSink(std::size_t dofs) : dofs_(dofs) {}
  void write(double, const std::vector<double>& values) override {
    frames.emplace_back(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(dofs_));
  }
  std::vector<std::vector<double>> frames;

 private:
  std::size_t dofs_;
};

struct Outcome {
  std::vector<std::vector<double>> frames;
  long long newton_iterations = 0;
};

Outcome traverse(const SolverSpec& solver) {
  Scene scene = read_scene_file(std::string(VASCSIM_SOURCE_DIR) + "/scenes/maze_body_drag.json");
  scene.solver = solver;
  scene.run.duration = kDuration;
  Run run(compile(scene));
  PositionSink sink(static_cast<std::size_t>(2 * scene.rod.nodes));
  EXPECT_TRUE(run.run(sink)) << run.statistics().failure;
  return {sink.frames, run.statistics().newton_iterations};
}

// m, the largest distance of any node from its place in the reference, over every frame.
double body_deviation(const Outcome& run, const Outcome& reference) {
  EXPECT_EQ(run.frames.size(), reference.frames.size());
  double worst = 0.0;
  for (std::size_t f = 0; f < std::min(run.frames.size(), reference.frames.size()); ++f)
    for (std::size_t d = 0; d + 1 < run.frames[f].size(); d += 2)
      worst = std::max(worst, std::hypot(run.frames[f][d] - reference.frames[f][d],
                                         run.frames[f][d + 1] - reference.frames[f][d + 1]));
  return worst;
}

SolverSpec preset(const char* name, double share) {
  SolverSpec s;
  apply_solver_preset(name, s);
  s.newton_stop_share = share;
  return s;
}

TEST(NewtonStop, SavesIterationsWithoutMovingTheBodyFromTheReference) {
  // The reference of `vascsim bench accuracy` (rtol 1.5e-6, floor 1.25e-4 s), residual test alone.
  SolverSpec tight = preset("balanced", 0.0);
  tight.rtol = 1.5e-6;
  tight.atol_velocity = 1e-5;
  tight.dt = tight.dt_floor = 1.25e-4;
  tight.dt_mean_min = 0.0;
  const Outcome reference = traverse(tight);
  for (const char* name : {"fast", "balanced"}) {
    const Outcome residual_only = traverse(preset(name, 0.0));
    const Outcome with_stop = traverse(preset(name, 0.3));
    const double before = body_deviation(residual_only, reference), after = body_deviation(with_stop, reference);
    EXPECT_LT(with_stop.newton_iterations, 0.9 * residual_only.newton_iterations)
        << name << ": " << with_stop.newton_iterations << " against " << residual_only.newton_iterations;
    EXPECT_LE(after, 1.1 * before + 1e-6) << name << ": body deviation " << after << " m against " << before << " m";
    EXPECT_GT(before, 0.0) << name;
  }
}

}  // namespace
}  // namespace vascsim

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
#include "sim/step/newton.h"
#include "sim/step/stepper.h"
#include "tests/rod_test_scenes.h"

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

// A stiffening spring on the last node, F = -(k + c |d|^2) d with d = p - anchor, and its exact
// Jacobian: nonlinear, so one Newton iteration does not reach the residual tolerance and the
// correction stop is asked. Its max_step_fraction stands in for a wall barrier near a node: it
// cuts every update to `cap` of itself.
class StiffeningSpring : public ForceModule {
 public:
  explicit StiffeningSpring(double cap) : cap_(cap) {}
  std::string channel() const override { return "force/test_spring"; }
  void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const override {
    const int dof = static_cast<int>(ctx.x->size()) - 2;
    const Eigen::Vector2d d = ctx.x->segment<2>(dof) - Eigen::Vector2d(1.05, 0.02);
    const double k = 100.0, c = 4e4;  // N/m, N/m^3: the cubic term as strong as the linear one at 5 cm
    force.segment<2>(dof) -= (k + c * d.squaredNorm()) * d;
    if (stiffness)
      stiffness->add_block<2>(dof, Eigen::Matrix2d((k + c * d.squaredNorm()) * Eigen::Matrix2d::Identity() +
                                                   2.0 * c * d * d.transpose()));
  }
  double max_step_fraction(const ForceContext&, const Eigen::VectorXd& dx) const override {
    return dx.lpNorm<Eigen::Infinity>() > 0.0 ? cap_ : 1.0;
  }

 private:
  double cap_;
};

// One backward Euler step of 10 ms from rest, solved with the correction stop at a tolerance
// (1 m) that any correction meets.
NewtonOutcome solve_step_with_spring(double cap) {
  Model model = build_model(test::axial_oscillator(Scheme::kBackwardEuler, 1e-8));
  model.forces.push_back(std::make_shared<StiffeningSpring>(cap));
  const State start = initial_state(model);
  Workspace ws(model);
  const Controls controls;
  const double h = 0.01;
  set_targets(model, controls, h, ws);
  ws.x_hat = start.x;
  ws.v_hat = start.v;
  ws.x = start.x;
  NewtonProblem p;
  p.t = h;
  p.c = 1.0 / h;
  p.controls = &controls;
  p.start = &start;
  p.correction_tol = 1.0;
  NewtonOutcome out = newton_solve(model, p, ws);
  EXPECT_TRUE(out.converged) << out.failure;
  return out;
}

TEST(NewtonStop, RefusedWhenAModuleWouldCutTheCorrection) {
  // Applying a correction a barrier would cut could close a gap: Newton must go on instead, to
  // the residual test (sim/step/newton.cpp, correction_converges).
  const NewtonOutcome free = solve_step_with_spring(1.0);
  EXPECT_TRUE(free.correction_stop);
  EXPECT_EQ(free.iterations, 1);
  const NewtonOutcome cut = solve_step_with_spring(0.99);
  EXPECT_FALSE(cut.correction_stop);
  EXPECT_GT(cut.iterations, 1);
  EXPECT_FALSE(cut.round_off_stop);
  EXPECT_LE(cut.residual, 1e-8 * cut.scale);  // by the residual test
}

}  // namespace
}  // namespace vascsim

// Error-controlled time stepping (sim/step/local_error.h, sim/step/step_size_controller.h, the run
// loop in sim/run/run.cpp) against an exact solution the code did not produce: the axial
// oscillator of tests/rod_dynamics_test.cpp (node 2 on a clamped first edge is a linear spring,
// k/m = (2 pi)^2; docs/references.md section 5), x(t) = x0 + A cos(2 pi t).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "sim/run/compile.h"
#include "sim/run/run.h"
#include "sim/step/local_error.h"
#include "sim/step/step_budget.h"
#include "sim/step/stepper.h"
#include "tests/rod_test_scenes.h"

namespace vascsim {
namespace {

constexpr double kOmega = 2 * M_PI;  // rad/s
constexpr double kAmplitude = 0.01;  // m

Scene oscillator(Scheme scheme) { return test::axial_oscillator(scheme, 1e-13); }

// The exact state at t: node 2 at x = 1 + A cos(w t) (at rest length 1 m from the root).
State exact_state(const Model& model, double t) {
  State s = initial_state(model);
  s.t = t;
  s.x[4] = 1.0 + kAmplitude * std::cos(kOmega * t);
  s.v[4] = -kAmplitude * kOmega * std::sin(kOmega * t);
  return s;
}

// A step of h from the exact solution and its exact history (steps of h): the estimate and the
// true local error of node 2's position and velocity.
struct OneStep {
  double estimate_x, true_x, estimate_v, true_v;
};

OneStep one_step(Scheme scheme, double h) {
  const Model model = *compile(oscillator(scheme));
  const double t0 = 0.3;  // x''' and v''' are both far from zero here
  State before = exact_state(model, t0);
  const State back1 = exact_state(model, t0 - h), back2 = exact_state(model, t0 - 2 * h);
  before.x_prev = back1.x, before.v_prev = back1.v, before.h_prev = h;
  before.x_prev2 = back2.x, before.v_prev2 = back2.v, before.h_prev2 = h;
  State after = before;
  Workspace ws(model);
  const StepReport r = step_once(model, after, ws, Controls{}, h);
  EXPECT_TRUE(r.ok) << r.failure;
  const int order = step_order(scheme, before, h);
  EXPECT_EQ(order, scheme == Scheme::kBdf2 ? 2 : 1);
  const State exact = exact_state(model, t0 + h);
  // Unit weights: local_error returns the errors in SI.
  const LocalError estimate = local_error(before, after, order, ws.fixed, {0.0, 1.0, 1.0, 1.0});
  const double estimate_x = estimate.position, estimate_v = estimate.velocity;
  return {estimate_x, std::abs(after.x[4] - exact.x[4]), estimate_v, std::abs(after.v[4] - exact.v[4])};
}

// The estimate must shrink as h^(p+1) (local error of an order-p scheme) and match the true
// local error, positions and velocities.
void expect_estimate_order(Scheme scheme, double local_order) {
  std::vector<OneStep> steps;
  for (const double h : {4e-3, 2e-3, 1e-3}) steps.push_back(one_step(scheme, h));
  for (std::size_t k = 0; k + 1 < steps.size(); ++k) {
    EXPECT_NEAR(std::log2(steps[k].estimate_x / steps[k + 1].estimate_x), local_order, 0.15) << "halving " << k;
    EXPECT_NEAR(std::log2(steps[k].estimate_v / steps[k + 1].estimate_v), local_order, 0.15) << "halving " << k;
  }
  for (const OneStep& s : steps) {
    EXPECT_NEAR(s.estimate_x / s.true_x, 1.0, 0.2) << "estimate " << s.estimate_x << " true " << s.true_x;
    EXPECT_NEAR(s.estimate_v / s.true_v, 1.0, 0.2) << "estimate " << s.estimate_v << " true " << s.true_v;
  }
}

TEST(LocalError, Bdf2EstimateShrinksAsHCubedAndMatchesTheTrueError) { expect_estimate_order(Scheme::kBdf2, 3.0); }
TEST(LocalError, BackwardEulerEstimateShrinksAsHSquaredAndMatchesTheTrueError) {
  expect_estimate_order(Scheme::kBackwardEuler, 2.0);
}

TEST(LocalError, NoEstimateWithoutHistoryAndPrescribedDegreesOfFreedomAreNotCounted) {
  const Model model = *compile(oscillator(Scheme::kBdf2));
  State before = exact_state(model, 0.3), after = exact_state(model, 0.301);
  Workspace ws(model);
  std::vector<char> none(ws.fixed.size(), 0);
  EXPECT_FALSE(local_error(before, after, 1, none, {0.0, 1.0, 1.0, 1.0}).estimated()) << "backward Euler needs one past step";
  before.x_prev = exact_state(model, 0.299).x, before.v_prev = exact_state(model, 0.299).v, before.h_prev = 1e-3;
  EXPECT_FALSE(local_error(before, after, 2, none, {0.0, 1.0, 1.0, 1.0}).estimated()) << "BDF2 needs two";
  after.x[4] += 1.0;  // a jump of 1 m: only a prescribed degree of freedom could do that
  EXPECT_GT(local_error(before, after, 1, none, {0.0, 1.0, 1.0, 1.0}).position, 0.1);
  std::vector<char> prescribed = none;
  prescribed[4] = 1;
  EXPECT_LT(local_error(before, after, 1, prescribed, {0.0, 1.0, 1.0, 1.0}).position, 1e-3);
}

// A constant axial pull F on node 2 from rest: x(t) = x_static (1 - cos w t), x_static = F / k.
struct ControlledRun {
  double error = 0.0;                // m, largest |x - exact| over the frames
  std::vector<double> frame_errors;  // m, |x - exact| at each frame
  RunStatistics stats;
};

ControlledRun pulled_oscillator(Scheme scheme, double rtol, double dt_floor = 0.0, double dt_mean_min = 0.0,
                                double mean_burst = 0.0) {
  Scene scene = oscillator(scheme);
  scene.solver.dt_floor = dt_floor;
  scene.solver.dt_mean_min = dt_mean_min;
  scene.solver.mean_burst = mean_burst;
  scene.solver.adaptive = StepControl::kError;
  scene.solver.rtol = rtol;
  scene.solver.atol_position = 0.0;
  // Positions only: their error is controlled per unit step, which is what makes the global
  // error proportional to the tolerance (velocities are controlled per step, docs/solver.md).
  scene.solver.atol_velocity = 1.0;
  scene.solver.dt = 1e-4;
  scene.run.duration = 3.0;
  scene.run.output_interval = 0.05;
  PointLoadSpec pull;
  pull.node = 2;
  const double l0 = 0.5, area = M_PI * (std::pow(scene.rod.outer_radius, 2) - std::pow(scene.rod.inner_radius, 2));
  const double k = scene.rod.youngs_modulus * area / l0;  // N/m
  pull.force = Vec2(k * kAmplitude, 0.0);
  scene.loads.point_loads.push_back(pull);
  Run run(compile(scene));
  struct Sink : FrameSink {
    std::vector<double> errors;
    void write(double t, const std::vector<double>& values) override {
      errors.push_back(std::abs(values[4] - (1.0 + kAmplitude * (1.0 - std::cos(kOmega * t)))));
    }
  } sink;
  EXPECT_TRUE(run.run(sink)) << run.statistics().failure;
  return {*std::max_element(sink.errors.begin(), sink.errors.end()), sink.errors, run.statistics()};
}

// Over a sweep of tolerances the global error stays within a small factor of what the tolerance
// promises (error per unit step: a run of T seconds keeps its error near T * rtol * length) and
// falls nearly in proportion to it: slope d log(error) / d log(rtol) measured 0.83 here, where
// error-per-step control gives 2/3 (0.59 measured with it). Tighter tolerances take more steps.
TEST(ErrorControl, OscillatorErrorFollowsTheTolerance) {
  const double duration = 3.0;  // s, pulled_oscillator's run
  const std::vector<double> tolerances = {1e-4, 1e-5, 1e-6};
  std::vector<double> errors;
  int previous_steps = 0;
  for (const double rtol : tolerances) {
    const ControlledRun r = pulled_oscillator(Scheme::kBdf2, rtol);
    const double ratio = r.error / (duration * rtol * 1.0);  // tolerance: rtol times the 1 m rod
    std::printf("rtol %g: error %.3g m (%.3g of T rtol L), %d steps (%d rejected), dt %.3g .. %.3g s\n", rtol, r.error,
                ratio, r.stats.steps, r.stats.error_rejected_steps, r.stats.dt_min, r.stats.dt_max);
    EXPECT_LT(ratio, 5.0) << "rtol " << rtol;
    EXPECT_GT(ratio, 0.1) << "rtol " << rtol << ": far more accurate than asked is wasted work";
    EXPECT_GT(r.stats.steps, previous_steps) << "rtol " << rtol;
    errors.push_back(r.error);
    previous_steps = r.stats.steps;
  }
  const double slope = std::log(errors.front() / errors.back()) / std::log(tolerances.front() / tolerances.back());
  EXPECT_GT(slope, 0.75) << "the error does not follow the tolerance";
  EXPECT_LT(slope, 1.1);
}

// The steps grow from a tiny first step and the frames stay on the output grid (frames inside
// a step come from its interpolant, sim/step/dense_output.h).
TEST(ErrorControl, StepsGrowFromATinyFirstStepAndFramesLandOnOutputTimes) {
  const ControlledRun r = pulled_oscillator(Scheme::kBdf2, 1e-4);
  EXPECT_GT(r.stats.dt_max, 50 * 1e-4) << "the first step was 1e-4 s";
  EXPECT_EQ(r.stats.frames, 61u);
}

// A floor (solver.dt_floor, the presets' bound on cost) keeps every chosen step at or above it
// and the steps it had to keep over the tolerance are counted; without it the same tolerance
// takes shorter steps.
TEST(ErrorControl, AFloorBoundsTheStepAndCountsWhatItKeepsOverTheTolerance) {
  const double floor = 0.01;  // s
  const ControlledRun free = pulled_oscillator(Scheme::kBdf2, 1e-6);
  const ControlledRun floored = pulled_oscillator(Scheme::kBdf2, 1e-6, floor);
  ASSERT_LT(free.stats.dt_max, floor) << "the tolerance must need steps below the floor";
  EXPECT_GE(floored.stats.dt_max, floor);
  EXPECT_LT(floored.stats.steps, free.stats.steps / 2);
  EXPECT_GT(floored.stats.warnings.step_over_tolerance.count, floored.stats.steps / 2);
  EXPECT_EQ(free.stats.warnings.step_over_tolerance.count, 0);
  EXPECT_LE(floored.stats.error_max, 1.0) << "error_max reports the steps within the tolerance";
  EXPECT_GT(floored.stats.error_max_at_floor, 1.0) << "and error_max_at_floor those kept over it";
  EXPECT_EQ(free.stats.error_max_at_floor, 0.0);
  // The error grows with the step, as a fixed step of the floor's size would give.
  EXPECT_GT(floored.error, 10 * free.error);
}

// A step whose Newton fails is retried with half the step, but under error control never below
// solver.dt_min (the retries took steps of 2.5e-4 s with dt_min 1e-3 s, then failed "at the
// smallest step"): a cantilever under a tip load far past what a step of dt_min resolves.
TEST(ErrorControl, NewtonRetriesDoNotGoBelowTheSmallestStep) {
  Scene scene = test::cantilever(21);
  scene.solver.mode = SolveMode::kDynamic;
  scene.solver.adaptive = StepControl::kError;
  scene.solver.dt = 4e-3;
  scene.solver.dt_min = 1e-3;
  scene.solver.dt_floor = 0.0;
  scene.run.duration = 0.5;
  scene.run.output_interval = 0.05;
  PointLoadSpec load;
  load.node = -1;
  load.force = Vec2(0.0, -1e4);
  scene.loads.point_loads.push_back(load);
  vascsim::Run run(compile(scene));
  struct : FrameSink {
    void write(double, const std::vector<double>&) override {}
  } sink;
  ASSERT_FALSE(run.run(sink)) << "the load is far past what any step resolves";
  const RunStatistics& stats = run.statistics();
  if (stats.steps > 0) {
    EXPECT_GE(stats.dt_min, 1e-3 * (1 - 1e-12));
  }
  EXPECT_NE(stats.failure.find("another would be shorter than solver.dt_min = 0.001 s"), std::string::npos) << stats.failure;
}

// A floor on the mean step (solver.dt_mean_min, the presets' bound on what rattling costs) lets
// the steps go as short as the tolerance asks while the run has credit, then holds them at the
// mean floor: the frames before the credit runs out are those of the run without a floor, and
// the run takes no more than T / dt_mean_min + mean_burst steps, plus one for the run's end.
TEST(ErrorControl, AMeanFloorFollowsTheToleranceWhileItHasCreditAndBoundsTheStepCount) {
  const double mean_floor = 0.01, duration = 3.0;  // s, the oscillator's run
  const ControlledRun free = pulled_oscillator(Scheme::kBdf2, 1e-6);
  ASSERT_GT(free.stats.steps, 4 * duration / mean_floor) << "the tolerance must need steps well below the mean floor";
  const double burst = free.stats.steps / 4.0;
  const ControlledRun bounded = pulled_oscillator(Scheme::kBdf2, 1e-6, 0.0, mean_floor, burst);
  EXPECT_LE(bounded.stats.steps, duration / mean_floor + burst + 1.0);
  EXPECT_LT(bounded.stats.steps, free.stats.steps / 2);
  EXPECT_GT(bounded.stats.warnings.step_over_tolerance.count, 0) << "the mean floor never held";
  EXPECT_LT(bounded.stats.dt_min, mean_floor) << "no step went below the mean floor on credit";
  ASSERT_EQ(bounded.frame_errors.size(), free.frame_errors.size());
  std::size_t same = 0;
  while (same < free.frame_errors.size() && bounded.frame_errors[same] == free.frame_errors[same]) ++same;
  // The credit, a quarter of the free run's steps, lasts about a quarter of the run.
  EXPECT_GT(same, free.frame_errors.size() / 8) << "the run left the tolerance before its credit was spent";
  EXPECT_LT(same, free.frame_errors.size()) << "the credit never ran out";
  // A hard floor at the same step gives up the tolerance from the start.
  const ControlledRun hard = pulled_oscillator(Scheme::kBdf2, 1e-6, mean_floor);
  EXPECT_GT(hard.frame_errors[free.frame_errors.size() / 8], 10 * free.frame_errors[free.frame_errors.size() / 8]);
}

// The credit's arithmetic (sim/step/step_budget.h): steps shorter than the mean floor spend it,
// longer ones earn it back up to the burst, and the hard floor holds whatever the credit.
TEST(StepBudget, CreditIsSpentBelowTheMeanFloorAndEarnedAboveIt) {
  StepBudget budget(1e-4, 1e-2, 3.0);
  EXPECT_EQ(budget.floor(), 1e-4) << "with credit only the hard floor holds";
  int below = 0;
  while (budget.floor() < 1e-2 && below < 100) {
    budget.spend(1e-4);  // costs 0.99 of a step each
    ++below;
  }
  EXPECT_EQ(below, 3) << "a burst of 3 steps allows 3 short steps";
  budget.spend(1e-2);
  EXPECT_EQ(budget.floor(), 1e-2) << "a step at the mean floor earns nothing";
  budget.spend(2e-2);  // earns one step
  EXPECT_EQ(budget.floor(), 1e-4);
  for (int k = 0; k < 100; ++k) budget.spend(2e-2);
  for (below = 0; budget.floor() < 1e-2 && below < 100; ++below) budget.spend(1e-4);
  EXPECT_EQ(below, 3) << "credit is capped at the burst";
  EXPECT_EQ(StepBudget(1e-4, 0.0, 0.0).floor(), 1e-4);
  EXPECT_EQ(StepBudget(0.0, 0.0, 0.0).floor(), 0.0);
}

// The dynamic cantilever of `vascsim bench accuracy` (the paper's rod, centred clamp, a tip load
// P = 0.01 EI/L^2 switched on at t = 0, so every mode rings) under error control, against the
// same mesh's time-converged motion (BDF2 at a fixed 2e-5 s): over a sweep of position
// tolerances the tip's error stays within a small factor of T * atol_position and falls with it.
// (Against the modal solution, docs/references.md sections 1-2, the mesh's own error of 21 nodes,
// about 1e-2 of the static deflection, would hide the time error: bench accuracy shows that part.)
struct TipSamples : FrameSink {
  std::vector<double> tip_y;
  void write(double, const std::vector<double>& values) override { tip_y.push_back(values[2 * 21 - 1]); }
};

Scene loaded_cantilever_dynamics() {
  Scene s = test::cantilever(21);
  s.solver.mode = SolveMode::kDynamic;
  s.solver.rel_tol = 1e-12;
  PointLoadSpec tip;
  tip.force = Vec2(0.0, -0.01 * test::bending_stiffness(s.rod) / (s.rod.length * s.rod.length));
  s.loads.point_loads.push_back(tip);
  s.run.duration = 1.0;
  s.run.output_interval = 0.02;
  return s;
}

std::vector<double> cantilever_tip(const Scene& scene, RunStatistics* stats = nullptr) {
  Run run(compile(scene));
  TipSamples sink;
  EXPECT_TRUE(run.run(sink)) << run.statistics().failure;
  if (stats) *stats = run.statistics();
  return sink.tip_y;
}

TEST(ErrorControl, DynamicCantileverErrorFollowsTheTolerance) {
  Scene fixed = loaded_cantilever_dynamics();
  fixed.solver.adaptive = StepControl::kOff;
  fixed.solver.dt = 2e-5;
  const std::vector<double> reference = cantilever_tip(fixed);
  const double deflection = 0.01 * fixed.rod.length / 3;  // m, P L^3 / (3 EI): the tip moves about twice this
  double previous_error = INFINITY;
  for (const double atol : {1e-5, 1e-6, 1e-7}) {
    Scene scene = loaded_cantilever_dynamics();
    scene.solver.adaptive = StepControl::kError;
    scene.solver.rtol = 0.0;
    scene.solver.atol_position = atol;  // m, per second of simulated time
    scene.solver.atol_velocity = 1.0;   // positions only, as in OscillatorErrorFollowsTheTolerance
    scene.solver.dt = 1e-4;
    RunStatistics stats;
    const std::vector<double> tip = cantilever_tip(scene, &stats);
    ASSERT_EQ(tip.size(), reference.size());
    double error = 0.0;
    for (std::size_t k = 0; k < tip.size(); ++k) error = std::max(error, std::abs(tip[k] - reference[k]));
    const double allowed = scene.run.duration * atol;
    std::printf("atol %g m: tip error %.3g m (%.3g of T atol; %.2g of the deflection), %d steps\n", atol, error,
                error / allowed, error / deflection, stats.steps);
    EXPECT_LT(error, 5 * allowed) << "atol " << atol;
    EXPECT_LT(error, previous_error) << "atol " << atol;
    previous_error = error;
  }
}

}  // namespace
}  // namespace vascsim

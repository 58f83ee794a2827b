// Warnings are counted, not lost: conditions that did not stop a run (Newton stopping at
// round-off, steps retried with a smaller dt, the paper contact's iteration cap, an unstable
// static equilibrium, a rod strained past 10 %) reach summary.json with how often and when they first happened, and stay
// at zero where they did not happen.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "tests/rod_test_scenes.h"
#include "tests/run_test_support.h"

namespace vascsim {
namespace {

using test::default_maze;
using test::summary_of;

nlohmann::json warnings_of(const Scene& scene) { return summary_of(scene)["warnings"]; }

void expect_count(const nlohmann::json& w, const char* name, bool happened) {
  ASSERT_TRUE(w.contains(name)) << w.dump();
  if (happened) {
    EXPECT_GT(w[name]["count"].get<int>(), 0) << name << ": " << w.dump();
    EXPECT_TRUE(w[name]["first_time"].is_number()) << name << ": " << w.dump();
  } else {
    EXPECT_EQ(w[name]["count"], 0) << name << ": " << w.dump();
    EXPECT_TRUE(w[name]["first_time"].is_null()) << name;
  }
}

// (The default scene's own Newton does stop at round-off now and then: that count is not zero.)
TEST(RunWarnings, NoneInAnOrdinaryRun) {
  const auto w = warnings_of(default_maze(1.0));
  for (const char* name : {"step_retried", "unresolved_step", "paper_contact_iteration_cap", "unstable_equilibrium", "left_unstable_equilibrium", "load_path_jumped",
                           "stability_undecided", "large_axial_strain"})
    expect_count(w, name, false);
}

TEST(RunWarnings, RoundOffStopsAndRetriesAreCounted) {
  Scene tight = default_maze(0.2);
  tight.solver.rel_tol = 1e-17;  // below what double precision can reach: Newton stops at round-off
  tight.solver.abs_tol = 0.0;
  tight.solver.newton_stop_share = 0.0;  // the residual test alone (error control's stop would end Newton first)
  expect_count(warnings_of(tight), "newton_round_off_stop", true);

  Scene coarse = default_maze(1.0);
  coarse.solver.dt = 0.05;  // too long to converge in one Newton iteration: steps are retried with dt/2
  coarse.solver.max_iterations = 1;
  coarse.solver.rel_tol = 1e-6;
  coarse.solver.newton_stop_share = 0.0;
  const auto s = summary_of(coarse);
  expect_count(s["warnings"], "step_retried", true);
  EXPECT_LE(s["warnings"]["step_retried"]["count"].get<int>(), s["rejected_steps"].get<int>())
      << "a retried step has one or more rejected attempts";
}

TEST(RunWarnings, PaperContactIterationCapIsCounted) {
  Scene paper = default_maze(19.0);  // the first wall contacts come at about 17 s
  paper.contact.mode = ContactMode::kPaper;
  paper.contact.paper_iterations = 1;
  const auto w = warnings_of(paper);
  expect_count(w, "paper_contact_iteration_cap", true);
  EXPECT_GT(w["paper_contact_iteration_cap"]["first_time"].get<double>(), 15.0);
}

// Hooke's law: a rod clamped at one end and pulled along its axis at the other by F is strained
// by F / EA on every free edge (EA = E pi (ro^2 - ri^2)). summary.json gives that strain; past
// 10 % the run warns (a rod pushed or pulled harder than it bears).
TEST(RunWarnings, LargeAxialStrainIsCountedAndItsSizeReported) {
  for (const double strain : {0.05, 0.2}) {
    Scene pulled = test::cantilever(21);
    const RodSpec& r = pulled.rod;
    const double ea = r.youngs_modulus * M_PI * (r.outer_radius * r.outer_radius - r.inner_radius * r.inner_radius);
    PointLoadSpec tip;
    tip.force = Vec2(strain * ea, 0.0);
    pulled.loads.point_loads.push_back(tip);
    const auto summary = summary_of(pulled);
    EXPECT_NEAR(summary["axial_strain_max"].get<double>(), strain, 1e-6) << strain;
    expect_count(summary["warnings"], "large_axial_strain", strain > 0.1);
  }
}

// docs/references.md section 3 (Timoshenko & Gere): a clamped-free column stays straight under an
// axial load past P_cr = pi^2 EI / (4 L^2), but that equilibrium is unstable. Without
// solver.stable_branch the solve returns it and warns; with it (the default) the solve buckles
// the column and says so.
TEST(RunWarnings, UnstableStaticEquilibriumIsCounted) {
  for (const bool stable_branch : {false, true}) {
    for (const double factor : {0.5, 1.5}) {
      Scene column = test::cantilever(21);
      column.solver.stable_branch = stable_branch;
      const double ei = test::bending_stiffness(column.rod), l = column.rod.length;
      PointLoadSpec tip;
      tip.force = Vec2(-factor * M_PI * M_PI * ei / (4 * l * l), 0.0);
      column.loads.point_loads.push_back(tip);
      const auto w = warnings_of(column);
      expect_count(w, "unstable_equilibrium", factor > 1.0 && !stable_branch);
      expect_count(w, "left_unstable_equilibrium", factor > 1.0 && stable_branch);
    }
  }
}

// The static load path that cannot follow its branch (a tip magnet in 10 T, 3 rad from the rod:
// MagnetLoad.WhereTheBranchTurnsTooSharplyTheSolveJumpsAndSaysSo) is reported in summary.json,
// dated by the load factor of the jump; 100 initial increments follow the branch and do not warn.
// And a fixed 5 ms step that ends at a saddle (MagnetLoad.AStepOfTheMotionNeverJumps) is counted.
TEST(RunWarnings, JumpsOfTheLoadPathAndUnresolvedStepsAreCounted) {
  Scene magnet = test::tip_magnet_cantilever(41, 10.0, 3.0);
  magnet.solver = SolverSpec{};
  magnet.solver.mode = SolveMode::kStatic;
  const auto jumped = warnings_of(magnet);
  expect_count(jumped, "load_path_jumped", true);
  EXPECT_GT(jumped["load_path_jumped"]["first_time"].get<double>(), 0.0);
  EXPECT_LT(jumped["load_path_jumped"]["first_time"].get<double>(), 1.0);
  magnet.solver.load_steps = 100;
  expect_count(warnings_of(magnet), "load_path_jumped", false);

  Scene fixed = test::cantilever(41);
  fixed.solver = SolverSpec{};
  apply_solver_preset("fast", fixed.solver);
  fixed.solver.adaptive = StepControl::kOff;
  fixed.solver.dt = 0.005;
  fixed.loads.magnet = magnet.loads.magnet;
  fixed.loads.magnet.field = 1.0;
  fixed.run.duration = 0.01;
  fixed.run.output_interval = 0.005;
  expect_count(warnings_of(fixed), "unresolved_step", true);
}

}  // namespace
}  // namespace vascsim

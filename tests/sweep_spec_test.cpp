// The sweep file and its expansion into runs (sim/io/sweep_spec.h, sim/io/sweep_expand.h): the
// order of a product, zips, ranges, repeats, fixed overrides, and every mistake an error naming
// the sweep file, the JSON pointer and what was expected, before anything runs.
#include <gtest/gtest.h>

#include <string>

#include "sim/io/scene_reader.h"
#include "sim/io/sweep_expand.h"
#include "sim/io/sweep_manifest.h"
#include "sim/io/sweep_spec.h"
#include "sim/scene/input_error.h"
#include "tests/cli_test_support.h"

namespace vascsim {
namespace {

// A small free-space scene: no maze, a short rod.
const char* const kScene = R"({
  "format": "vascsim-scene/1",
  "name": "tiny",
  "maze": null,
  "rod": {"nodes": 5, "length": 0.1, "density": 1000},
  "solver": {"preset": "fast"},
  "loads": {"damping": {"enabled": true, "coefficient": 4.0}, "point": [{"node": 4, "force": [0, 1e-4]}]},
  "run": {"duration": 0.01}
})";

SweepSpec spec_of(const std::string& text) { return read_sweep_text(text, "sweeps/s.json"); }

SweepPlan plan_of(const std::string& sweep) {
  return expand_sweep_with_scene(spec_of(sweep), kScene, "sweeps/tiny.json");
}

std::string error_of(const std::string& sweep) {
  try {
    plan_of(sweep);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << sweep;
  return "";
}

void expect_error(const std::string& sweep, const std::string& needle) {
  const std::string message = error_of(sweep);
  EXPECT_EQ(message.rfind("sweeps/s.json: ", 0), 0u) << message;
  EXPECT_NE(message.find(needle), std::string::npos) << "expected '" << needle << "' in: " << message;
}

std::string sweep_with_axes(const std::string& axes, const std::string& extra = "") {
  return R"({"format": "vascsim-sweep/1", "scene": "tiny.json", "axes": )" + axes + extra + "}";
}

TEST(SweepSpec, ProductRunsTheFirstAxisSlowestInTheOrderWritten) {
  // "/rod/nodes" sorts after "/loads/damping/coefficient" alphabetically; written first, it varies slowest.
  const SweepPlan plan = plan_of(sweep_with_axes(R"({"/rod/nodes": [5, 7], "/loads/damping/coefficient": [2, 4, 8]})"));
  ASSERT_EQ(plan.runs.size(), 6u);
  ASSERT_EQ(plan.spec.axes.size(), 2u);
  EXPECT_EQ(plan.spec.axes[0].pointer, "/rod/nodes");
  const char* expected[6][2] = {{"5", "2"}, {"5", "4"}, {"5", "8"}, {"7", "2"}, {"7", "4"}, {"7", "8"}};
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(plan.runs[i].index, i);
    EXPECT_EQ(plan.runs[i].id, "000" + std::to_string(i));
    EXPECT_EQ(plan.runs[i].values[0], expected[i][0]);
    EXPECT_EQ(plan.runs[i].values[1], expected[i][1]);
    const Scene s = read_scene_text(plan.runs[i].scene_json, "run");
    EXPECT_EQ(s.rod.nodes, std::stoi(expected[i][0]));
    EXPECT_DOUBLE_EQ(s.loads.damping.coefficient, std::stod(expected[i][1]));
    EXPECT_EQ(s.solver.preset, "fast");  // the rest of the scene as written
  }
}

TEST(SweepSpec, ZipPairsTheValuesAndRefusesUnequalLengths) {
  const SweepPlan plan = plan_of(sweep_with_axes(R"({"/loads/damping/coefficient": [2, 4], "/rod/density": [0.1, 0.2]})",
                                                 R"(, "combine": "zip")"));
  ASSERT_EQ(plan.runs.size(), 2u);
  EXPECT_EQ(plan.runs[1].values[0], "4");
  EXPECT_EQ(plan.runs[1].values[1], "0.2");
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": [2, 4], "/rod/density": [0.1, 0.2, 0.3]})", R"(, "combine": "zip")"),
               "/axes/~1rod~1density: expected 2 values (as many as /loads/damping/coefficient");
}

TEST(SweepSpec, RangesGiveIntegersStepsCountsAndLogScales) {
  auto values = [](const std::string& range) { return spec_of(sweep_with_axes(R"({"/maze/seed": )" + range + "}")).axes[0].values; };
  EXPECT_EQ(values(R"({"from": 1, "to": 4})"), (std::vector<std::string>{"1", "2", "3", "4"}));
  EXPECT_EQ(values(R"({"from": 0, "to": 10, "step": 4})"), (std::vector<std::string>{"0", "4", "8"}));
  // Round-off neither drops the last value nor shows in the values.
  EXPECT_EQ(values(R"({"from": 0.1, "to": 0.3, "step": 0.1})"), (std::vector<std::string>{"0.1", "0.2", "0.3"}));
  // Between integer bounds, values on integers are integers: an integer field takes them.
  EXPECT_EQ(values(R"({"from": 0, "to": 1, "count": 3})"), (std::vector<std::string>{"0", "0.5", "1"}));
  EXPECT_EQ(values(R"({"from": 5, "to": 9, "count": 3})"), (std::vector<std::string>{"5", "7", "9"}));
  // And with a step, whatever it is written as (1.0 gave 1.0, 2.0, 3.0, refused by /maze/seed).
  EXPECT_EQ(values(R"({"from": 1, "to": 3, "step": 1.0})"), (std::vector<std::string>{"1", "2", "3"}));
  EXPECT_EQ(values(R"({"from": 1, "to": 2, "step": 0.5})"), (std::vector<std::string>{"1", "1.5", "2"}));
  EXPECT_EQ(values(R"({"from": 10, "to": 1000, "count": 3, "scale": "log"})"), (std::vector<std::string>{"10", "100", "1000"}));
  EXPECT_EQ(values(R"({"from": 0.0, "to": 1.0, "count": 3})"), (std::vector<std::string>{"0.0", "0.5", "1.0"}));
  EXPECT_EQ(values(R"({"from": 0.001, "to": 0.1, "count": 3, "scale": "log"})"),
            (std::vector<std::string>{"0.001", "0.01", "0.1"}));
}

TEST(SweepSpec, RepeatsAreTheOuterLoop) {
  const SweepPlan plan = plan_of(sweep_with_axes(R"({"/loads/damping/coefficient": [2, 4]})", R"(, "repeats": 3)"));
  ASSERT_EQ(plan.runs.size(), 6u);
  EXPECT_EQ(plan.runs[2].repeat, 1);
  EXPECT_EQ(plan.runs[2].values[0], "2");
  EXPECT_EQ(plan.runs[5].repeat, 2);
  EXPECT_EQ(plan.runs[5].values[0], "4");
}

TEST(SweepSpec, FixedOverridesApplyToEveryRunAndDefaultsCanBeSwept) {
  // "/solver/dt" is not in the scene file: a field left at its default is added, the preset kept.
  const SweepPlan plan = plan_of(sweep_with_axes(R"({"/solver/dt": [1e-3, 5e-4]})", R"(, "overrides": {"/run/duration": 0.002, "/rod/length": 0.2})"));
  ASSERT_EQ(plan.runs.size(), 2u);
  for (const auto& run : plan.runs) {
    const Scene s = read_scene_text(run.scene_json, "run");
    EXPECT_DOUBLE_EQ(s.run.duration, 0.002);
    EXPECT_DOUBLE_EQ(s.rod.length, 0.2);
    EXPECT_EQ(s.solver.preset, "fast");
  }
  EXPECT_DOUBLE_EQ(read_scene_text(plan.runs[1].scene_json, "run").solver.dt, 5e-4);
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": [1]})", R"(, "overrides": {"/loads/damping/coefficient": 2})"),
               "/overrides/~1loads~1damping~1coefficient: /loads/damping/coefficient is also an axis");
}

// A sweep may switch a mode and set the fields of one of them: the runs where a field goes unused
// run with a warning (sim/scene/unused_fields.h), not an error, and a field the base scene's
// configuration leaves unused is still one an axis may set.
TEST(SweepSpec, FieldsUnusedInSomeRunsAreSetAndReportedThere) {
  const SweepPlan plan =
      plan_of(sweep_with_axes(R"({"/solver/adaptive": ["error", "off"]})", R"(, "overrides": {"/solver/rtol": 1e-3})"));
  ASSERT_EQ(plan.runs.size(), 2u);
  EXPECT_TRUE(read_scene_text(plan.runs[0].scene_json, "run").unused_given.empty());
  const Scene off = read_scene_text(plan.runs[1].scene_json, "run");
  ASSERT_EQ(off.unused_given.size(), 1u);
  EXPECT_EQ(off.unused_given[0].pointer, "/solver/rtol");
  // The plan counts them, for the sweep to say so once before anything runs.
  ASSERT_EQ(plan.unused.size(), 1u);
  EXPECT_EQ(plan.unused[0].pointer, "/solver/rtol");
  EXPECT_EQ(plan.unused[0].runs, 1u);
  EXPECT_EQ(plan_of(sweep_with_axes(R"({"/solver/load_steps": [2, 4]})")).runs.size(), 2u);
}

TEST(SweepSpec, PointersThatOverlapAreRefused) {
  // One inside another would set a field twice: the run's value and the results' column could
  // disagree (an axis /loads/damping beside /loads/damping/coefficient, or an override inside an axis).
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": [1, 2], "/loads/damping": [{"coefficient": 3}]})"),
               "/axes/~1loads~1damping: /loads/damping overlaps the axis /loads/damping/coefficient");
  expect_error(sweep_with_axes(R"({"/loads/damping": [{"coefficient": 3}]})", R"(, "overrides": {"/loads/damping/coefficient": 2})"),
               "/overrides/~1loads~1damping~1coefficient: /loads/damping/coefficient overlaps the axis /loads/damping");
  expect_error(sweep_with_axes(R"({"/solver/dt": [1e-3]})", R"(, "overrides": {"/rod/length": 0.2, "/rod": {"length": 0.3}})"),
               "/overrides/~1rod: /rod overlaps the override /rod/length");
  // A shared prefix that is not a whole token is no overlap.
  EXPECT_EQ(spec_of(sweep_with_axes(R"({"/rod/length": [0.2], "/rod/length2": [1]})")).axes.size(), 2u);
}

TEST(SweepSpec, APointerToNoFieldIsAnErrorNamingTheFieldsThere) {
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficientp": [1, 2]})"), "/axes/~1loads~1damping~1coefficientp: the scene sweeps/tiny.json has no field /loads/damping/coefficientp (fields of /loads/damping: ");
  EXPECT_NE(error_of(sweep_with_axes(R"({"/loads/damping/coefficientp": [1, 2]})")).find("enabled"), std::string::npos);
  expect_error(sweep_with_axes(R"({"/nothing/here": [1]})"), "has no field /nothing/here (fields of /: ");
  expect_error(sweep_with_axes(R"({"/loads/point/3/node": [1]})"), "has no field /loads/point/3/node");
  expect_error(sweep_with_axes(R"({"control/kp": [1]})"), "/axes/control~1kp: expected a JSON pointer into the scene such as \"/control/kp\"");
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": []})"), "/axes/~1loads~1damping~1coefficient: expected a non-empty list of values or a range");
}

TEST(SweepSpec, AValueTheSceneRefusesNamesTheRunAndTheField) {
  const std::string message = error_of(sweep_with_axes(R"({"/loads/damping/coefficient": [2, "fast", 4]})"));
  EXPECT_NE(message.find("sweeps/s.json: run 0001 (/loads/damping/coefficient = \"fast\"): sweeps/tiny.json: /loads/damping/coefficient: expected a number"),
            std::string::npos)
      << message;
  expect_error(sweep_with_axes(R"({"/rod/nodes": [5, 2]})"), "run 0001 (/rod/nodes = 2): sweeps/tiny.json: /rod/nodes: expected an integer in [3, ");
  // A maze scene refuses a shape: the same check as for a scene file.
  expect_error(sweep_with_axes(R"({"/solver/preset": ["fast", "fastest"]})"), "/solver/preset: expected one of");
}

TEST(SweepSpec, MistakesInTheFileItselfNameThePointer) {
  expect_error(R"({"scene": "tiny.json", "axes": {"/loads/damping/coefficient": [1]}})", "/format: missing");
  expect_error(R"({"format": "vascsim-sweep/2", "scene": "tiny.json", "axes": {"/loads/damping/coefficient": [1]}})", "/format: expected \"vascsim-sweep/1\"");
  expect_error(R"({"format": "vascsim-sweep/1", "axes": {"/loads/damping/coefficient": [1]}})", "/scene: missing");
  expect_error(sweep_with_axes("{}"), "/axes: expected at least one axis: an object of JSON pointers");
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": [1]})", R"(, "combine": "cross")"), "/combine: expected one of \"product\", \"zip\"");
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": [1]})", R"(, "repeat": 2)"), "/repeat: unknown key");
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": {"from": 3, "to": 1}})"), "/axes/~1loads~1damping~1coefficient/to: expected a number >= \"from\"");
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": {"from": 3}})"), "/axes/~1loads~1damping~1coefficient/to: missing");
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": {"from": 1, "to": 2, "stride": 1}})"), "/axes/~1loads~1damping~1coefficient/stride: unknown key");
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": {"from": 1, "to": 2, "step": 0}})"), "/axes/~1loads~1damping~1coefficient/step: expected a number > 0");
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": [1], "/loads/damping/coefficient": [2]})"), "/axes/~1loads~1damping~1coefficient: the key appears twice");
  expect_error(sweep_with_axes(R"({"/maze/seed": {"from": 1, "to": 1000}, "/loads/damping/coefficient": {"from": 1, "to": 1000}})"),
               "/axes: the sweep has 1000000 runs, more than the limit");
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": {"from": 1, "to": 11}})", R"(, "repeats": 10000)"),
               "/axes and /repeats: the sweep has 110000 runs (11 settings, each 10000 times), more than the limit");
}

// A value twice on one axis of a product (2 and 2.0 set the same number) would make its runs
// twice and count them under two rows of the per-value summary: refused, naming both places.
// A zipped axis may repeat a value beside different values of the others.
TEST(SweepSpec, AValueGivenTwiceOnAProductAxisIsRefused) {
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": [2, 4, 2.0]})"),
               "/axes/~1loads~1damping~1coefficient/2: the value 2.0 is given twice (also at "
               "/axes/~1loads~1damping~1coefficient/0): each run would be made twice; use \"repeats\"");
  expect_error(sweep_with_axes(R"({"/loads/damping/coefficient": [1, 2], "/rod/density": [0.1, 0.3, 0.1]})"),
               "/axes/~1rod~1density/2: the value 0.1 is given twice (also at /axes/~1rod~1density/0)");
  EXPECT_EQ(plan_of(sweep_with_axes(R"({"/loads/damping/coefficient": [2, 2, 4], "/rod/density": [0.1, 0.2, 0.3]})",
                                    R"(, "combine": "zip")"))
                .runs.size(),
            3u);
}

TEST(SweepSpec, TheBaseSceneIsCheckedAndNamed) {
  try {
    expand_sweep(read_sweep_text(sweep_with_axes(R"({"/loads/damping/coefficient": [1]})"), "/nonexistent/s.json"));
    ADD_FAILURE() << "accepted a missing scene";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/s.json: /scene: /nonexistent/tiny.json: cannot open scene file"),
              std::string::npos)
        << e.what();
  }
  // The shipped default scene, relative to the sweep file's folder.
  const std::string dir = test::fresh_temp_dir("sweep_spec_scene");
  test::write_text(dir + "/s.json", R"({"format": "vascsim-sweep/1", "scene": ")" + test::source_path("scenes/maze_default.json") +
                                        R"(", "axes": {"/control/kp": [2, 4, 8], "/maze/seed": {"from": 1, "to": 10}}})");
  const SweepPlan plan = expand_sweep(read_sweep_file(dir + "/s.json"));
  ASSERT_EQ(plan.runs.size(), 30u);
  const Scene last = read_scene_text(plan.runs[29].scene_json, "run");
  EXPECT_EQ(last.maze.seed, 10u);
  EXPECT_DOUBLE_EQ(last.control.kp, 8.0);
  EXPECT_TRUE(last.run.duration > 0);
}

TEST(SweepManifest, RoundTripsAndIsTheSameBytesForTheSameSweep) {
  const std::string sweep = sweep_with_axes(R"({"/solver/preset": ["fast", "balanced"], "/loads/damping/coefficient": {"from": 1, "to": 3}})",
                                            R"(, "overrides": {"/run/duration": 0.001})");
  const std::string a = sweep_manifest_json(manifest_of(plan_of(sweep)));
  EXPECT_EQ(a, sweep_manifest_json(manifest_of(plan_of(sweep))));
  const std::string dir = test::fresh_temp_dir("sweep_manifest");
  test::write_text(dir + "/manifest.json", a);
  const SweepManifest m = read_sweep_manifest(dir + "/manifest.json");
  EXPECT_EQ(sweep_manifest_json(m), a);
  ASSERT_EQ(m.runs.size(), 6u);
  EXPECT_EQ(m.runs[4].values[0], "\"balanced\"");
  EXPECT_EQ(m.runs[4].values[1], "2");
  EXPECT_EQ(m.axes[0].pointer, "/solver/preset");

  std::string tampered = a;
  tampered.replace(tampered.find("\"0003\""), 6, "\"0009\"");
  test::write_text(dir + "/manifest.json", tampered);
  try {
    read_sweep_manifest(dir + "/manifest.json");
    ADD_FAILURE() << "accepted a manifest with a wrong id";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("manifest.json: /runs/3/id: expected \"0003\", got \"0009\""), std::string::npos)
        << e.what();
  }
}

TEST(SweepManifest, IdsHaveAtLeastFourDigitsAndSortAsTheRuns) {
  EXPECT_EQ(sweep_run_id(7, 30), "0007");
  EXPECT_EQ(sweep_run_id(7, 10000), "0007");
  EXPECT_EQ(sweep_run_id(7, 10001), "00007");
  EXPECT_EQ(sweep_run_id(12345, 100000), "12345");
}

}  // namespace
}  // namespace vascsim

// Every documented scene error (docs/scenes.md, "Errors") through the executable: the message
// names the file, the JSON pointer and what was expected; the exit code is 2; nothing is written.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/cli_test_support.h"

namespace vascsim::test {
namespace {

struct BadScene {
  const char* name;
  const char* text;
  const char* message;  // expected after "FILE: "
};

const BadScene kBadScenes[] = {
    {"rows_zero", R"({"maze": {"rows": 0}})", "/maze/rows: expected an integer in [1, 200], got 0"},
    {"rows_float", R"({"maze": {"rows": 2.5}})", "/maze/rows: expected an integer in [1, 200], got 2.5"},
    {"one_cell", R"({"maze": {"rows": 1, "cols": 1}})",
     "/maze/cols: expected a maze of at least 2 cells (its start and goal are different cells), got 1"},
    // A whole number written as a float is not taken for one; the message says how to write it.
    {"rows_whole_float", R"({"maze": {"rows": 5e1}})",
     "/maze/rows: expected an integer in [1, 200] written without a decimal point or exponent, got 50.0"},
    {"cols_string", R"({"maze": {"cols": "five"}})", "/maze/cols: expected an integer in [1, 200], got \"five\""},
    {"unknown_top", R"({"mazes": {}})", "/mazes: unknown key"},
    {"unknown_nested", R"({"rod": {"nodes": 10, "lenght": 0.5}})", "/rod/lenght: unknown key"},
    // A key with '~' or '/' is one reference token of the pointer (RFC 6901): it was written as is.
    {"unknown_odd_key", R"({"rod": {"~odd/key": 1}})", "/rod/~0odd~1key: unknown key"},
    {"lumen_too_wide", R"({"maze": {"lumen_width": 0.3}})", "/maze/lumen_width: expected a number in [1e-06, 0.2], got 0.3"},
    {"negative_width", R"({"maze": {"width": -1}})", "/maze/width: expected a number in [0.001, 1000], got -1"},
    {"rod_nodes", R"({"rod": {"nodes": 1}})", "/rod/nodes: expected an integer in [3, 1000000], got 1"},
    {"inner_radius", R"({"rod": {"outer_radius": 0.002, "inner_radius": 0.002}})",
     "/rod/inner_radius: expected a number in [0, outer_radius = 0.002), got 0.002"},
    {"poisson", R"({"rod": {"poisson_ratio": 0.7}})", "/rod/poisson_ratio: expected a number in [-1, 0.5], got 0.7"},
    {"dt_tiny", R"({"solver": {"dt": 1e-300}})", "/solver/dt: expected a number in [1e-09, 10], got 1e-300"},
    // dt_min above the first step or the floor: the run failed on its first rejection, "at the
    // smallest step", with steps shorter than dt_min already taken.
    {"dt_min_over_floor", R"({"solver": {"adaptive": "error", "dt": 0.02, "dt_min": 0.01, "dt_floor": 0.001}})",
     "/solver/dt_min: expected at most the floor, dt_floor = 0.001 s, got 0.01"},
    {"dt_below_dt_min", R"({"solver": {"adaptive": "error", "dt": 1e-9, "dt_min": 1e-6}})",
     "/solver/dt_min: expected at most the first step, dt = 1e-09 s, got 1e-06"},
    {"static_prescribed", R"({"maze": null, "solver": {"mode": "static"}, "boundary": {"prescribed": [{"node": 5, "velocity": [0, 0.01]}]}})",
     "/boundary/prescribed: expected [] with solver mode \"static\""},
    {"speed_tiny", R"({"path": {"speed": 1e-308}})", "/path/speed: expected a number in [1e-09, 1000], got 1e-308"},
    // Once accepted and ignored: only kinematic mode imposes a tip to offset.
    {"position_disturbance_force_mode", R"({"control": {"mode": "force", "disturbance": {"kind": "position"}}})",
     "/control/disturbance/kind: expected \"force\" in force mode"},
    {"solver_name", R"({"path": {"solver": "dfs"}})", "/path/solver: expected one of \"wall_follower\", \"bfs\", got \"dfs\""},
    {"maze_not_object", R"({"maze": 5})", "/maze: expected an object, got 5"},
    {"walls_and_rows", R"({"maze": {"rows": 3, "walls": [{"from": [0, 0], "to": [1, 0]}]}})",
     "/maze/rows: expected no generator settings beside an explicit \"walls\" list, got 3"},
    {"wall_point", R"({"maze": {"walls": [{"from": [0, 0], "to": [1]}]}})",
     "/maze/walls/0/to: expected an array of 2 numbers [x, y] in [-1000, 1000], got [1]"},
    // Extreme values that used to pass the reader and fail at the first step as "the rod blew up"
    // (exit 1, as a diverging run) instead of an input error naming the field.
    {"start_far_away", R"({"maze": null, "shape": {"start": [1e20, 0]}})",
     "/shape/start: expected an array of 2 numbers [x, y] in [-1000, 1000], got [1e+20,0]"},
    {"gravity_huge", R"({"maze": null, "loads": {"gravity": {"acceleration": [0, -1e300]}}})",
     "/loads/gravity/acceleration: expected an array of 2 numbers [x, y] in [-10000, 10000], got [0,-1e+300]"},
    {"rod_length_subnormal", R"({"maze": null, "rod": {"length": 1e-308}})",
     "/rod/length: expected a number in [1e-06, 1000], got 1e-308"},
    {"point_force_huge", R"({"maze": null, "loads": {"point": [{"node": -1, "force": [1e300, 0]}]}})",
     "/loads/point/0/force: expected an array of 2 numbers [x, y] in [-1000000, 1000000], got [1e+300,0]"},
    {"wall_missing_to", R"({"maze": {"walls": [{"from": [0, 0]}]}})", "/maze/walls/0/to: expected a point [x, y], got null"},
    {"start_outside", R"({"maze": {"walls": [{"from": [0, 0], "to": [1, 0]}], "start": [2, 0.5]}})",
     "/maze/start: expected a point inside the maze bounds, got [2.0,0.5]"},
    {"format", R"({"format": "vascsim-scene/9"})", "/format: expected \"vascsim-scene/1\", got \"vascsim-scene/9\""},
    {"not_object", R"([1, 2])", "/: expected an object, got [1,2]"},
    {"shape_in_maze", R"({"shape": {"direction": 1.0}})",
     "/shape: expected no \"shape\" in a maze or vessel scene (the rod starts at the inlet, docs/navigation.md), got an object"},
    {"static_in_maze", R"({"solver": {"mode": "static"}})",
     "/solver/mode: expected \"dynamic\" in a maze scene (static equilibrium has no trajectory to follow), got \"static\""},
    {"static_ramp", R"({"maze": null, "solver": {"mode": "static"}, "loads": {"point": [{"force": [0, 1], "profile": "ramp"}]}})",
     "/loads/point/0/profile: expected \"constant\" with solver mode \"static\", got \"ramp\""},
    {"tangential_drag_on_tip", R"({"loads": {"drag": {"enabled": true, "area": "tip", "tangential_coefficient": 0.1}}})",
     "/loads/drag/tangential_coefficient: expected area \"nodes\" for a tangential coefficient (the tip's frontal drag has one), got 0.1"},
};

class SceneErrors : public ::testing::TestWithParam<BadScene> {};

TEST_P(SceneErrors, NameFilePointerAndExpectationAndExitTwo) {
  const BadScene& bad = GetParam();
  const std::string dir = fresh_temp_dir(std::string("scene_") + bad.name);
  const std::string scene = dir + "/bad.json";
  const std::string out = dir + "/maze.json";
  write_text(scene, bad.text);
  const CommandResult r = run_vascsim("maze --scene " + scene + " --out " + out);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(scene + ": " + bad.message), std::string::npos)
      << "expected: " << scene << ": " << bad.message << "\ngot: " << r.output;
  EXPECT_FALSE(std::filesystem::exists(out)) << "an output was written despite the error";
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Documented, SceneErrors, ::testing::ValuesIn(kBadScenes),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(SceneFiles, MissingFileAndInvalidJson) {
  const std::string dir = fresh_temp_dir("scene_files");
  CommandResult r = run_vascsim("maze --scene " + dir + "/absent.json --out " + dir + "/m.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find(dir + "/absent.json: cannot open scene file (No such file or directory)"), std::string::npos)
      << r.output;
  write_text(dir + "/broken.json", "{\"maze\": {\"rows\": 5,");
  r = run_vascsim("maze --scene " + dir + "/broken.json --out " + dir + "/m.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find(dir + "/broken.json: not valid JSON"), std::string::npos) << r.output;
  // A number no double holds is placed by line and column (the parser names only the number).
  write_text(dir + "/huge.json", "{\"maze\": {\"rows\": 5},\n  \"path\": {\"speed\": 1e400}}");
  r = run_vascsim("maze --scene " + dir + "/huge.json --out " + dir + "/m.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find(dir + "/huge.json: a number out of the double range at line 2, column 21"), std::string::npos)
      << r.output;
  std::filesystem::remove_all(dir);
}

// A vascsim file of another kind where a scene or a sweep was expected (the maze `vascsim maze`
// wrote, given to `vascsim run`; a scene given to `vascsim sweep`) is named with what it is and
// what to do with it, not only with the format expected.
TEST(SceneFiles, AFileOfAnotherKindSaysWhatItIsAndHowItIsUsed) {
  const std::string dir = fresh_temp_dir("scene_other_kinds");
  ASSERT_EQ(run_vascsim("maze --seed 3 --rows 4 --cols 6 --out " + dir + "/m.json").exit_code, 0);
  ASSERT_EQ(run_vascsim("vessels --scene " + source_path("scenes/vessel_tree.json") + " --out " + dir + "/v.json").exit_code, 0);
  const std::string expected = ": /format: expected \"vascsim-scene/1\", got ";
  CommandResult r = run_vascsim("run " + dir + "/m.json --out " + dir + "/r");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/m.json" + expected + "\"vascsim-maze/1\": it is a maze written by `vascsim maze` for "
                          "inspection; a scene makes its maze from the settings in its \"maze\" section"),
            std::string::npos) << r.output;
  r = run_vascsim("run " + dir + "/v.json --out " + dir + "/r");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/v.json" + expected + "\"vascsim-vessels/1\": it is a vessel network written by "
                          "`vascsim vessels`"), std::string::npos) << r.output;
  r = run_vascsim("sweep " + source_path("scenes/maze_default.json") + " --out " + dir + "/s");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("maze_default.json: /format: expected \"vascsim-sweep/1\", got \"vascsim-scene/1\": it is a "
                          "scene: `vascsim run FILE --out DIR` runs it"), std::string::npos) << r.output;
  // A format vascsim does not write gets no hint.
  write_text(dir + "/other.json", R"({"format": "someone-else/3"})");
  r = run_vascsim("run " + dir + "/other.json --out " + dir + "/r");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/other.json" + expected + "\"someone-else/3\"\n"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/r"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/s"));
  std::filesystem::remove_all(dir);
}

TEST(SceneFiles, ShippedScenesAreValid) {
  for (const char* name : {"scenes/maze_default.json", "scenes/paper_maze.json", "scenes/maze_body_drag.json"}) {
    const std::string dir = fresh_temp_dir("shipped");
    const CommandResult r = run_vascsim("maze --scene " + source_path(name) + " --out " + dir + "/m.json");
    EXPECT_EQ(r.exit_code, 0) << name << ": " << r.output;
    std::filesystem::remove_all(dir);
  }
}

}  // namespace
}  // namespace vascsim::test

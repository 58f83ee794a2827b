// Fields a scene gives that its configuration does not use (sim/scene/unused_fields.h): each is
// reported by the reader with the setting that leaves it unused, left out of the canonical text
// (which then reads back with nothing to report), and warned of by `vascsim run`, which records
// it in summary.json. Which settings use which fields was found by running each case without
// the field and with it (a QA pass comparing frame records): the output did not change.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/io/scene_reader.h"
#include "sim/log/frame_log.h"
#include "tests/cli_test_support.h"

namespace vascsim {
namespace {

struct UnusedCase {
  const char* name;
  const char* scene;
  const char* pointer;
  const char* why;  // a fragment of the reason given
};

#define TUBE R"("vessels": {"nodes": {"a": [0, 0], "b": [0.5, 0]}, "segments": [{"from": "a", "to": "b", "radius": 0.05}], "start": "a", "goal": "b"})"

const UnusedCase kCases[] = {
    {"route_in_free_space", R"({"maze": null, "path": {"speed": 3}})", "/path/speed", "no route"},
    {"walls_in_free_space", R"({"maze": null, "contact": {"friction": 0.5}})", "/contact/friction", "no walls"},
    {"maze_solver_in_vessels", "{" TUBE R"(, "path": {"solver": "bfs"}})", "/path/solver", "graph or mask"},
    {"wall_follower_on_explicit_walls", R"({"maze": {"walls": [{"from": [0, 0], "to": [1, 0]}], "start": [0.5, 0.5], "goal": [0.1, 0.1]},
     "path": {"solver": "wall_follower"}})", "/path/solver", "breadth-first"},
    {"friction_under_paper", R"({"contact": {"mode": "paper", "friction": 0.1}})", "/contact/friction", "\"paper\""},
    {"barrier_without_contact", R"({"contact": {"mode": "none", "stiffness": 1}})", "/contact/stiffness", "\"none\""},
    {"penalty_under_implicit", R"({"contact": {"paper_gain": 10}})", "/contact/paper_gain", "\"implicit\""},
    {"slip_without_friction", R"({"contact": {"slip_velocity": 0.01}})", "/contact/slip_velocity", "friction is 0"},
    {"gains_without_actuation", R"({"control": {"mode": "none", "kp": 40}})", "/control/kp", "\"none\""},
    {"magnet_in_force_mode", R"({"control": {"magnet_moment": 0.1}})", "/control/magnet_moment", "\"field\""},
    {"force_on_a_kinematic_tip", R"({"control": {"mode": "kinematic", "kp": 0.5, "disturbance": {"amplitude": 0.01}}})",
     "/control/disturbance", "\"kinematic\""},
    {"frequency_of_no_disturbance", R"({"control": {"disturbance": {"amplitude": 0, "omega": 50}}})", "/control/disturbance/omega",
     "amplitude is 0"},
    {"frequency_of_no_oscillation", R"({"maze": null, "boundary": {"prescribed": [{"node": 0, "velocity": [0, 0.1], "frequency": 3}]}})",
     "/boundary/prescribed/0/frequency", "amplitude is [0, 0]"},
    {"tolerance_with_a_fixed_step", R"({"maze": null, "solver": {"adaptive": "off", "rtol": 1e-3}})", "/solver/rtol", "\"off\""},
    {"largest_step_with_dt_alone", R"({"maze": null, "solver": {"dt": 2e-3, "dt_max": 0.01}})", "/solver/dt_max", "\"retry\""},
    {"burst_without_mean_floor", R"({"maze": null, "solver": {"dt_mean_min": 0, "mean_burst": 5}})", "/solver/mean_burst",
     "dt_mean_min is 0"},
    {"halvings_when_off", R"({"maze": null, "solver": {"adaptive": "off", "max_halvings": 2}})", "/solver/max_halvings", "\"off\""},
    {"load_steps_in_dynamics", R"({"maze": null, "solver": {"load_steps": 3}})", "/solver/load_steps", "\"dynamic\""},
    {"time_step_in_statics", R"({"maze": null, "solver": {"mode": "static", "dt": 0.5}})", "/solver/dt", "\"static\""},
    {"output_interval_in_statics", R"({"maze": null, "solver": {"mode": "static"}, "run": {"output_interval": 0.5}})",
     "/run/output_interval", "\"static\""},
    {"frequency_of_a_constant_load", R"({"maze": null, "loads": {"point": [{"node": -1, "force": [0, 1], "frequency": 9}]}})",
     "/loads/point/0/frequency", "not \"sine\""},
    {"ramp_of_a_sine_load", R"({"maze": null, "loads": {"point": [{"node": -1, "force": [0, 1], "profile": "sine", "ramp_time": 2}]}})",
     "/loads/point/0/ramp_time", "not \"ramp\""},
};

class UnusedFields : public ::testing::TestWithParam<UnusedCase> {};

TEST_P(UnusedFields, AreReportedAndLeftOutOfTheCanonicalText) {
  const UnusedCase& c = GetParam();
  const Scene scene = read_scene_text(c.scene, "s.json");
  ASSERT_EQ(scene.unused_given.size(), 1u) << c.scene;
  EXPECT_EQ(scene.unused_given[0].pointer, c.pointer);
  EXPECT_NE(scene.unused_given[0].why.find(c.why), std::string::npos) << scene.unused_given[0].why;
  const std::string canonical = scene_to_json(scene);
  EXPECT_FALSE(nlohmann::json::parse(canonical).contains(nlohmann::json::json_pointer(c.pointer))) << canonical;
  const Scene again = read_scene_text(canonical, "canonical.json");
  EXPECT_TRUE(again.unused_given.empty()) << again.unused_given[0].pointer;
  EXPECT_EQ(scene_to_json(again), canonical);
}

INSTANTIATE_TEST_SUITE_P(Scenes, UnusedFields, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(UnusedFields, TheSameFieldWhereItIsUsedIsNotReported) {
  for (const char* text : {R"({"contact": {"mode": "implicit", "friction": 0.1, "slip_velocity": 0.01}})",
                           R"({"contact": {"mode": "paper", "paper_gain": 10}})",
                           // Self-contact's barrier takes these two, with walls or without, in any mode.
                           R"({"maze": null, "contact": {"self": true, "activation_distance": 0.001, "stiffness": 2}})",
                           R"({"contact": {"mode": "paper", "self": true, "activation_distance": 0.001, "stiffness": 2}})",
                           R"({"control": {"mode": "field", "magnet_moment": 0.1}})",
                           R"({"control": {"mode": "kinematic", "kp": 0.5, "disturbance": {"kind": "position", "amplitude": 0.01}}})",
                           R"({"maze": null, "solver": {"adaptive": "error", "rtol": 1e-3, "dt_max": 0.01}})",
                           R"({"maze": null, "solver": {"mode": "static", "load_steps": 3}})",
                           R"({"maze": null, "loads": {"point": [{"node": -1, "force": [0, 1], "profile": "sine", "frequency": 9}]}})",
                           R"({"maze": null, "boundary": {"prescribed": [{"node": 0, "amplitude": [0, 0.01], "frequency": 3}]}})",
                           R"({"control": {"disturbance": {"amplitude": 0.001, "omega": 50}}})"}) {
    const Scene scene = read_scene_text(text, "s.json");
    EXPECT_TRUE(scene.unused_given.empty()) << text << ": " << scene.unused_given[0].pointer;
  }
}

TEST(UnusedFields, ShippedScenesGiveNone) {
  for (const char* name : {"maze_default", "maze_body_drag", "paper_maze", "cantilever", "coil_chamber", "bifurcation",
                           "aneurysm", "stenosis", "tortuous", "vessel_tree", "vessel_mask"}) {
    const Scene scene = read_scene_file(test::source_path(std::string("scenes/") + name + ".json"));
    for (const UnusedField& u : scene.unused_given) ADD_FAILURE() << name << ": " << u.pointer << " (" << u.why << ")";
  }
}

TEST(UnusedFields, RunWarnsNamingTheFileAndRecordsThemInTheSummary) {
  const std::string dir = test::fresh_temp_dir("unused_fields_run");
  test::write_text(dir + "/s.json", R"({"maze": null, "rod": {"nodes": 5}, "boundary": {"clamp": "first_edge"},
    "contact": {"friction": 0.5}, "solver": {"load_steps": 4}, "run": {"duration": 0.01}})");
  const test::CommandResult r = test::run_vascsim("run " + dir + "/s.json --out " + dir + "/out --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("warning: " + dir + "/s.json: /contact/friction has no effect here: a scene without a maze or vessels has no walls"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("/solver/load_steps has no effect here"), std::string::npos) << r.output;
  const auto summary = nlohmann::json::parse(test::read_text(dir + "/out/summary.json"));
  ASSERT_EQ(summary["unused_fields"].size(), 2u) << summary["unused_fields"].dump();
  EXPECT_EQ(summary["unused_fields"][0]["pointer"], "/solver/load_steps");
  EXPECT_EQ(summary["unused_fields"][1]["pointer"], "/contact/friction");
  // The commands that write a scene of their own say so too.
  test::write_text(dir + "/maze.json", R"({"contact": {"mode": "paper", "friction": 0.1}})");
  const test::CommandResult m = test::run_vascsim("maze --scene " + dir + "/maze.json --out " + dir + "/maze_out.json");
  ASSERT_EQ(m.exit_code, 0) << m.output;
  EXPECT_NE(m.output.find("vascsim maze: warning: " + dir + "/maze.json: /contact/friction has no effect here"), std::string::npos)
      << m.output;
  EXPECT_EQ(test::read_text(dir + "/maze_out.json").find("friction"), std::string::npos);
}

// A field reported unused must change nothing: paper contact in free space (no walls) changed the
// Newton predictor, and the frames drifted apart at round-off (a QA pass found it).
TEST(UnusedFields, AReportedFieldChangesNoFrame) {
  const std::string dir = test::fresh_temp_dir("unused_fields_frames");
  const std::string base = R"({"maze": null, "rod": {"nodes": 12}, "boundary": {"clamp": "first_edge"},
    "loads": {"gravity": {"enabled": true}}, "run": {"duration": 0.3})";
  test::write_text(dir + "/plain.json", base + "}");
  test::write_text(dir + "/paper.json", base + R"(, "contact": {"mode": "paper", "paper_gain": 9}})");
  for (const char* name : {"plain", "paper"}) {
    const test::CommandResult r = test::run_vascsim(std::string("run ") + dir + "/" + name + ".json --out " + dir + "/" + name + " --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  FrameLogReader plain(dir + "/plain/frames.vlog"), paper(dir + "/paper/frames.vlog");
  ASSERT_EQ(plain.frame_count(), paper.frame_count());
  std::vector<double> a, b;
  for (std::size_t i = 0; i < plain.frame_count(); ++i) {
    plain.read(i, a);
    paper.read(i, b);
    ASSERT_EQ(a, b) << "frame " << i;
  }
}

// The kinematic tip's motion is imposed, so a force disturbance on it moved nothing; it was
// still written to force/external in every frame, as if it had acted.
TEST(UnusedFields, AKinematicTipLogsNoForceDisturbance) {
  const std::string dir = test::fresh_temp_dir("unused_fields_kinematic");
  test::write_text(dir + "/s.json", R"({"rod": {"nodes": 12}, "control": {"mode": "kinematic", "kp": 0.5},
    "run": {"duration": 0.05}})");
  const test::CommandResult r = test::run_vascsim("run " + dir + "/s.json --out " + dir + "/out --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;  // the default disturbance was not written
  FrameLogReader log(dir + "/out/frames.vlog");
  EXPECT_LT(log.header().find_channel("force/external"), 0);
}

}  // namespace
}  // namespace vascsim

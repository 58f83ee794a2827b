// The rod-core scene sections (shape, boundary, loads, solver; sim/io/read_*.cpp): defaults,
// presets with explicit overrides, a stable round trip, and errors naming the JSON path.
#include <gtest/gtest.h>

#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/scene/input_error.h"
#include "sim/step/model.h"

namespace vascsim {
namespace {

TEST(SolverSections, PresetThenExplicitOverride) {
  const Scene s = read_scene_text(R"({"maze": null, "solver": {"preset": "fast", "rel_tol": 1e-7}})", "t.json");
  EXPECT_EQ(s.solver.scheme, Scheme::kBdf2);
  EXPECT_EQ(s.solver.dt, 4e-3);
  EXPECT_EQ(s.solver.rel_tol, 1e-7);
  // The presets control the error, with their former fixed step as the floor and first step.
  EXPECT_EQ(s.solver.adaptive, StepControl::kError);
  EXPECT_EQ(s.solver.dt_floor, 4e-3);
  EXPECT_EQ(read_scene_text(R"({"maze": null})", "t.json").solver.rtol, 5e-5);
  // A scene that gives its dt and not its step control steps at that dt, as it did before.
  const Scene d = read_scene_text(R"({"maze": null, "solver": {"preset": "accurate", "dt": 1e-4}})", "t.json");
  EXPECT_EQ(d.solver.adaptive, StepControl::kRetry);
  EXPECT_EQ(d.solver.dt, 1e-4);
  EXPECT_EQ(read_scene_text(R"({"maze": null, "solver": {"dt": 1e-4, "adaptive": "error"}})", "t.json").solver.adaptive,
            StepControl::kError);
  // And a floor on the mean step with 10 s of credit below it (sim/step/step_budget.h).
  EXPECT_EQ(s.solver.dt_mean_min, 1e-2);
  EXPECT_DOUBLE_EQ(s.solver.mean_burst, 1000.0);
  const Scene m = read_scene_text(R"({"maze": null, "solver": {"dt_mean_min": 0, "mean_burst": 5}})", "t.json");
  EXPECT_EQ(m.solver.dt_mean_min, 0.0);
  EXPECT_EQ(m.solver.mean_burst, 5.0);
  EXPECT_EQ(m.solver.dt_floor, 1e-3) << "the balanced preset's hard floor stays";
  EXPECT_EQ(s.solver.newton_stop_share, 0.3);
  EXPECT_EQ(read_scene_text(R"({"maze": null, "solver": {"newton_stop_share": 0}})", "t.json").solver.newton_stop_share, 0.0);
  const std::pair<const char*, const char*> refused[] = {{R"({"maze": null, "solver": {"dt_floor": 0.5}})", "dt_floor"},
                                                          {R"({"maze": null, "solver": {"dt_mean_min": 0.5}})", "dt_mean_min"},
                                                          {R"({"maze": null, "solver": {"mean_burst": -1}})", "mean_burst"},
                                                          {R"({"maze": null, "solver": {"newton_stop_share": 2}})", "newton_stop_share"}};
  for (const auto& [text, key] : refused) {
    try {
      read_scene_text(text, "t.json");
      ADD_FAILURE() << "accepted " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("/solver/") + key), std::string::npos) << e.what();
    }
  }
  const Scene e = read_scene_text(R"({"maze": null, "solver": {"adaptive": "error", "rtol": 1e-5}})", "t.json");
  EXPECT_EQ(e.solver.adaptive, StepControl::kError);
  EXPECT_EQ(e.solver.rtol, 1e-5);
  // The older spelling, as the scenes stored in older logs have it.
  EXPECT_EQ(read_scene_text(R"({"maze": null, "solver": {"adaptive": true}})", "t.json").solver.adaptive, StepControl::kRetry);
  EXPECT_EQ(read_scene_text(R"({"maze": null, "solver": {"adaptive": false}})", "t.json").solver.adaptive, StepControl::kOff);
}

TEST(SolverSections, RoundTripIsStable) {
  const Scene a = read_scene_text(R"({"maze": null,
    "shape": {"start": [0.1, 0.2], "direction": 1.5, "rest_curvature": 3},
    "boundary": {"clamp": "centred", "pinned": [-1], "prescribed": [{"node": 5, "velocity": [0, 1]}]},
    "loads": {"gravity": {"enabled": true}, "drag": {"enabled": true, "area": "tip"},
              "point": [{"node": -1, "force": [0, -1], "profile": "sine", "frequency": 2}]},
    "solver": {"preset": "accurate", "dt": 1e-4, "stable_branch": false}})", "t.json");
  const std::string once = scene_to_json(a);
  const Scene b = read_scene_text(once, "again.json");
  EXPECT_EQ(scene_to_json(b), once);
  EXPECT_EQ(b.boundary.clamp, ClampKind::kCentred);
  EXPECT_EQ(b.boundary.prescribed.at(0).node, 5);
  EXPECT_EQ(b.loads.point_loads.at(0).profile, LoadProfile::kSine);
  EXPECT_EQ(b.loads.drag.area, DragArea::kTipFrontal);
  EXPECT_EQ(b.solver.dt, 1e-4);
  EXPECT_EQ(b.solver.scheme, Scheme::kBdf2);
  // stable_branch sets the static solve: a dynamic scene reports it unused, and its canonical
  // text leaves it out, so that text reads back with nothing to report.
  ASSERT_EQ(a.unused_given.size(), 1u);
  EXPECT_EQ(a.unused_given[0].pointer, "/solver/stable_branch");
  EXPECT_EQ(once.find("stable_branch"), std::string::npos);
  EXPECT_TRUE(b.unused_given.empty());
}

TEST(SolverSections, ErrorsNameTheJsonPath) {
  try {
    read_scene_text(R"({"maze": null, "solver": {"scheme": "rk4"}})", "bad.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.json: /solver/scheme"), std::string::npos) << e.what();
  }
  try {
    read_scene_text(R"({"maze": null, "loads": {"point": [{"node": 1, "forse": [0, 1]}]}})", "bad.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/loads/point/0/forse"), std::string::npos) << e.what();
  }
  // Node indices are checked against the rod when the model is built.
  const Scene s = read_scene_text(R"({"maze": null, "rod": {"nodes": 10}, "boundary": {"pinned": [12]}})", "bad.json");
  try {
    compile(s);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.json: /boundary/pinned/0"), std::string::npos) << e.what();
  }
}

TEST(SolverSections, CantileverSceneLoads) {
  const Scene s = read_scene_file(VASCSIM_SOURCE_DIR "/scenes/cantilever.json");
  EXPECT_FALSE(s.has_environment);
  EXPECT_EQ(s.boundary.clamp, ClampKind::kCentred);
  const Model m = *compile(s);
  EXPECT_EQ(m.constraints.size(), 2u);
  EXPECT_EQ(m.forces.size(), 2u);  // point load and damping; nothing else is paid for
}

}  // namespace
}  // namespace vascsim

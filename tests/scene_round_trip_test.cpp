// The canonical scene text (scene_to_json) is what every frame log and summary stores so that a
// run can be reproduced from its outputs: for each shipped scene, as written and as compiled
// (the resolved copy a log holds), that text must read back as a scene and give the same text.
// Found by the scene fuzz harness (tests/fuzz): a maze scene's canonical text carried a "shape"
// section, which the reader refuses beside an environment.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/scene/input_error.h"
#include "sim/step/model.h"

namespace vascsim {
namespace {

std::string reread(const std::string& canonical, const std::string& label) {
  try {
    return scene_to_json(read_scene_text(canonical, label));
  } catch (const InputError& e) {
    return std::string("refused: ") + e.what();
  }
}

TEST(SceneRoundTrip, CanonicalTextOfEveryShippedSceneReadsBackUnchanged) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(VASCSIM_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    ++scenes;
    const std::string path = entry.path().string();
    const Scene scene = read_scene_file(path);
    const std::string given = scene_to_json(scene);
    EXPECT_EQ(reread(given, path), given) << path << " as written";
    const std::string compiled = scene_to_json(compile(scene)->scene);
    EXPECT_EQ(reread(compiled, path), compiled) << path << " as compiled (what its log stores)";
  }
  EXPECT_GE(scenes, 10);
}

// The reader normalises a disturbance direction; normalising it again when the canonical text is
// read moved its last bit (0.70710678118641 06 -> 07), so a log's scene text was not a fixed
// point (found by the fuzz harness: tests/fuzz/regressions/scene/direction_renormalised.json).
TEST(SceneRoundTrip, UnitDirectionIsAFixedPoint) {
  const Scene scene = read_scene_text(
      R"({"control": {"disturbance": {"direction": [0.7071067811862738, 0.7071067811865476]}}})",
      "direction.json");
  const std::string once = scene_to_json(scene);
  EXPECT_EQ(reread(once, "direction.json"), once);
  EXPECT_NEAR(scene.control.disturbance.direction.norm(), 1.0, 1e-15);
  // A direction that is not of unit length is still normalised.
  EXPECT_EQ(read_scene_text(R"({"control": {"disturbance": {"direction": [3, 4]}}})", "d.json")
                .control.disturbance.direction,
            Vec2(0.6, 0.8));
  // Directions whose plain norm overflows or underflows: once [1e200, 1e200] vanished (an
  // infinite norm) and [1e-200, 1e-200] was refused as zero.
  for (const char* direction : {"[1e200, 1e200]", "[1e-200, 1e-200]"}) {
    const Vec2 d = read_scene_text(std::string(R"({"control": {"disturbance": {"direction": )") + direction + "}}}", "d.json")
                       .control.disturbance.direction;
    EXPECT_NEAR(d.x(), std::sqrt(0.5), 1e-15) << direction;
    EXPECT_NEAR(d.y(), std::sqrt(0.5), 1e-15) << direction;
  }
}

}  // namespace
}  // namespace vascsim

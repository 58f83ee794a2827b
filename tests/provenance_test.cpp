// Provenance: `vascsim --version` names the version and the commit of the build, and every
// summary.json and frame log metadata carry the same version and commit with the hash of the
// canonical scene they ran, so a result traces back to its code and input.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/io/log_metadata.h"
#include "sim/io/provenance.h"
#include "sim/io/scene_reader.h"
#include "sim/scene/input_error.h"
#include "sim/log/frame_log.h"
#include "tests/cli_test_support.h"
#include "tests/png_bytes_support.h"

namespace vascsim::test {
namespace {

// FNV-1a 64-bit test vectors from the algorithm's authors (Fowler, Noll, Vo; IETF draft
// draft-eastlake-fnv, appendix C): "" and "a" and "foobar".
TEST(Provenance, SceneHashIsFnv1a64) {
  EXPECT_EQ(scene_hash(""), "cbf29ce484222325");
  EXPECT_EQ(scene_hash("a"), "af63dc4c8601ec8c");
  EXPECT_EQ(scene_hash("foobar"), "85944171f73967e8");
}

TEST(Provenance, VersionSummaryAndLogAgree) {
  const CommandResult version = run_vascsim("--version");
  ASSERT_EQ(version.exit_code, 0) << version.output;
  // "vascsim X.Y.Z (commit C)", parsed by hand: GCC 12 warns inside <regex> under ASan.
  const std::string line = version.output.substr(0, version.output.find('\n'));
  const std::string prefix = "vascsim ", middle = " (commit ";
  const std::size_t at = line.find(middle);
  ASSERT_EQ(line.rfind(prefix, 0), 0u) << line;
  ASSERT_NE(at, std::string::npos) << line;
  ASSERT_EQ(line.back(), ')') << line;
  const std::string number = line.substr(prefix.size(), at - prefix.size());
  const std::string commit = line.substr(at + middle.size(), line.size() - at - middle.size() - 1);
  ASSERT_EQ(std::count(number.begin(), number.end(), '.'), 2) << number;
  ASSERT_EQ(number.find_first_not_of("0123456789."), std::string::npos) << number;
  ASSERT_FALSE(commit.empty()) << line;
  ASSERT_EQ(commit.find_first_not_of("0123456789abcdefghijklmnopqrstuvwxyz.-"), std::string::npos) << commit;

  const std::string dir = fresh_temp_dir("provenance");
  const char* scene = R"({"name": "short", "maze": {"seed": 4}, "rod": {"nodes": 12},
                          "path": {"speed": 0.2}, "run": {"duration": 0.2, "output_interval": 0.1}})";
  write_text(dir + "/scene.json", scene);
  for (const char* out : {"/a", "/b"})
    ASSERT_EQ(run_vascsim("run " + dir + "/scene.json --out " + dir + out + " --quiet").exit_code, 0);
  write_text(dir + "/other.json", std::string(scene).replace(std::string(scene).find("\"seed\": 4"), 9, "\"seed\": 5"));
  ASSERT_EQ(run_vascsim("run " + dir + "/other.json --out " + dir + "/c --quiet").exit_code, 0);

  auto summary = [&](const char* run) { return nlohmann::json::parse(read_text(dir + run + "/summary.json"))["provenance"]; };
  const auto a = summary("/a");
  EXPECT_EQ(a["vascsim_version"], number);
  EXPECT_EQ(a["commit"], commit);
  ASSERT_TRUE(a["scene_hash"].is_string());
  EXPECT_EQ(a["scene_hash"].get<std::string>().size(), 16u);
  EXPECT_EQ(summary("/b")["scene_hash"], a["scene_hash"]) << "the same scene hashed differently";
  EXPECT_NE(summary("/c")["scene_hash"], a["scene_hash"]) << "another maze seed hashed the same";

  const FrameLogReader log(dir + "/a/frames.vlog");
  const LogMetadata meta = read_log_metadata(log.header().metadata, "a");
  EXPECT_EQ(meta.vascsim_version, number);
  EXPECT_EQ(meta.commit, commit);
  EXPECT_EQ(meta.scene_hash, a["scene_hash"].get<std::string>());
  EXPECT_EQ(meta.scene_hash, scene_hash(meta.scene_json))
      << "the hash is not that of the canonical scene the log carries";
}

// A vessel mask's scene names its image by path, so the canonical scene carries the pixels' hash:
// the scene hash tells two images apart, and a scene re-read (from a log, say) after its image
// changed is refused, naming the field and the image, rather than run on other vessels.
TEST(Provenance, AMaskScenesHashCoversItsPixels) {
  const std::string dir = fresh_temp_dir("provenance_mask");
  std::vector<std::uint8_t> disc(60 * 60, 0);
  for (int row = 0; row < 60; ++row)
    for (int col = 0; col < 60; ++col)
      if ((col - 30) * (col - 30) + (row - 30) * (row - 30) < 400) disc[static_cast<std::size_t>(row * 60 + col)] = 255;
  const auto write_image = [&] { std::ofstream(dir + "/lumen.png", std::ios::binary) << png_bytes(60, 60, 0, disc); };
  write_image();
  write_text(dir + "/scene.json",
             R"({"vessels": {"mask": {"file": "lumen.png", "pixel_size": 0.01}, "start": [0.3, 0.3], "goal": [0.35, 0.3]}})");
  const std::string canonical = scene_to_json(read_scene_file(dir + "/scene.json"));
  const std::string hash = nlohmann::json::parse(canonical)["vessels"]["mask"]["pixel_hash"].get<std::string>();
  EXPECT_EQ(hash.size(), 16u);
  write_text(dir + "/canonical.json", canonical);
  EXPECT_EQ(scene_to_json(read_scene_file(dir + "/canonical.json")), canonical);  // the same image: read as before

  disc[30 * 60 + 30] = 254;  // one grey level of one pixel
  write_image();
  const std::string changed = scene_to_json(read_scene_file(dir + "/scene.json"));
  EXPECT_NE(nlohmann::json::parse(changed)["vessels"]["mask"]["pixel_hash"].get<std::string>(), hash);
  EXPECT_NE(provenance_of(changed).scene_hash, provenance_of(canonical).scene_hash);
  try {
    read_scene_file(dir + "/canonical.json");
    ADD_FAILURE() << "a scene whose image changed was read";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(dir + "/canonical.json: /vessels/mask/pixel_hash: expected the hash of "), std::string::npos) << message;
    EXPECT_NE(message.find("lumen.png"), std::string::npos) << message;
    EXPECT_NE(message.find(hash), std::string::npos) << message;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vascsim::test

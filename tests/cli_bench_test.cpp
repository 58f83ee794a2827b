// `vascsim bench accuracy` as a user drives it: its CSV holds every row, the presets among them,
// and bad output paths or a missing scene directory are refused before any run, with exit code 2
// and the path named, nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/cli_test_support.h"

namespace vascsim::test {
namespace {

namespace fs = std::filesystem;

TEST(CliBench, AccuracyWritesEveryRowWithThePresets) {
  const std::string dir = fresh_temp_dir("bench_accuracy");
  const CommandResult r = run_vascsim("bench accuracy --quick --csv " + dir + "/accuracy.csv");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string csv = read_text(dir + "/accuracy.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "problem,scheme,dt,nodes,rel_tol,error,wall_time,iterations,ok");
  for (const char* row : {"bdf2/preset fast", "bdf2/preset balanced", "bdf2/preset accurate", "bdf2/preset fast dt_max 0.1", "bdf2/err 1e-04", "elastica_alpha_1"})
    EXPECT_NE(csv.find(row), std::string::npos) << row;
  EXPECT_EQ(csv.find(",0\n"), std::string::npos) << "a row failed:\n" << csv;
  fs::remove_all(dir);
}

TEST(CliBench, AccuracyRefusesBadOutputsAndMissingScenesUpFront) {
  const std::string dir = fresh_temp_dir("bench_accuracy_bad");
  CommandResult r = run_vascsim("bench accuracy --quick --csv " + dir + "/missing/accuracy.csv");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/missing"), std::string::npos) << r.output;
  r = run_vascsim("bench accuracy --scenes " + dir + "/no_scenes --csv " + dir + "/accuracy.csv --traversal-csv " + dir +
                  "/traversal.csv");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/no_scenes/maze_body_drag.json"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir)) << "something was written";
  // --seeds needs a generated maze in maze_body_drag.json: a vessel network has no seed.
  fs::create_directories(dir + "/vessels");
  fs::copy_file(source_path("scenes/vessel_tree.json"), dir + "/vessels/maze_body_drag.json");
  fs::copy_file(source_path("scenes/maze_default.json"), dir + "/vessels/maze_default.json");
  r = run_vascsim("bench accuracy --seeds 3 --scenes " + dir + "/vessels --csv " + dir + "/accuracy.csv --traversal-csv " +
                  dir + "/traversal.csv");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--seeds: " + dir + "/vessels/maze_body_drag.json has no generated maze"), std::string::npos)
      << r.output;
  r = run_vascsim("bench accuracy --seeds 0 --quick --csv " + dir + "/accuracy.csv");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--seeds"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/accuracy.csv"));
  EXPECT_FALSE(fs::exists(dir + "/traversal.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vascsim::test

// `vascsim maze` as a user drives it: help, usage errors, no silent overwrite, determinism.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/cli_test_support.h"

namespace vascsim::test {
namespace {

TEST(CliMaze, HelpListsEveryOption) {
  const CommandResult r = run_vascsim("maze --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* option : {"--scene", "--seed", "--rows", "--cols", "--lumen-width", "--solver", "--corner-radius",
                             "--speed", "--out", "--force"})
    EXPECT_NE(r.output.find(option), std::string::npos) << option << " missing from:\n" << r.output;
  const CommandResult top = run_vascsim("--help");
  EXPECT_EQ(top.exit_code, 0);
  EXPECT_NE(top.output.find("maze"), std::string::npos);
  // `vascsim help maze` prints the same as `vascsim maze --help`; an unknown one is refused.
  const CommandResult alias = run_vascsim("help maze");
  EXPECT_EQ(alias.exit_code, 0);
  EXPECT_EQ(alias.output, r.output);
  EXPECT_EQ(run_vascsim("help mazes").exit_code, 2);
}

TEST(CliMaze, UsageErrorsExitTwo) {
  const std::string dir = fresh_temp_dir("usage");
  struct Case { std::string args, message; };
  const Case cases[] = {
      {"maze --bogus --out " + dir + "/m.json", "unknown option '--bogus'"},
      {"maze --rows 0 --out " + dir + "/m.json", "--rows: expected an integer in [1, 200], got '0'"},
      // Named by the option, not as the built-in scene's /maze/lumen_width.
      {"maze --lumen-width 1e-6 --out " + dir + "/m.json", "--lumen-width: the lumen (0.001 mm) must be wider than the rod (4 mm across, /rod/outer_radius)"},
      // One cell holds both the start and the goal: a run reached its goal at its first step.
      {"maze --rows 1 --cols 1 --out " + dir + "/m.json", "--rows 1 --cols 1: a maze has at least 2 cells (its start and goal are different cells)"},
      {"maze --rows", "option '--rows' needs a value R"},
      // An unset variable in a script: named, not ": cannot write".
      {"maze --out ''", "option '--out' needs a value FILE, got an empty one"},
      {"maze --out=", "option '--out' needs a value FILE, got an empty one"},
      // A value left out: the next option is not taken for it (it said "--out FILE is required").
      {"maze --out --rows 3", "option '--out' needs a value FILE, got the option '--rows'"},
      {"maze", "--out FILE is required"},
      {"maze --solver dfs --out " + dir + "/m.json", "--solver: expected wall_follower or bfs, got 'dfs'"},
      {"frobnicate", "unknown command 'frobnicate'"},
      {"maze --out /nonexistent-dir/m.json", "/nonexistent-dir/m.json: directory /nonexistent-dir does not exist"},
  };
  for (const auto& c : cases) {
    const CommandResult r = run_vascsim(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\nexpected: " << c.message << "\ngot: " << r.output;
  }
  std::filesystem::remove_all(dir);
}

TEST(CliMaze, DoesNotOverwriteWithoutForce) {
  const std::string dir = fresh_temp_dir("overwrite");
  const std::string out = dir + "/m.json";
  write_text(out, "precious");
  CommandResult r = run_vascsim("maze --out " + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find(out + ": already exists (pass --force to overwrite it)"), std::string::npos) << r.output;
  EXPECT_EQ(read_text(out), "precious");
  r = run_vascsim("maze --out " + out + " --force");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(read_text(out), "precious");
  std::filesystem::remove_all(dir);
}

// `--out -` is standard output, as for Unix tools (it wrote a file named "-"): the same bytes as
// the file, and nothing else on standard output; a file named "-" is still reachable as ./-.
TEST(CliMaze, OutDashWritesTheDocumentToStandardOutput) {
  const std::string dir = fresh_temp_dir("stdout");
  ASSERT_EQ(run_vascsim("maze --seed 7 --rows 4 --cols 5 --out " + dir + "/a.json").exit_code, 0);
  const CommandResult r = run_shell("cd " + dir + " && " + std::string(VASCSIM_EXE) +
                                    " maze --seed 7 --rows 4 --cols 5 --out - 2>/dev/null");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.output, read_text(dir + "/a.json"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/-"));
  ASSERT_EQ(run_shell("cd " + dir + " && " + std::string(VASCSIM_EXE) + " maze --seed 7 --rows 4 --cols 5 --out ./-").exit_code, 0);
  EXPECT_EQ(read_text(dir + "/-"), read_text(dir + "/a.json"));
  std::filesystem::remove_all(dir);
}

TEST(CliMaze, SameSeedSameBytesDifferentSeedDifferentMaze) {
  const std::string dir = fresh_temp_dir("determinism");
  ASSERT_EQ(run_vascsim("maze --seed 7 --rows 9 --cols 11 --out " + dir + "/a.json").exit_code, 0);
  ASSERT_EQ(run_vascsim("maze --seed 7 --rows 9 --cols 11 --out " + dir + "/b.json").exit_code, 0);
  ASSERT_EQ(run_vascsim("maze --seed 8 --rows 9 --cols 11 --out " + dir + "/c.json").exit_code, 0);
  const std::string a = read_text(dir + "/a.json");
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, read_text(dir + "/b.json"));
  EXPECT_NE(a, read_text(dir + "/c.json"));
  EXPECT_NE(a.find("\"format\": \"vascsim-maze/1\""), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vascsim::test

// vascsim and vascsim-render (apps/vascsim/renderer_program.h): vascsim loads none of the
// renderer's libraries, so a `vascsim run` started by GNU parallel or Slurm does not pay for
// them, and hands the commands that draw to vascsim-render, which it finds beside itself; without
// it those commands fail with a message that says where it looked, and the rest still work.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/cli_test_support.h"

namespace vascsim {
namespace {

namespace fs = std::filesystem;

// The shared libraries the dynamic loader maps for `exe` (what ldd prints).
std::string loaded_libraries(const std::string& exe) {
  const test::CommandResult r = test::run_shell("LD_TRACE_LOADED_OBJECTS=1 '" + exe + "'");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return r.output;
}

TEST(RenderProgram, VascsimLoadsNoRendererLibraryAndVascsimRenderDoes) {
  const std::string light = loaded_libraries(VASCSIM_EXE), heavy = loaded_libraries(VASCSIM_RENDER_EXE);
  for (const char* library : {"libOSMesa", "libavcodec", "libavformat", "libLLVM"}) {
    EXPECT_EQ(light.find(library), std::string::npos) << "vascsim loads " << library << ":\n" << light;
    EXPECT_NE(heavy.find(library), std::string::npos) << "vascsim-render does not load " << library << ":\n" << heavy;
  }
}

TEST(RenderProgram, CommandsThatDrawRunInVascsimRender) {
  const std::string dir = test::fresh_temp_dir("render_program");
  const std::string scene = test::source_path("scenes/maze_default.json");
  const test::CommandResult run = test::run_vascsim("run '" + scene + "' --duration 0.2 --out '" + dir + "/run' --quiet --render");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::is_regular_file(dir + "/run/video.mp4")) << run.output;
  const test::CommandResult still =
      test::run_vascsim("render '" + dir + "/run' --still 0.1 --png '" + dir + "/still.png'");
  ASSERT_EQ(still.exit_code, 0) << still.output;
  const test::CommandResult same = test::run_vascsim("diff '" + dir + "/still.png' '" + dir + "/still.png'");
  EXPECT_EQ(same.exit_code, 0) << same.output;
  EXPECT_NE(same.output.find("identical"), std::string::npos) << same.output;
}

TEST(RenderProgram, WithoutVascsimRenderDrawingFailsClearlyAndTheRestWorks) {
  const std::string dir = test::fresh_temp_dir("render_program_alone");
  const std::string alone = dir + "/vascsim";
  fs::copy_file(VASCSIM_EXE, alone);
  const std::string scene = test::source_path("scenes/maze_default.json");
  const test::CommandResult run = test::run_shell("'" + alone + "' run '" + scene + "' --duration 0.1 --out '" + dir + "/run' --quiet");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  for (const std::string& command : {"render '" + dir + "/run' --png '" + dir + "/f.png'", "run '" + scene +
                                        "' --duration 0.1 --out '" + dir + "/run2' --render",
                                    std::string("bench render --help")}) {
    const test::CommandResult r = test::run_shell("'" + alone + "' " + command);
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.output;
    EXPECT_NE(r.output.find(dir + "/vascsim-render"), std::string::npos) << command << "\n" << r.output;
    EXPECT_NE(r.output.find("libexec/vascsim/vascsim-render"), std::string::npos) << command << "\n" << r.output;
  }
  EXPECT_FALSE(fs::exists(dir + "/run2/video.mp4"));
}

}  // namespace
}  // namespace vascsim

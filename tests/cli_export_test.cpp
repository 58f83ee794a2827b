// `vascsim export RUN_DIR --csv DIR` through the executable: DIR created if missing, the chosen
// channels, times and decimation, one row per frame and node, the units in the header; an
// unknown channel and an existing file without --force are refused with exit 2 and nothing
// replaced or created.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/log/frame_log.h"
#include "tests/cli_test_support.h"

namespace vascsim::test {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(ExportCommand, WritesChosenChannelsTimesAndFrames) {
  const std::string dir = fresh_temp_dir("export");
  CommandResult r = run_vascsim("run " + source_path("scenes/bifurcation.json") + " --out " + dir + "/run --duration 1 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // A refused export leaves no directory behind; a good one creates it, with its parents.
  r = run_vascsim("export " + dir + "/run --csv " + dir + "/csv/sub --channels tip/speed");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/csv"));
  // A destination that is a file, or under one, is refused naming it.
  { std::ofstream(dir + "/a_file") << "x"; }
  r = run_vascsim("export " + dir + "/run --csv " + dir + "/a_file --channels tip/error");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/a_file: not a directory"), std::string::npos) << r.output;
  r = run_vascsim("export " + dir + "/run --csv " + dir + "/a_file/sub --channels tip/error");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/a_file/sub: cannot create the directory"), std::string::npos) << r.output;
  r = run_vascsim("export " + dir + "/run --csv " + dir + "/csv/sub --channels tip/error");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "/csv/sub/tip_error.csv"));
  // 0.02 s frames: 0.5..0.9 s holds 21 frames; every 5th keeps 0.5, 0.6, 0.7, 0.8, 0.9.
  r = run_vascsim("export " + dir + "/run --csv " + dir + "/csv --channels position,tip/error --from 0.5 --to 0.9 --every 5");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto position = lines_of(read_text(dir + "/csv/position.csv"));
  ASSERT_EQ(position.size(), 1u + 5u * 50u);
  EXPECT_EQ(position[0], "time [s],node,x [m],y [m]");
  EXPECT_EQ(position[1].rfind("0.5", 0), 0u) << position[1];
  EXPECT_EQ(position[1].find(",0,"), position[1].find(','));
  EXPECT_EQ(position[200].substr(0, 3), "0.8") << position[200];  // the last node of the 4th frame kept
  EXPECT_EQ(position[201].substr(0, 3), "0.9") << position[201];
  const auto error = lines_of(read_text(dir + "/csv/tip_error.csv"));
  ASSERT_EQ(error.size(), 6u);
  EXPECT_EQ(error[0], "time [s],value [m]");
  EXPECT_FALSE(std::filesystem::exists(dir + "/csv/velocity.csv")) << "a channel not asked for";

  // Existing files are kept without --force; an unknown channel names the log's channels.
  const std::string before = read_text(dir + "/csv/position.csv");
  r = run_vascsim("export " + dir + "/run --csv " + dir + "/csv --channels position");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("position.csv: already exists"), std::string::npos) << r.output;
  EXPECT_EQ(read_text(dir + "/csv/position.csv"), before);
  r = run_vascsim("export " + dir + "/run --csv " + dir + "/csv --channels tip/speed");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no channel \"tip/speed\" (the log has position, velocity"), std::string::npos) << r.output;
  r = run_vascsim("export " + dir + "/run --csv " + dir + "/csv --force");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(lines_of(read_text(dir + "/csv/position.csv")).size(), 1u + 51u * 50u);
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << "a finished run: " << r.output;

  // Asking for nothing the log holds is an error, not header-only files.
  for (const std::string& options : {std::string("--from 5 --to 6"), std::string("--channels ''"),
                                     std::string("--channels tip/error,tip/error"), std::string("--to 1 --to 2")}) {
    r = run_vascsim("export " + dir + "/run --csv " + dir + "/csv --force " + options);
    EXPECT_EQ(r.exit_code, 2) << options << ": " << r.output;
  }
  EXPECT_NE(run_vascsim("export " + dir + "/run --csv " + dir + "/csv --force --from 5 --to 6")
                .output.find("no frame in the time range [5, 6] s (the log spans 0 .. 1 s)"),
            std::string::npos);

  // A run without its summary, which no run is writing (killed, or copied without it), exports
  // what it has, with a warning (one still being written: tests/cli_run_test.cpp).
  std::filesystem::remove(dir + "/run/summary.json");
  r = run_vascsim("export " + dir + "/run --csv " + dir + "/csv --force");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("/run has no summary.json: no run is writing it (the directory was copied without it, or its run was killed)"),
            std::string::npos)
      << r.output;
  std::filesystem::remove_all(dir);
}

// A log from another tool may hold channels "a/b" and "a_b", both a_b.csv: refused before any
// file is written (one was written, then the other refused as "already exists").
TEST(ExportCommand, ChannelsSharingAFileNameAreRefusedBeforeWriting) {
  const std::string dir = fresh_temp_dir("export_same_name");
  std::filesystem::create_directories(dir + "/csv");
  FrameLogHeader header;
  header.node_count = 2;
  header.channels = {{"position", "m", ChannelLayout::kNodeVectors, 4},
                     {"probe/pressure", "Pa", ChannelLayout::kScalars, 1},
                     {"probe_pressure", "Pa", ChannelLayout::kScalars, 1}};
  header.metadata = "{}";
  {
    FrameLogWriter log(dir + "/other.vlog", header);
    log.append(0.0, {0, 0, 1, 0, 5, 6});
    log.close();
  }
  CommandResult r = run_vascsim("export " + dir + "/other.vlog --csv " + dir + "/csv");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("channels \"probe/pressure\" and \"probe_pressure\" would both be written to probe_pressure.csv"),
            std::string::npos)
      << r.output;
  EXPECT_TRUE(std::filesystem::is_empty(dir + "/csv"));
  r = run_vascsim("export " + dir + "/other.vlog --csv " + dir + "/csv --channels position,probe_pressure");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_text(dir + "/csv/probe_pressure.csv"), "time [s],value [Pa]\n0,6\n");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vascsim::test

// Frame log round trip, seeking, and recovery of a log whose writer was killed mid-record.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "sim/log/frame_log.h"
#include "sim/scene/input_error.h"

namespace vascsim {
namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("vascsim_" + name + "_" + std::to_string(::getpid()))).string();
}

FrameLogHeader two_node_header() {
  FrameLogHeader h;
  h.node_count = 2;
  h.channels = {{"position", "m", ChannelLayout::kNodeVectors, 4}, {"tip/error", "m", ChannelLayout::kScalars, 1}};
  h.metadata = "{\"title\":\"t\"}";
  return h;
}

TEST(FrameLog, RoundTripsHeaderAndFrames) {
  const std::string path = temp_path("roundtrip.vlog");
  {
    FrameLogWriter w(path, two_node_header());
    for (int i = 0; i < 10; ++i) w.append(0.1 * i, {1.0 * i, 2.0, 3.0, 4.0 + i, -1.0 * i});
    w.close();
  }
  FrameLogReader r(path);
  EXPECT_EQ(r.header().node_count, 2u);
  ASSERT_EQ(r.header().channels.size(), 2u);
  EXPECT_EQ(r.header().channels[1].name, "tip/error");
  EXPECT_EQ(r.header().metadata, "{\"title\":\"t\"}");
  EXPECT_EQ(r.header().channel_offset(r.header().find_channel("tip/error")), 5u);
  ASSERT_EQ(r.frame_count(), 10u);
  std::vector<double> rec;
  r.read(7, rec);
  EXPECT_EQ(rec, (std::vector<double>{0.1 * 7, 7.0, 2.0, 3.0, 11.0, -7.0}));
  EXPECT_EQ(r.frame_at_time(0.45), 4u);
  EXPECT_EQ(r.frame_at_time(-1.0), 0u);
  EXPECT_EQ(r.frame_at_time(100.0), 9u);
  std::remove(path.c_str());
}

TEST(FrameLog, TornLastRecordIsIgnored) {
  const std::string path = temp_path("torn.vlog");
  {
    FrameLogWriter w(path, two_node_header());
    for (int i = 0; i < 3; ++i) w.append(i, {0, 0, 0, 0, 0});
  }
  // Simulate a kill in the middle of a write: half a record at the end.
  { std::ofstream f(path, std::ios::binary | std::ios::app); f.write("garbage-", 8); }
  FrameLogReader r(path);
  EXPECT_EQ(r.frame_count(), 3u);
  std::remove(path.c_str());
}

TEST(FrameLog, RejectsMissingAndForeignFiles) {
  EXPECT_THROW(FrameLogReader("/nonexistent/dir/x.vlog"), InputError);
  const std::string path = temp_path("foreign.vlog");
  { std::ofstream f(path); f << "hello, not a log"; }
  try {
    FrameLogReader r(path);
    FAIL() << "accepted a foreign file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  { std::ofstream f(path, std::ios::binary); f.write("VSIMLOG\0\1\0\0\0", 12); }
  EXPECT_THROW(FrameLogReader{path}, InputError);  // truncated header
  std::remove(path.c_str());
}

}  // namespace
}  // namespace vascsim

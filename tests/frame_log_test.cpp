// Frame log round trip, seeking, and recovery of a log whose writer was killed mid-record.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <future>

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

std::size_t open_descriptors() {
  std::size_t n = 0;
  for (const auto& e : std::filesystem::directory_iterator("/proc/self/fd")) n += !e.path().empty();
  return n;
}

// A reader refusing a file, or a writer failing on its header, must close what it opened: the
// frame-log fuzz harness ran out of file descriptors after some 50000 refused logs (a replay
// server or a sweep opening many logs would too).
TEST(FrameLog, RefusedLogsAndFailedWritersCloseTheirFile) {
  const std::string bad = temp_path("not_a_log.vlog"), cut = temp_path("cut_header.vlog");
  std::ofstream(bad, std::ios::binary) << "not a frame log at all";
  std::ofstream(cut, std::ios::binary) << std::string("VSIMLOG\0\1\0\0\0", 12);
  const std::size_t before = open_descriptors();
  int refused = 0;
  for (int k = 0; k < 20; ++k) {
    for (const std::string& path : {bad, cut}) {
      try {
        FrameLogReader reader(path);
      } catch (const InputError&) {
        ++refused;
      }
    }
    try {
      FrameLogWriter writer("/dev/full", two_node_header());  // the header's write fails: ENOSPC
    } catch (const InputError&) {
      ++refused;
    }
  }
  EXPECT_EQ(refused, 60);
  EXPECT_EQ(open_descriptors(), before);
  std::remove(bad.c_str());
  std::remove(cut.c_str());
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
  // A log of a newer format (3D rods, say) is not called corrupt: the reader says it is newer.
  { std::ofstream f(path, std::ios::binary); f.write("VSIMLOG\0\2\0\0\0\0\0\0\0\0\0\0\0", 20); }
  try {
    FrameLogReader r(path);
    FAIL() << "read a version 2 log";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(": frame log format version 2, written by a newer vascsim; this build reads "
                                         "version 1 (update vascsim to read it)"),
              std::string::npos)
        << e.what();
  }
  std::remove(path.c_str());
}

// A pipe named like a log hung `export` and `render` (fopen waits for a writer) and a directory
// was reported as a "truncated frame log header": both are refused up front, naming what they are.
TEST(FrameLog, RefusesPipesAndDirectoriesWithoutWaiting) {
  const std::string dir = temp_path("not_a_log");
  std::filesystem::create_directories(dir);
  try {
    FrameLogReader r(dir);
    FAIL() << "accepted a directory";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), dir + ": is a directory, not a frame log");
  }
  const std::string fifo = dir + "/frames.vlog";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto opened = std::async(std::launch::async, [&]() -> std::string {
    try {
      FrameLogReader r(fifo);
      return "accepted a pipe";
    } catch (const InputError& e) {
      return e.what();
    }
  });
  if (opened.wait_for(std::chrono::seconds(10)) != std::future_status::ready) {
    // Unblock the reader so the test ends and reports instead of hanging.
    std::FILE* writer = std::fopen(fifo.c_str(), "wb");
    if (writer) std::fclose(writer);
    ADD_FAILURE() << "the reader waited on a pipe";
  }
  EXPECT_EQ(opened.get(), fifo + ": not a regular file (a frame log is read from a file, not a device or a pipe)");
  std::filesystem::remove_all(dir);
}

// Metadata is bounded (kMaxMetadataBytes, 32 MB): the writer refuses to make a log its readers
// would refuse, and a reader refuses a header that claims more, before allocating it (a 10^6-point
// path once made `vascsim render` use over 3 GB; a corrupt length, 1 GB at once).
TEST(FrameLog, MetadataIsBoundedOnWriteAndOnRead) {
  FrameLogHeader h;
  h.node_count = 2;
  h.channels = {{"position", "m", ChannelLayout::kNodeVectors, 4}};
  h.metadata = std::string(kMaxMetadataBytes + 1, ' ');
  const std::string path = temp_path("big_meta.vlog");
  try {
    FrameLogWriter w(path, h);
    ADD_FAILURE() << "wrote metadata over the limit";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("32 MiB"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path)) << "a refused log must not appear";
  // A header whose metadata length says 1 GB: patch a small valid log's length field.
  h.metadata = "{}";
  { FrameLogWriter w(path, h); }
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::size_t length_at = 20 + 4 + 8 + 4 + 1 + 1 + 4;  // after the channel "position", unit "m", layout, count
  ASSERT_EQ(bytes.compare(length_at + 4, 2, "{}"), 0) << "the test's idea of the header layout is wrong";
  const std::uint32_t claimed = 1u << 30;
  std::memcpy(&bytes[length_at], &claimed, 4);
  { std::ofstream out(path, std::ios::binary); out << bytes; }
  try {
    FrameLogReader r(path);
    ADD_FAILURE() << "accepted a 1 GB metadata length";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("exceeds the 32 MiB limit"), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace vascsim

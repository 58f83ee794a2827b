// A frame log whose channels do not hold what their layout says (a hand-made or corrupt log) is
// refused on open with a message naming the log and the channel, before any reader can run past
// a record's values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include "render/frame_source.h"
#include "render_test_util.h"
#include "sim/io/log_metadata.h"
#include "sim/log/frame_log.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;

// Writes a valid log of `channels` (counts as their layouts need), then overwrites channel
// `bad`'s count in the header with `bad_count`: the writer itself refuses such a header.
void write_log(const std::string& path, std::uint32_t nodes, std::vector<LogChannel> channels, std::size_t bad,
               std::uint32_t bad_count) {
  FrameLogHeader h;
  h.node_count = nodes;
  for (auto& c : channels) c.count = c.layout == ChannelLayout::kNodeVectors ? 2 * nodes : c.layout == ChannelLayout::kVector ? 2 : 1;
  h.channels = channels;
  h.metadata = write_log_metadata(synthetic_metadata(SyntheticLogSpec{}));
  {
    FrameLogWriter w(path, h);
    w.append(0.0, std::vector<double>(h.record_doubles() - 1, 0.0));
  }
  std::string bytes = testing::read_bytes(path);
  std::size_t at = 20;  // docs/frame-log.md: channel records start after magic, version, N, C
  for (std::size_t i = 0;; ++i) {
    at += 4 + channels[i].name.size();
    at += 4 + channels[i].unit.size() + 1;  // unit, layout
    if (i == bad) break;
    at += 4;
  }
  std::memcpy(&bytes[at], &bad_count, 4);
  std::ofstream(path, std::ios::binary) << bytes;
}

TEST(FrameSourceChannels, ACountThatContradictsTheLayoutIsRefusedNamingTheChannel) {
  ScratchDir dir("source_channels");
  const std::string path = dir / "bad.vlog";
  const std::vector<LogChannel> channels = {{"position", "m", ChannelLayout::kNodeVectors, 0},
                                            {"force/contact", "N", ChannelLayout::kNodeVectors, 0},
                                            {"tip/reference", "m", ChannelLayout::kVector, 0},
                                            {"tip/error", "m", ChannelLayout::kScalars, 0}};
  const struct {
    std::size_t channel;
    std::uint32_t count;
    std::string named;
  } cases[] = {{0, 0, "position"}, {1, 2, "force/contact"}, {2, 0, "tip/reference"}, {3, 0, "tip/error"}};
  for (const auto& c : cases) {
    write_log(path, 50, channels, c.channel, c.count);
    try {
      FrameSource source(path);
      ADD_FAILURE() << "accepted a log whose '" << c.named << "' channel contradicts its layout";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.named), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
  write_log(path, 50, channels, 3, 1);  // the count it should have
  EXPECT_NO_THROW(FrameSource{path});
}

}  // namespace
}  // namespace vascsim::render

namespace vascsim::render {
namespace {

using testing::ScratchDir;
namespace fs = std::filesystem;

// A 3-node log whose frame k has time times[k].
std::string log_with_times(const ScratchDir& dir, const std::string& name, const std::vector<double>& times) {
  const std::string path = dir / name;
  FrameLogHeader h;
  h.node_count = 3;
  h.channels = {{"position", "m", ChannelLayout::kNodeVectors, 6}};
  h.metadata = write_log_metadata(synthetic_metadata(SyntheticLogSpec{}));
  FrameLogWriter w(path, h);
  for (std::size_t k = 0; k < times.size(); ++k) w.append(times[k], {0.0, 0.0, 0.01, 0.0, 0.02, 0.001 * k});
  return path;
}

// Times must be finite, >= 0 and non-decreasing: a NaN, a negative or a decreasing time once made
// `vascsim render` compute a huge or NaN frame count and write PNGs until the disk was full.
TEST(FrameSourceTimes, BadFirstOrLastTimesAreRefusedOnOpen) {
  ScratchDir dir("source_times");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const struct {
    std::vector<double> times;
    std::string frame;
  } cases[] = {{{nan, 0.1, 0.2}, "frame 0"}, {{0.0, 0.1, nan}, "frame 2"}, {{-1e10, 0.1, 0.2}, "frame 0"},
               {{0.5, 0.6, 0.2}, "frame 2"}, {{0.0, 0.1, INFINITY}, "frame 2"}};
  for (const auto& c : cases) {
    const std::string log = log_with_times(dir, "bad.vlog", c.times);
    try {
      FrameSource source(log);
      ADD_FAILURE() << "accepted times " << c.times[0] << ", " << c.times[1] << ", " << c.times[2];
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.frame), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(log), std::string::npos) << e.what();
    }
  }
}

TEST(FrameSourceTimes, RenderStopsAtTheFirstBadFrameAndRefusesHugeRanges) {
  ScratchDir dir("render_times");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // A NaN or a step back in the middle passes the open checks and stops the render where read.
  for (const double bad : {nan, 0.15}) {
    const std::string log = log_with_times(dir, "middle.vlog", {0.0, 0.1, 0.2, bad, 0.4, 0.5});
    fs::remove_all(dir / "png");
    auto r = testing::run_vascsim("render '" + log + "' --png-dir '" + (dir / "png") + "' --fps 10 --width 64 --height 64", dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("frame 3"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "png/frame_000005.png")) << "it rendered past the bad frame";
  }
  // Finite but absurd: 0 .. 1e9 s at 30 fps would be 3e10 frames.
  const std::string far = log_with_times(dir, "far.vlog", {0.0, 1e9});
  auto r = testing::run_vascsim("render '" + far + "' --png-dir '" + (dir / "far") + "' --width 64 --height 64", dir);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--speed"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "far/frame_000000.png"));
}

}  // namespace
}  // namespace vascsim::render

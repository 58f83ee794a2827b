// A frame log whose channels do not hold what their layout says (a hand-made or corrupt log) is
// refused on open with a message naming the log and the channel, before any reader can run past
// a record's values.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

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

// MP4 output read back with libavformat (codec, pixel format, frame count, duration, index at
// the front), and determinism: the same log and options give identical MP4 and PNG bytes.
#include <gtest/gtest.h>

#include <cstring>

#include "render/png_writer.h"
#include "render/render_run.h"
#include "render/video_encoder.h"
#include "render_test_util.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;
namespace fs = std::filesystem;

RenderOptions small_video(const ScratchDir& dir, const std::string& name) {
  RenderOptions o;
  o.mp4_path = dir / name;
  o.view.width = 160;
  o.view.height = 120;
  o.fps = 10;
  o.to = 1.1;  // 0.0, 0.1, ..., 1.1 s: 12 frames
  return o;
}

// Names of the top-level MP4 boxes in file order.
std::vector<std::string> top_level_boxes(const std::string& bytes) {
  std::vector<std::string> names;
  std::size_t at = 0;
  while (at + 8 <= bytes.size()) {
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + at);
    std::uint64_t size = (std::uint64_t(b[0]) << 24) | (b[1] << 16) | (b[2] << 8) | b[3];
    names.emplace_back(bytes.data() + at + 4, 4);
    if (size == 1 && at + 16 <= bytes.size()) {
      size = 0;
      for (int k = 0; k < 8; ++k) size = (size << 8) | static_cast<unsigned char>(bytes[at + 8 + k]);
    }
    if (size < 8) break;
    at += size;
  }
  return names;
}

TEST(RenderVideo, Mp4HasH264Yuv420pAndExactDuration) {
  ScratchDir dir("video_probe");
  SyntheticLogSpec spec;
  spec.duration = 2.0;
  const std::string run = testing::make_run(dir, spec);
  const RenderReport r = render_run(run, small_video(dir, "a.mp4"));
  ASSERT_EQ(r.frames, 12u);
  ASSERT_EQ(r.video_codec, "h264") << "libx264 missing? " << r.note;
  const VideoInfo info = probe_video(r.video_path);
  EXPECT_EQ(info.codec, "h264");
  EXPECT_EQ(info.pixel_format, "yuv420p");
  EXPECT_EQ(info.width, 160);
  EXPECT_EQ(info.height, 120);
  EXPECT_EQ(info.frames, 12);
  EXPECT_NEAR(info.duration, 12 / 10.0, 1e-9);  // frames / fps exactly
  EXPECT_NEAR(info.fps, 10.0, 1e-9);
  // faststart: the index (moov) precedes the media data (mdat) so browsers can stream.
  const auto boxes = top_level_boxes(testing::read_bytes(r.video_path));
  const auto moov = std::find(boxes.begin(), boxes.end(), "moov"), mdat = std::find(boxes.begin(), boxes.end(), "mdat");
  ASSERT_NE(moov, boxes.end());
  ASSERT_NE(mdat, boxes.end());
  EXPECT_LT(moov - boxes.begin(), mdat - boxes.begin());
  // Nothing left beside it under a temporary name (hidden: .a.mp4.tmp-HOST-PID).
  for (const auto& e : fs::directory_iterator(dir.path()))
    EXPECT_NE(e.path().filename().string().rfind(".a.mp4", 0), 0u) << e.path();
}

TEST(RenderVideo, SameLogGivesIdenticalMp4AndPngBytes) {
  ScratchDir dir("video_determinism");
  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  RenderOptions a = small_video(dir, "a.mp4"), b = small_video(dir, "b.mp4");
  a.png_dir = dir / "png_a";
  b.png_dir = dir / "png_b";
  a.to = b.to = 0.4;
  render_run(run, a);
  render_run(run, b);
  const std::string va = testing::read_bytes(a.mp4_path), vb = testing::read_bytes(b.mp4_path);
  ASSERT_GT(va.size(), 1000u);
  EXPECT_TRUE(va == vb) << "MP4 bytes differ between two identical renders";
  for (std::size_t i = 0; i < 5; ++i) {
    const std::string pa = testing::read_bytes(png_frame_path(a.png_dir, i));
    ASSERT_FALSE(pa.empty());
    EXPECT_TRUE(pa == testing::read_bytes(png_frame_path(b.png_dir, i))) << "PNG frame " << i << " differs";
  }
  // And the frames do change over time (the test could fail).
  EXPECT_FALSE(testing::read_bytes(png_frame_path(a.png_dir, 0)) == testing::read_bytes(png_frame_path(a.png_dir, 4)));
}

}  // namespace
}  // namespace vascsim::render

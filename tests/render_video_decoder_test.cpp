// Frames decoded from a rendered MP4 (render/video_decoder.h) against the PNGs the renderer
// wrote for the same times in the same render: equal up to H.264 and 4:2:0 chroma loss, and
// clearly unequal for other times. Also the decoder's errors and the mp4_frame tool.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <functional>
#include <memory>

#include "render/png_writer.h"
#include "render/render_run.h"
#include "render/video_decoder.h"
#include "render_test_util.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;
namespace fs = std::filesystem;

// Bounds for a decoded frame against its own PNG, from measurements of this 320x240 render
// (SWS bicubic chroma interpolation): mean 1.56..1.71 levels per channel, PSNR 33.2..34.5 dB.
// Most of the loss is yuv420p's half-resolution chroma on thin coloured lines (a round trip
// through yuv420p without H.264 alone gives mean 1.40), so the maximum is large (~135) and
// not bounded. The same frame against the last PNG measured mean 5.0..5.3, PSNR ~20 dB.
constexpr double kMaxMeanDifference = 2.5;  // levels of 255
constexpr double kMinPsnr = 30.0;           // dB

// 21 frames (0.0, 0.1, ..., 2.0 s) of a synthetic maze at 320x240, as MP4 and PNGs from one
// render, so both outputs saw exactly the same RGBA frames. The rod moves 3x the default
// speed so neighbouring frames differ clearly (~18 px per frame).
constexpr long long kFrames = 21;
class RenderVideoDecoder : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = std::make_unique<ScratchDir>("video_decoder");
    SyntheticLogSpec spec;
    spec.duration = 2.0;
    spec.frames = 21;
    spec.speed = 0.06;
    const std::string run = testing::make_run(*dir_, spec);
    RenderOptions o;
    o.mp4_path = *dir_ / "video.mp4";
    o.png_dir = *dir_ / "png";
    o.view.width = 320;
    o.view.height = 240;
    o.fps = 10;
    const RenderReport r = render_run(run, o);
    ASSERT_EQ(r.frames, static_cast<std::size_t>(kFrames));
    ASSERT_EQ(r.video_codec, "h264") << "libx264 missing? " << r.note;
    mp4_ = r.video_path;
    png_dir_ = o.png_dir;
  }
  static void TearDownTestSuite() { dir_.reset(); }

  static Image png(long long k) { return load_png(png_frame_path(png_dir_, static_cast<std::size_t>(k))); }

  static std::unique_ptr<ScratchDir> dir_;
  static std::string mp4_, png_dir_;
};
std::unique_ptr<ScratchDir> RenderVideoDecoder::dir_;
std::string RenderVideoDecoder::mp4_, RenderVideoDecoder::png_dir_;

std::string describe(const DiffStats& s) {
  return "mean " + std::to_string(s.mean_difference) + ", max " + std::to_string(s.max_difference) + ", PSNR " +
         std::to_string(s.psnr_db) + " dB";
}

// The InputError's message, or a failure if `f` throws none.
std::string input_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return "";
}

TEST_F(RenderVideoDecoder, FirstAndLastFramesMatchTheirPngsWithinH264Loss) {
  const Image first = decode_video_frame(mp4_, 0), last = decode_video_frame(mp4_, kFrames - 1);
  ASSERT_EQ(first.width, 320);
  ASSERT_EQ(first.height, 240);
  ASSERT_EQ(first.rgb.size(), 320u * 240 * 3);
  const Image first_png = png(0), last_png = png(kFrames - 1);
  for (const auto& [name, s] : {std::pair{"frame 0", diff_images(first, first_png, 24, nullptr)},
                                {"last frame", diff_images(last, last_png, 24, nullptr)}}) {
    EXPECT_LT(s.mean_difference, kMaxMeanDifference) << name << ": " << describe(s);
    EXPECT_GT(s.psnr_db, kMinPsnr) << name << ": " << describe(s);
  }
  // The comparison can fail: a frame against another time's PNG is far outside the bounds.
  for (const auto& [name, s] : {std::pair{"frame 0 vs last PNG", diff_images(first, last_png, 24, nullptr)},
                                {"last frame vs PNG 0", diff_images(last, first_png, 24, nullptr)}}) {
    EXPECT_GT(s.mean_difference, 1.5 * kMaxMeanDifference) << name << ": " << describe(s);
    EXPECT_LT(s.psnr_db, kMinPsnr - 5) << name << ": " << describe(s);
  }
}

TEST_F(RenderVideoDecoder, IndexIsExactNotOffByOne) {
  // Frame 10 is much closer to PNG 10 than to its neighbours' PNGs 9 and 11. PSNR separates
  // them better than the mean here: measured 34.0 dB against PNG 10, 24.9 dB against 9 and 11
  // (mean 1.65 against 2.84 and 2.87).
  const Image middle = decode_video_frame(mp4_, 10);
  const DiffStats own = diff_images(middle, png(10), 24, nullptr);
  EXPECT_LT(own.mean_difference, kMaxMeanDifference) << describe(own);
  EXPECT_GT(own.psnr_db, kMinPsnr) << describe(own);
  for (const long long k : {9, 11}) {
    const DiffStats other = diff_images(middle, png(k), 24, nullptr);
    EXPECT_LT(other.psnr_db, own.psnr_db - 5) << "PNG " << k << ": " << describe(other);
  }
}

TEST_F(RenderVideoDecoder, IndexPastTheEndSaysHowManyFramesThereAre) {
  for (const long long k : {kFrames, 1000000000000LL}) {
    const std::string m = input_error_of([&] { decode_video_frame(mp4_, k); });
    EXPECT_NE(m.find(mp4_), std::string::npos) << m;
    EXPECT_NE(m.find("no frame " + std::to_string(k)), std::string::npos) << m;
    EXPECT_NE(m.find("has 21 frames (0..20)"), std::string::npos) << m;
  }
  const std::string negative = input_error_of([&] { decode_video_frame(mp4_, -1); });
  EXPECT_NE(negative.find(">= 0, got -1"), std::string::npos) << negative;
}

TEST_F(RenderVideoDecoder, MissingFileAndNoVideoStreamNameTheFile) {
  const std::string missing = *dir_ / "missing.mp4";
  const std::string m = input_error_of([&] { decode_video_frame(missing, 0); });
  EXPECT_NE(m.find(missing + ": cannot open video"), std::string::npos) << m;

  // A valid WAV file (16-bit mono PCM, 0.1 s of silence): opens, but holds only audio.
  const std::string wav = *dir_ / "audio.wav";
  {
    std::ofstream out(wav, std::ios::binary);
    const auto u32 = [&](std::uint32_t v) { for (int i = 0; i < 4; ++i) out.put(static_cast<char>(v >> (8 * i))); };
    const auto u16 = [&](std::uint16_t v) { for (int i = 0; i < 2; ++i) out.put(static_cast<char>(v >> (8 * i))); };
    const std::uint32_t data_bytes = 1600;
    out << "RIFF";
    u32(36 + data_bytes);
    out << "WAVEfmt ";
    u32(16);
    u16(1);       // PCM
    u16(1);       // channels
    u32(8000);    // samples per second
    u32(16000);   // bytes per second
    u16(2);       // bytes per sample frame
    u16(16);      // bits per sample
    out << "data";
    u32(data_bytes);
    out << std::string(data_bytes, '\0');
  }
  const std::string a = input_error_of([&] { decode_video_frame(wav, 0); });
  EXPECT_NE(a.find(wav + ": no video stream"), std::string::npos) << a;
}

TEST_F(RenderVideoDecoder, Mp4FrameToolWritesThePngAndNeverOverwrites) {
  const std::string out = *dir_ / "f10.png";
  const auto quoted = [](const std::string& s) { return "'" + s + "'"; };
  const testing::CommandResult ok = testing::run_program(MP4_FRAME_EXE, quoted(mp4_) + " 10 " + quoted(out), *dir_);
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const DiffStats s = diff_images(load_png(out), decode_video_frame(mp4_, 10), 0, nullptr);
  EXPECT_EQ(s.max_difference, 0) << "the PNG holds exactly the decoded frame";

  // An existing file (the tool's own output, or anything a user wrote) stays as it was.
  const std::string mine = *dir_ / "mine.png";
  std::ofstream(mine) << "my notes";
  for (const std::string& target : {out, mine}) {
    const std::string before = testing::read_bytes(target);
    const testing::CommandResult again = testing::run_program(MP4_FRAME_EXE, quoted(mp4_) + " 3 " + quoted(target), *dir_);
    EXPECT_EQ(again.exit_code, 2) << target;
    EXPECT_NE(again.err.find(target + ": already exists"), std::string::npos) << again.err;
    EXPECT_EQ(testing::read_bytes(target), before) << target;
  }

  const std::string past = *dir_ / "f21.png";
  const testing::CommandResult end = testing::run_program(MP4_FRAME_EXE, quoted(mp4_) + " 21 " + quoted(past), *dir_);
  EXPECT_EQ(end.exit_code, 2);
  EXPECT_NE(end.err.find("has 21 frames"), std::string::npos) << end.err;
  EXPECT_FALSE(fs::exists(past));

  for (const std::string bad : {"1x", "-1", "''"}) {
    const testing::CommandResult r = testing::run_program(MP4_FRAME_EXE, quoted(mp4_) + " " + bad + " " + quoted(past), *dir_);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find("INDEX: expected a whole number"), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace vascsim::render

// io::read_at_most (sim/io/bounded_read.h), the chunked read behind the scene and sweep files'
// size caps: a file at the cap is read whole, one past it is told apart, a huge one costs the cap
// and one byte, not its size; and the readers that use it still refuse an oversized file by name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "sim/io/bounded_read.h"
#include "sim/io/png_file.h"
#include "sim/io/scene_reader.h"
#include "sim/io/sweep_manifest.h"
#include "sim/io/sweep_spec.h"
#include "sim/scene/input_error.h"
#include "tests/cli_test_support.h"

namespace vascsim {
namespace {

std::string bytes(std::size_t n) {
  std::string s(n, ' ');
  for (std::size_t i = 0; i < n; ++i) s[i] = static_cast<char>('a' + i % 26);
  return s;
}

TEST(BoundedRead, ReadsUpToOnePastTheLimitAcrossChunks) {
  const std::size_t chunk = 1 << 16;  // read_at_most's chunk: sizes on both sides of it
  for (const std::size_t limit : {std::size_t(0), std::size_t(10), chunk - 1, chunk, chunk + 1, 3 * chunk + 5}) {
    for (const std::size_t size : {std::size_t(0), limit, limit + 1, limit + 2, 2 * limit + chunk + 3}) {
      const std::string content = bytes(size);
      std::istringstream in(content);
      const std::string got = io::read_at_most(in, limit);
      EXPECT_EQ(got, content.substr(0, limit + 1)) << "limit " << limit << ", size " << size;
      EXPECT_FALSE(in.bad());
    }
  }
}

std::string error_reading(const std::string& path, bool sweep) {
  try {
    if (sweep) read_sweep_file(path);
    else read_scene_file(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(BoundedRead, OversizedSceneAndSweepFilesAreRefusedByName) {
  const std::string dir = test::fresh_temp_dir("bounded_read");
  for (const bool sweep : {false, true}) {
    const std::size_t limit = sweep ? kMaxSweepFileBytes : kMaxSceneBytes;
    const std::string path = dir + (sweep ? "/big_sweep.json" : "/big_scene.json");
    // Valid JSON padded with spaces to one byte past the cap: refused for its size, not parsed.
    std::ofstream(path, std::ios::binary) << "{}" << std::string(limit - 1, ' ');
    const std::string message = error_reading(path, sweep);
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find("larger than " + std::to_string(limit >> 20) + " MiB"), std::string::npos) << message;
    // At the cap it is read (and then judged on its content).
    std::ofstream(path, std::ios::binary | std::ios::trunc) << "{}" << std::string(limit - 2, ' ');
    EXPECT_EQ(error_reading(path, sweep).find("larger than"), std::string::npos);
  }
}

// The PNG reader (vessel masks, goldens) and the sweep manifest reader, whose caps are large,
// refuse a file by its size before reading it: a (sparse) file one byte past the cap is refused
// by name, at once.
TEST(BoundedRead, OversizedPngAndManifestAreRefusedByName) {
  const std::string dir = test::fresh_temp_dir("bounded_read_big");
  const std::string png = dir + "/big.png", manifest = dir + "/manifest.json";
  std::ofstream(png, std::ios::binary).close();
  std::filesystem::resize_file(png, io::kMaxPngBytes + 1);
  std::ofstream(manifest, std::ios::binary).close();
  std::filesystem::resize_file(manifest, kMaxManifestBytes + 1);
  auto message_of = [](const std::function<void()>& read) -> std::string {
    try {
      read();
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  const std::string png_error = message_of([&] { io::read_png(png, 1); });
  EXPECT_NE(png_error.find(png + ": cannot read PNG (larger than 256 MiB)"), std::string::npos) << png_error;
  const std::string manifest_error = message_of([&] { read_sweep_manifest(manifest); });
  EXPECT_NE(manifest_error.find(manifest + ": larger than 256 MiB"), std::string::npos) << manifest_error;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vascsim

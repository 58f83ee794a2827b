// Reading mask images (sim/io/png_file.h): load_grey_png gives the grey levels row by row from the
// top, converts colour to grey, and refuses an image over the side limit (from its header, before
// decoding) or a file that is not a PNG, naming the file. The PNGs are written here byte by byte
// (stored, uncompressed deflate blocks), so the test needs no encoder.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "sim/io/png_file.h"
#include "sim/scene/input_error.h"
#include "tests/cli_test_support.h"
#include "tests/png_bytes_support.h"

namespace vascsim::io {
namespace {

using test::png_bytes;


std::string write_png(const std::string& dir, const std::string& name, int width, int height, int colour_type,
                      const std::vector<std::uint8_t>& pixels) {
  const std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary) << png_bytes(width, height, colour_type, pixels);
  return path;
}

std::string refusal(const std::string& path, int max_side = kMaxMaskSide) {
  try {
    load_grey_png(path, max_side);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(VesselMaskPng, ReadsGreyRowsFromTheTopAndColourAsLuminance) {
  const std::string dir = test::fresh_temp_dir("vessel_mask_png_read");
  const GreyImage g = load_grey_png(write_png(dir, "grey.png", 3, 2, 0, {0, 10, 20, 200, 230, 255}));
  EXPECT_EQ(g.width, 3);
  EXPECT_EQ(g.height, 2);
  EXPECT_EQ(g.grey, (std::vector<std::uint8_t>{0, 10, 20, 200, 230, 255}));
  const GreyImage c = load_grey_png(write_png(dir, "rgb.png", 2, 1, 2, {255, 255, 255, 0, 0, 0}));
  EXPECT_EQ(c.grey, (std::vector<std::uint8_t>{255, 0}));
  // Alpha composited over black: transparent white is background, not lumen.
  const GreyImage a = load_grey_png(write_png(dir, "grey_alpha.png", 3, 1, 4, {255, 255, 255, 0, 128, 128}));
  EXPECT_EQ(a.grey, (std::vector<std::uint8_t>{255, 0, 64}));
  const GreyImage rgba = load_grey_png(write_png(dir, "rgba.png", 2, 1, 6, {255, 255, 255, 0, 255, 255, 255, 255}));
  EXPECT_EQ(rgba.grey, (std::vector<std::uint8_t>{0, 255}));
}

TEST(VesselMaskPng, RefusesAnImageOverTheSizeLimit) {
  const std::string dir = test::fresh_temp_dir("vessel_mask_png_size");
  const std::string small = write_png(dir, "small.png", 20, 9, 0, std::vector<std::uint8_t>(20 * 9, 255));
  std::string msg = refusal(small, 16);
  EXPECT_EQ(msg.rfind(small + ": ", 0), 0u) << msg;
  EXPECT_NE(msg.find("20 x 9 px, larger than 16 px a side"), std::string::npos) << msg;
  EXPECT_EQ(refusal(small, 20), "(no error)");
  // The default limit, kMaxMaskSide = 8192 px, with one pixel more.
  const std::string tall = write_png(dir, "tall.png", 1, kMaxMaskSide + 1, 0, std::vector<std::uint8_t>(kMaxMaskSide + 1, 0));
  msg = refusal(tall);
  EXPECT_EQ(msg.rfind(tall + ": ", 0), 0u) << msg;
  EXPECT_NE(msg.find("1 x 8193 px, larger than 8192 px a side"), std::string::npos) << msg;
}

// A PNG of no pixels, or claiming more than kMaxPngPixels, is refused saying so (stb_image
// refused both as "unknown image type"); read with no side limit, as `vascsim diff` reads.
TEST(VesselMaskPng, AnEmptyOrHugeImageIsRefusedBySize) {
  const std::string empty = png_bytes(0, 0, 0, {});
  std::string huge = png_bytes(1, 1, 0, {0});
  for (const int at : {16, 20}) {  // IHDR's width and height, big-endian: 100000 px each
    for (int k = 0; k < 4; ++k) huge[at + k] = static_cast<char>((100000u >> (24 - 8 * k)) & 0xFF);
  }
  const std::uint32_t crc = test::crc32_of(huge.substr(12, 17));  // IHDR's type and data
  for (int k = 0; k < 4; ++k) huge[29 + k] = static_cast<char>((crc >> (24 - 8 * k)) & 0xFF);
  const std::pair<std::string, std::string> cases[] = {
      {empty, "empty.png: the image is 0 x 0 px: no pixel"},
      {huge, "huge.png: the image is 100000 x 100000 px: more than the 268435456 px read"}};
  for (const auto& [bytes, expected] : cases) {
    try {
      decode_png(bytes, expected.substr(0, expected.find(':')), 4);
      ADD_FAILURE() << "accepted " << expected;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), expected);
    }
  }
}

TEST(VesselMaskPng, RefusesMissingAndNonPngFilesNamingThem) {
  const std::string dir = test::fresh_temp_dir("vessel_mask_png_bad");
  test::write_text(dir + "/mask.png", "P2 2 2 255 0 0 0 0\n");  // a PGM, not a PNG
  std::string msg = refusal(dir + "/mask.png");
  EXPECT_EQ(msg, dir + "/mask.png: not a PNG file (no PNG signature)");
  msg = refusal(dir + "/missing.png");
  EXPECT_EQ(msg, dir + "/missing.png: cannot read PNG (no such file)");
  msg = refusal(dir);
  EXPECT_EQ(msg, dir + ": cannot read PNG (not a regular file)");
}

// stb_image keeps the palette in an uninitialised array: an index past the PLTE chunk's colours
// read stack bytes (mask pixels that could differ between runs). Such a file is refused naming
// the first pixel; a full palette, or indices within a short one, read as their colours.
TEST(VesselMaskPng, RefusesAPaletteIndexPastThePaletteNamingThePixel) {
  const std::string dir = test::fresh_temp_dir("vessel_mask_png_palette");
  const std::vector<std::uint8_t> black_white = {0, 0, 0, 255, 255, 255};
  std::ofstream(dir + "/within.png", std::ios::binary) << test::indexed_png_bytes(3, 1, {1, 0, 1}, black_white);
  EXPECT_EQ(load_grey_png(dir + "/within.png").grey, (std::vector<std::uint8_t>{255, 0, 255}));
  std::ofstream(dir + "/past.png", std::ios::binary) << test::indexed_png_bytes(3, 2, {1, 0, 1, 0, 0, 7}, black_white);
  EXPECT_EQ(refusal(dir + "/past.png"),
            dir + "/past.png: damaged PNG (pixel (2, 1) has a palette index past the 2 colours of its PLTE chunk)");
  // A palette that already holds the colour the check would pick for the missing entries.
  std::vector<std::uint8_t> crowded;
  for (int r = 0; r < 200; ++r) crowded.insert(crowded.end(), {std::uint8_t(r), 0x5A, 0xA5});
  std::ofstream(dir + "/crowded.png", std::ios::binary) << test::indexed_png_bytes(2, 1, {0, 199}, crowded);
  const PngPixels rgb = read_png(dir + "/crowded.png", 3);
  EXPECT_EQ(rgb.data, (std::vector<std::uint8_t>{0, 0x5A, 0xA5, 199, 0x5A, 0xA5}));
  std::ofstream(dir + "/crowded_past.png", std::ios::binary) << test::indexed_png_bytes(2, 1, {0, 200}, crowded);
  EXPECT_NE(refusal(dir + "/crowded_past.png").find("pixel (1, 0) has a palette index past the 200 colours"),
            std::string::npos);
}

}  // namespace
}  // namespace vascsim::io

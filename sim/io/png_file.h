// Strict PNG reading, shared by the renderer (golden images, `vascsim diff`) and the scene reader
// (vessel masks): the file's container is checked as libpng does and stb_image does not (the
// signature, every chunk's CRC-32, an empty IEND that ends the file), so a damaged file is refused
// naming it instead of decoding to plausible pixels; then stb_image decodes it. stb_image is
// compiled here, once, with PNG support only; no other file may define STB_IMAGE_IMPLEMENTATION.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vascsim::io {

// Largest PNG file read, in bytes (256 MB): bigger is not an image vascsim wrote or needs.
inline constexpr std::size_t kMaxPngBytes = std::size_t(256) << 20;
// Most pixels read from a PNG (2^28: 1 GB decoded as RGBA), about eight of the largest video frames.
inline constexpr std::uint64_t kMaxPngPixels = std::uint64_t(1) << 28;
// Largest width or height (px) of a mask image: 8192^2 pixels is ~0.5 GB of tracing arrays.
inline constexpr int kMaxMaskSide = 8192;

struct PngPixels {
  int width = 0, height = 0;        // px
  int channels = 0;                 // bytes per pixel: 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA
  std::vector<std::uint8_t> data;   // row-major, row 0 at the top, `channels` bytes per pixel
  // The same samples at full precision (0..65535), for a 16-bit PNG read with keep_16_bit; else
  // empty. `data` holds each one's high byte.
  std::vector<std::uint16_t> data16;
};

// Reads `path` and decodes it to `channels` (1..4) bytes per pixel, converting as stb_image does
// (to grey: luminance (77 R + 150 G + 29 B) / 256; alpha dropped). max_side > 0: refuses an image
// wider or taller than max_side px, read from the header before any pixel is decoded. Throws
// InputError naming the file if it is missing, not a regular file, over kMaxPngBytes, not a
// well-formed PNG (signature, CRCs, final IEND), too large or not decodable.
// keep_16_bit: a 16-bit PNG's samples are also kept whole, in data16 (vascsim diff: two images
// differing in their low bytes only must not compare equal).
PngPixels read_png(const std::string& path, int channels, int max_side = 0, bool keep_16_bit = false);
// read_png's checks and decoding of a file's bytes already in memory (`label` names them in
// errors); read_png is this after reading the file. The fuzz harness (tests/fuzz) calls it.
PngPixels decode_png(const std::string& bytes, const std::string& label, int channels, int max_side = 0,
                     bool keep_16_bit = false);

// Width and height (px) from a PNG file's header (its first 24 bytes), without decoding it; {0, 0}
// if the file does not start like a PNG (read_png then says what is wrong). vascsim diff compares
// two images' sizes before decoding either: a small file can decode to gigabytes.
std::pair<int, int> png_dimensions(const std::string& path);

// An 8-bit grey image: 0 black .. 255 white.
struct GreyImage {
  int width = 0, height = 0;         // px
  std::vector<std::uint8_t> grey;    // row-major, row 0 at the top
};
// A grey image: a colour PNG is converted to its luminance, and a PNG with alpha is composited
// over black (transparent is not lumen).
GreyImage load_grey_png(const std::string& path, int max_side = kMaxMaskSide);

}  // namespace vascsim::io

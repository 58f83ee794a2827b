// Image comparison for golden-image tests and `vascsim diff`: per-channel absolute differences
// of two PNGs of the same size (RGB, and alpha where either image has any pixel not opaque),
// summarised as max, mean, the count of
// pixels whose largest channel difference exceeds a tolerance, and PSNR, plus a heat map.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vascsim::render {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;    // top-down rows, 3 bytes per pixel
  std::vector<std::uint8_t> alpha;  // 1 byte per pixel; empty when every pixel is opaque
  // A 16-bit PNG's samples whole (RGBA, 4 per pixel, 0..65535); empty for an 8-bit one. rgb and
  // alpha then hold their high bytes.
  std::vector<std::uint16_t> rgba16;
};

// Throws InputError naming the file if it is missing, not a regular file, over 256 MB, not a
// well-formed PNG (signature, every chunk's CRC, a final empty IEND) or not decodable.
Image load_png(const std::string& path);

// Differences are in 8-bit levels (0..255) for any image: a 16-bit sample counts as value / 257,
// so a 16-bit image's differences have fractions and the tolerance means the same for both.
struct DiffStats {
  double max_difference = 0;    // largest channel difference, 0..255
  double mean_difference = 0;   // mean over all channels of all pixels
  long pixels_over = 0;         // pixels whose largest channel difference > tolerance
  long pixels = 0;
  double psnr_db = 0;           // infinity for identical images
};

// Requires equal sizes (throws InputError otherwise). `heat_map`, if not null, receives an RGB
// image: the first picture faded to grey, with differing pixels in yellow to red by size.
DiffStats diff_images(const Image& a, const Image& b, double tolerance, Image* heat_map);

// Writes an RGB image as PNG (temporary name, then rename).
void write_image_png(const std::string& path, const Image& image);

}  // namespace vascsim::render

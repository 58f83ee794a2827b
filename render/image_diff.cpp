#include "render/image_diff.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

#include "render/png_writer.h"
#include "sim/io/png_file.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {

// The strict reading (container checks, stb_image) is sim/io/png_file.h's, shared with the
// scene reader's vessel masks.
Image load_png(const std::string& path) {
  const io::PngPixels p = io::read_png(path, 4, 0, true);
  Image img;
  img.width = p.width;
  img.height = p.height;
  const std::size_t pixels = static_cast<std::size_t>(p.width) * p.height;
  img.rgb.resize(3 * pixels);
  img.alpha.resize(pixels);
  bool opaque = true;
  for (std::size_t i = 0; i < pixels; ++i) {
    for (int k = 0; k < 3; ++k) img.rgb[3 * i + k] = p.data[4 * i + k];
    img.alpha[i] = p.data[4 * i + 3];
    opaque = opaque && img.alpha[i] == 255;
  }
  if (opaque) img.alpha.clear();
  img.rgba16 = p.data16;
  return img;
}

DiffStats diff_images(const Image& a, const Image& b, double tolerance, Image* heat_map) {
  if (a.width != b.width || a.height != b.height)
    throw InputError("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " vs " +
                     std::to_string(b.width) + "x" + std::to_string(b.height));
  DiffStats s;
  s.pixels = static_cast<long>(a.width) * a.height;
  if (heat_map) {
    heat_map->width = a.width;
    heat_map->height = a.height;
    heat_map->rgb.assign(a.rgb.size(), 0);
  }
  // Alpha counts as a fourth channel when either image has any pixel not opaque (once it was
  // dropped on reading, and a half-transparent picture compared equal to its opaque original).
  // A 16-bit image counts all four (its alpha is kept whole only there).
  const int channels = a.alpha.empty() && b.alpha.empty() && a.rgba16.empty() && b.rgba16.empty() ? 3 : 4;
  // Channel k of pixel p in 8-bit levels (a 16-bit sample as value / 257, exactly 255 at full).
  const auto sample = [](const Image& i, long p, int k) -> double {
    const auto at = static_cast<std::size_t>(p);
    if (!i.rgba16.empty()) return i.rgba16[4 * at + static_cast<std::size_t>(k)] / 257.0;
    if (k < 3) return i.rgb[3 * at + static_cast<std::size_t>(k)];
    return i.alpha.empty() ? 255 : i.alpha[at];
  };
  double sum = 0, sum_sq = 0;
  for (long p = 0; p < s.pixels; ++p) {
    double worst = 0;
    for (int k = 0; k < channels; ++k) {
      const double d = std::abs(sample(a, p, k) - sample(b, p, k));
      worst = std::max(worst, d);
      sum += d;
      sum_sq += d * d;
    }
    s.max_difference = std::max(s.max_difference, worst);
    if (worst > tolerance) ++s.pixels_over;
    if (heat_map) {
      std::uint8_t* out = &heat_map->rgb[3 * p];
      if (worst == 0) {
        // Context: the first image as light grey, so differences stand out.
        const int grey = (a.rgb[3 * p] * 30 + a.rgb[3 * p + 1] * 59 + a.rgb[3 * p + 2] * 11) / 100;
        out[0] = out[1] = out[2] = static_cast<std::uint8_t>(170 + grey / 3);
      } else {
        const double w = std::min(1.0, worst / 64.0);  // yellow for small, red for large
        out[0] = 255;
        out[1] = static_cast<std::uint8_t>(220 * (1 - w));
        out[2] = 0;
      }
    }
  }
  const double n = channels * static_cast<double>(s.pixels);
  s.mean_difference = n > 0 ? sum / n : 0;
  const double mse = n > 0 ? sum_sq / n : 0;
  s.psnr_db = mse > 0 ? 10 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
  return s;
}

void write_image_png(const std::string& path, const Image& image) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(image.width) * image.height * 4, 255);
  for (std::size_t p = 0, n = static_cast<std::size_t>(image.width) * image.height; p < n; ++p)
    for (int k = 0; k < 3; ++k) rgba[4 * p + k] = image.rgb[3 * p + k];
  write_png(path, rgba.data(), image.width, image.height);
}

}  // namespace vascsim::render

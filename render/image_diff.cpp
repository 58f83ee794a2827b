#include "render/image_diff.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

#include "render/png_writer.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {

namespace {

constexpr std::size_t kMaxPngBytes = std::size_t(256) << 20;

std::uint32_t big_endian_u32(const unsigned char* p) {
  return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) | std::uint32_t(p[3]);
}

// The PNG container, checked as libpng does and stb_image does not: the signature, every chunk's
// length and CRC-32 (zlib's), and an empty IEND chunk that ends the file. A golden image that
// was damaged in transit must not compare as "within tolerance".
void check_png_container(const std::string& bytes, const std::string& path) {
  static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  if (bytes.size() < 8 || std::memcmp(b, signature, 8) != 0) throw InputError(path + ": not a PNG file (no PNG signature)");
  std::size_t at = 8;
  for (;;) {
    if (at + 12 > bytes.size()) throw InputError(path + ": truncated PNG (no IEND chunk at the end)");
    const std::uint32_t length = big_endian_u32(b + at);
    const std::string type(bytes, at + 4, 4);
    if (length > bytes.size() - at - 12)
      throw InputError(path + ": truncated PNG (chunk " + type + " at offset " + std::to_string(at) + " runs past the end)");
    const std::uint32_t crc = static_cast<std::uint32_t>(crc32(crc32(0, nullptr, 0), b + at + 4, length + 4));
    if (crc != big_endian_u32(b + at + 8 + length))
      throw InputError(path + ": damaged PNG (bad CRC in chunk " + type + " at offset " + std::to_string(at) + ")");
    at += 12 + length;
    if (type == "IEND") {
      if (length != 0 || at != bytes.size()) throw InputError(path + ": damaged PNG (data after or inside IEND)");
      return;
    }
  }
}

std::string read_png_bytes(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw InputError(path + ": cannot read PNG (no such file)");
  if (!std::filesystem::is_regular_file(status)) throw InputError(path + ": cannot read PNG (not a regular file)");
  if (std::filesystem::file_size(path, ec) > kMaxPngBytes)
    throw InputError(path + ": cannot read PNG (larger than " + std::to_string(kMaxPngBytes >> 20) + " MB)");
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw InputError(path + ": cannot read PNG (read error)");
  return bytes;
}

}  // namespace

Image load_png(const std::string& path) {
  const std::string bytes = read_png_bytes(path);
  check_png_container(bytes, path);
  int w = 0, h = 0, comp = 0;
  unsigned char* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                              static_cast<int>(bytes.size()), &w, &h, &comp, 3);
  if (!data) {
    const char* why = stbi_failure_reason();
    throw InputError(path + ": cannot decode PNG (" + (why && *why ? why : "unknown error") + ")");
  }
  Image img;
  img.width = w;
  img.height = h;
  img.rgb.assign(data, data + static_cast<std::size_t>(w) * h * 3);
  stbi_image_free(data);
  return img;
}

DiffStats diff_images(const Image& a, const Image& b, int tolerance, Image* heat_map) {
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
  double sum = 0, sum_sq = 0;
  for (long p = 0; p < s.pixels; ++p) {
    int worst = 0;
    for (int k = 0; k < 3; ++k) {
      const int d = std::abs(int(a.rgb[3 * p + k]) - int(b.rgb[3 * p + k]));
      worst = std::max(worst, d);
      sum += d;
      sum_sq += double(d) * d;
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
  const double n = 3.0 * static_cast<double>(s.pixels);
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

#include "sim/io/png_file.h"

#include <zlib.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

#include "sim/scene/input_error.h"

namespace vascsim::io {

namespace {

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
  if (!in) throw InputError(path + ": cannot read PNG (cannot open it)");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw InputError(path + ": cannot read PNG (read error)");
  return bytes;
}

std::string decode_failure(const std::string& path) {
  const char* why = stbi_failure_reason();
  return path + ": cannot decode PNG (" + (why && *why ? why : "unknown error") + ")";
}

}  // namespace

PngPixels read_png(const std::string& path, int channels, int max_side) {
  return decode_png(read_png_bytes(path), path, channels, max_side);
}

PngPixels decode_png(const std::string& bytes, const std::string& label, int channels, int max_side) {
  if (bytes.size() > kMaxPngBytes)
    throw InputError(label + ": cannot read PNG (larger than " + std::to_string(kMaxPngBytes >> 20) + " MB)");
  check_png_container(bytes, label);
  const auto* raw = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = static_cast<int>(bytes.size());  // <= kMaxPngBytes, fits an int
  int w = 0, h = 0, comp = 0;
  // The header's size first: a small file can claim a huge image, and decoding allocates it.
  if (!stbi_info_from_memory(raw, size, &w, &h, &comp)) throw InputError(decode_failure(label));
  if (max_side > 0 && (w > max_side || h > max_side))
    throw InputError(label + ": the image is " + std::to_string(w) + " x " + std::to_string(h) +
                     " px, larger than " + std::to_string(max_side) + " px a side");
  unsigned char* data = stbi_load_from_memory(raw, size, &w, &h, &comp, channels);
  if (!data) throw InputError(decode_failure(label));
  PngPixels img;
  img.width = w;
  img.height = h;
  img.channels = channels;
  img.data.assign(data, data + static_cast<std::size_t>(w) * h * channels);
  stbi_image_free(data);
  return img;
}

GreyImage load_grey_png(const std::string& path, int max_side) {
  // Grey and alpha, composited over black: a mask drawn on a transparent background (white with
  // alpha 0 outside the vessels, as image editors export it) was read as all lumen.
  const PngPixels p = read_png(path, 2, max_side);
  GreyImage img;
  img.width = p.width;
  img.height = p.height;
  img.grey.resize(p.data.size() / 2);
  for (std::size_t i = 0; i < img.grey.size(); ++i)
    img.grey[i] = static_cast<std::uint8_t>((unsigned{p.data[2 * i]} * p.data[2 * i + 1] + 127) / 255);
  return img;
}

}  // namespace vascsim::io

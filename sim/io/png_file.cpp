#include "sim/io/png_file.h"

#include <zlib.h>

#include <cerrno>
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

void put_big_endian_u32(std::string& s, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) s.push_back(static_cast<char>((v >> shift) & 0xFF));
}

// What the checks after the container's need from it: the image's size, and where a palette
// image's colours are.
struct PaletteChunk {
  bool has_header = false;              // an IHDR chunk was read
  std::uint32_t width = 0, height = 0;  // px, IHDR
  bool indexed = false;        // IHDR colour type 3
  int bit_depth = 0;           // bits per index
  std::size_t at = 0;          // offset of the PLTE chunk (its length field)
  std::size_t entries = 0;     // colours it holds
};

// The PNG container, checked as libpng does and stb_image does not: the signature, every chunk's
// length and CRC-32 (zlib's), and an empty IEND chunk that ends the file. A golden image that
// was damaged in transit must not compare as "within tolerance".
PaletteChunk check_png_container(const std::string& bytes, const std::string& path) {
  PaletteChunk palette;
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
    if (type == "IHDR" && length >= 10) {
      palette.has_header = true;
      palette.width = big_endian_u32(b + at + 8);
      palette.height = big_endian_u32(b + at + 12);
      palette.bit_depth = b[at + 16];
      palette.indexed = b[at + 17] == 3;
    }
    if (type == "PLTE" && length % 3 == 0) {  // a ragged one is stb_image's to refuse
      palette.at = at;
      palette.entries = length / 3;
    }
    at += 12 + length;
    if (type == "IEND") {
      if (length != 0 || at != bytes.size()) throw InputError(path + ": damaged PNG (data after or inside IEND)");
      return palette;
    }
  }
}

std::string read_png_bytes(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw InputError(path + ": cannot read PNG (no such file)");
  if (!std::filesystem::is_regular_file(status)) throw InputError(path + ": cannot read PNG (not a regular file)");
  if (std::filesystem::file_size(path, ec) > kMaxPngBytes)
    throw InputError(path + ": cannot read PNG (larger than " + std::to_string(kMaxPngBytes >> 20) + " MiB)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read PNG (cannot open it: " + std::strerror(errno) + ")");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw InputError(path + ": cannot read PNG (read error)");
  return bytes;
}

std::string decode_failure(const std::string& path) {
  const char* why = stbi_failure_reason();
  return path + ": cannot decode PNG (" + (why && *why ? why : "unknown error") + ")";
}

// stb_image keeps a palette in an uninitialised 256-entry array, so an index past the PLTE
// chunk's colours decodes to whatever was on the stack: pixels that differ from run to run. The
// image is decoded once with the missing entries filled by a colour the palette does not hold,
// and refused if any pixel shows it; the filled copy is what is then decoded, so even a decoder
// that gets past the check reads defined bytes. Only palette images short of 2^depth colours pay;
// for any other image this returns an empty string and the original bytes are decoded.
std::string refuse_indices_past_the_palette(const std::string& bytes, const PaletteChunk& palette,
                                            const std::string& label) {
  if (!palette.indexed || palette.at == 0 || palette.bit_depth < 1 || palette.bit_depth > 8) return {};
  const std::size_t possible = std::size_t{1} << palette.bit_depth;
  if (palette.entries == 0 || palette.entries >= possible) return {};
  const std::string colours = bytes.substr(palette.at + 8, palette.entries * 3);
  std::string unused = "\x5A\xA5";  // first byte chosen below: one of 256 is free of <= 255 colours
  for (int r = 0; r < 256; ++r) {
    const std::string candidate = std::string(1, static_cast<char>(r)) + unused;
    bool taken = false;
    for (std::size_t k = 0; k < palette.entries && !taken; ++k) taken = colours.compare(3 * k, 3, candidate) == 0;
    if (!taken) {
      unused = candidate;
      break;
    }
  }
  std::string plte = "PLTE" + colours;
  for (std::size_t k = palette.entries; k < possible; ++k) plte += unused;
  std::string filled = bytes.substr(0, palette.at);
  put_big_endian_u32(filled, static_cast<std::uint32_t>(plte.size() - 4));
  filled += plte;
  put_big_endian_u32(filled, static_cast<std::uint32_t>(
                                 crc32(crc32(0, nullptr, 0), reinterpret_cast<const Bytef*>(plte.data()), plte.size())));
  filled += bytes.substr(palette.at + 12 + palette.entries * 3);
  int w = 0, h = 0, comp = 0;
  unsigned char* rgb = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(filled.data()),
                                             static_cast<int>(filled.size()), &w, &h, &comp, 3);
  if (!rgb) throw InputError(decode_failure(label));
  const std::size_t pixels = static_cast<std::size_t>(w) * h;
  std::size_t first = pixels;
  for (std::size_t i = 0; i < pixels && first == pixels; ++i)
    if (std::memcmp(rgb + 3 * i, unused.data(), 3) == 0) first = i;
  stbi_image_free(rgb);
  if (first < pixels)
    throw InputError(label + ": damaged PNG (pixel (" + std::to_string(first % w) + ", " + std::to_string(first / w) +
                     ") has a palette index past the " + std::to_string(palette.entries) +
                     " colours of its PLTE chunk)");
  return filled;
}

}  // namespace

std::pair<int, int> png_dimensions(const std::string& path) {
  unsigned char head[24] = {};
  std::ifstream in(path, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(head), sizeof head)) return {0, 0};
  static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (std::memcmp(head, signature, 8) != 0 || std::memcmp(head + 12, "IHDR", 4) != 0) return {0, 0};
  const auto big_endian = [&](int at) {
    return static_cast<std::uint32_t>(head[at]) << 24 | static_cast<std::uint32_t>(head[at + 1]) << 16 |
           static_cast<std::uint32_t>(head[at + 2]) << 8 | head[at + 3];
  };
  const std::uint32_t w = big_endian(16), h = big_endian(20);
  if (w == 0 || h == 0 || w > 0x7fffffffu || h > 0x7fffffffu) return {0, 0};
  return {static_cast<int>(w), static_cast<int>(h)};
}

PngPixels read_png(const std::string& path, int channels, int max_side, bool keep_16_bit) {
  return decode_png(read_png_bytes(path), path, channels, max_side, keep_16_bit);
}

PngPixels decode_png(const std::string& bytes, const std::string& label, int channels, int max_side, bool keep_16_bit) {
  if (bytes.size() > kMaxPngBytes)
    throw InputError(label + ": cannot read PNG (larger than " + std::to_string(kMaxPngBytes >> 20) + " MiB)");
  const PaletteChunk palette = check_png_container(bytes, label);
  const auto* raw = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = static_cast<int>(bytes.size());  // <= kMaxPngBytes, fits an int
  int w = 0, h = 0, comp = 0;
  // The header's size first: a small file can claim a huge image, and decoding allocates it.
  // Said here in pixels: stb_image refuses both an empty image and a huge one as "unknown image
  // type".
  const std::uint64_t pixels = std::uint64_t{palette.width} * palette.height;
  if (palette.has_header && (pixels == 0 || pixels > kMaxPngPixels))
    throw InputError(label + ": the image is " + std::to_string(palette.width) + " x " + std::to_string(palette.height) +
                     " px: " + (pixels == 0 ? "no pixel" : "more than the " + std::to_string(kMaxPngPixels) + " px read"));
  if (!stbi_info_from_memory(raw, size, &w, &h, &comp)) throw InputError(decode_failure(label));
  if (max_side > 0 && (w > max_side || h > max_side))
    throw InputError(label + ": the image is " + std::to_string(w) + " x " + std::to_string(h) +
                     " px, larger than " + std::to_string(max_side) + " px a side");
  const std::string filled = refuse_indices_past_the_palette(bytes, palette, label);
  const std::string& decoded = filled.empty() ? bytes : filled;
  unsigned char* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(decoded.data()),
                                              static_cast<int>(decoded.size()), &w, &h, &comp, channels);
  if (!data) throw InputError(decode_failure(label));
  PngPixels img;
  img.width = w;
  img.height = h;
  img.channels = channels;
  const std::size_t samples = static_cast<std::size_t>(w) * h * channels;
  img.data.assign(data, data + samples);
  stbi_image_free(data);
  if (keep_16_bit && stbi_is_16_bit_from_memory(reinterpret_cast<const stbi_uc*>(decoded.data()), static_cast<int>(decoded.size()))) {
    stbi_us* wide = stbi_load_16_from_memory(reinterpret_cast<const stbi_uc*>(decoded.data()),
                                             static_cast<int>(decoded.size()), &w, &h, &comp, channels);
    if (!wide) throw InputError(decode_failure(label));
    img.data16.assign(wide, wide + samples);
    stbi_image_free(wide);
  }
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

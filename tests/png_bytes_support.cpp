#include "tests/png_bytes_support.h"

#include <algorithm>

namespace vascsim::test {

std::uint32_t crc32_of(const std::string& bytes) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return c ^ 0xFFFFFFFFu;
}

namespace {

void put_u32(std::string& s, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) s.push_back(static_cast<char>((v >> shift) & 0xFF));
}

void put_chunk(std::string& png, const std::string& type, const std::string& data) {
  put_u32(png, static_cast<std::uint32_t>(data.size()));
  const std::string body = type + data;
  png += body;
  put_u32(png, crc32_of(body));
}

std::string png_with_palette(int width, int height, int colour_type, const std::vector<std::uint8_t>& pixels,
                             const std::vector<std::uint8_t>& palette_rgb, int bit_depth = 8) {
  const int channels = (colour_type == 2 ? 3 : colour_type == 4 ? 2 : colour_type == 6 ? 4 : 1) * (bit_depth / 8);
  std::string raw;  // each row: filter type 0, then its bytes
  for (int y = 0; y < height; ++y) {
    raw.push_back(0);
    raw.append(reinterpret_cast<const char*>(pixels.data()) + static_cast<std::size_t>(y) * width * channels,
               static_cast<std::size_t>(width) * channels);
  }
  std::string z = "\x78\x01";  // zlib header: deflate, no dictionary
  for (std::size_t at = 0; at < raw.size() || at == 0; at += 65535) {
    const std::size_t n = std::min<std::size_t>(65535, raw.size() - at);
    z.push_back(at + n >= raw.size() ? 1 : 0);  // BFINAL, BTYPE 00 (stored)
    z.push_back(static_cast<char>(n & 0xFF));
    z.push_back(static_cast<char>(n >> 8));
    z.push_back(static_cast<char>(~n & 0xFF));
    z.push_back(static_cast<char>((~n >> 8) & 0xFF));
    z.append(raw, at, n);
    if (raw.empty()) break;
  }
  std::uint32_t a = 1, b = 0;  // Adler-32
  for (unsigned char c : raw) {
    a = (a + c) % 65521;
    b = (b + a) % 65521;
  }
  put_u32(z, (b << 16) | a);
  std::string ihdr;
  put_u32(ihdr, static_cast<std::uint32_t>(width));
  put_u32(ihdr, static_cast<std::uint32_t>(height));
  ihdr += std::string{static_cast<char>(bit_depth), static_cast<char>(colour_type), 0, 0, 0};  // depth, colour, deflate, filter, no interlace
  std::string png = "\x89PNG\r\n\x1a\n";
  put_chunk(png, "IHDR", ihdr);
  if (colour_type == 3) put_chunk(png, "PLTE", std::string(palette_rgb.begin(), palette_rgb.end()));
  put_chunk(png, "IDAT", z);
  put_chunk(png, "IEND", "");
  return png;
}

}  // namespace

std::string png_bytes(int width, int height, int colour_type, const std::vector<std::uint8_t>& pixels) {
  return png_with_palette(width, height, colour_type, pixels, {});
}

std::string png16_bytes(int width, int height, int colour_type, const std::vector<std::uint16_t>& samples) {
  std::vector<std::uint8_t> big_endian;
  for (std::uint16_t v : samples) {
    big_endian.push_back(static_cast<std::uint8_t>(v >> 8));
    big_endian.push_back(static_cast<std::uint8_t>(v & 0xFF));
  }
  return png_with_palette(width, height, colour_type, big_endian, {}, 16);
}

std::string indexed_png_bytes(int width, int height, const std::vector<std::uint8_t>& indices,
                              const std::vector<std::uint8_t>& palette_rgb) {
  return png_with_palette(width, height, 3, indices, palette_rgb);
}

}  // namespace vascsim::test

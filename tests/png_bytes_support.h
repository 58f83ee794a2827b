// A hand-made PNG encoder for tests (stored deflate blocks, no compression): the reader under test
// must not be checked with files its own library wrote, and sim-only builds have no PNG writer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vascsim::test {

// The CRC-32 PNG chunks carry (ISO 3309, as zlib's crc32).
std::uint32_t crc32_of(const std::string& bytes);
// An 8-bit PNG of colour type 0 (grey, 1 byte a pixel), 2 (RGB, 3 bytes), 4 (grey and alpha, 2)
// or 6 (RGBA, 4), rows from the top.
std::string png_bytes(int width, int height, int colour_type, const std::vector<std::uint8_t>& pixels);
// The same at 16 bits a sample (written big-endian, as PNG stores them).
std::string png16_bytes(int width, int height, int colour_type, const std::vector<std::uint16_t>& samples);
// An 8-bit palette PNG (colour type 3): one index a pixel into palette_rgb's colours (3 bytes
// each, written as the PLTE chunk as given, however few).
std::string indexed_png_bytes(int width, int height, const std::vector<std::uint8_t>& indices,
                              const std::vector<std::uint8_t>& palette_rgb);

}  // namespace vascsim::test

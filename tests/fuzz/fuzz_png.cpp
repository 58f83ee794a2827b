#include <zlib.h>

#include "sim/io/png_file.h"
#include "sim/scene/input_error.h"
#include "tests/fuzz/fuzz_harnesses.h"

namespace vascsim::fuzz {

namespace {

// The bytes with every chunk's CRC-32 recomputed. A mutation almost never keeps a CRC right,
// so without this nearly every input would stop at the container check and the decoder
// behind it would go unfuzzed (libpng's fuzzers skip CRCs for the same reason).
std::string with_valid_crcs(std::string b) {
  for (std::size_t at = 8; at + 12 <= b.size();) {
    const auto* p = reinterpret_cast<const unsigned char*>(b.data()) + at;
    const std::size_t length = (std::size_t(p[0]) << 24) | (std::size_t(p[1]) << 16) | (std::size_t(p[2]) << 8) | p[3];
    if (length > b.size() - at - 12) break;
    const auto crc = static_cast<std::uint32_t>(crc32(crc32(0, nullptr, 0), p + 4, static_cast<uInt>(length + 4)));
    for (int k = 0; k < 4; ++k) b[at + 8 + length + k] = static_cast<char>(crc >> (24 - 8 * k));
    at += 12 + length;
  }
  return b;
}

void decode_as_the_readers_do(const std::string& bytes) {
  try {
    // `vascsim diff` (render/image_diff.cpp): RGB, no side limit.
    const io::PngPixels rgb = io::decode_png(bytes, "fuzz.png", 3);
    if (rgb.data.size() != static_cast<std::size_t>(rgb.width) * rgb.height * 3)
      fail("decode_png returned " + std::to_string(rgb.data.size()) + " bytes for " + std::to_string(rgb.width) +
           " x " + std::to_string(rgb.height) + " RGB");
    // A vessel mask (sim/io/read_mask_pixels.cpp): grey, at most kMaxMaskSide px a side.
    const io::PngPixels grey = io::decode_png(bytes, "fuzz.png", 1, io::kMaxMaskSide);
    if (grey.width != rgb.width || grey.height != rgb.height) fail("the same PNG decodes to two sizes");
  } catch (const InputError&) {
    // the documented refusal
  }
}

}  // namespace

int png_reader(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  decode_as_the_readers_do(bytes);
  const std::string repaired = with_valid_crcs(bytes);
  if (repaired != bytes) decode_as_the_readers_do(repaired);
  return 0;
}

}  // namespace vascsim::fuzz

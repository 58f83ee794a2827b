// PNG files through stb_image_write, tuned for rendered frames: RGB (no alpha), a fixed row
// filter and zlib (level 1) in place of stb's own deflate, because the adaptive filter search
// and stb's default effort cost ~135 ms per 720p frame while flat-coloured renders compress
// nearly as well this way (~8 ms).
// Files are written to a temporary name and renamed, so a final name never holds a partial file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vascsim::render {

// PNG bytes of a top-down RGBA image (alpha dropped). Deterministic.
std::vector<std::uint8_t> encode_png(const std::uint8_t* rgba, int width, int height);
// Writes the PNG under a temporary name of this process's own, then renames it to `path`
// (write_file_atomically, sim/io/output_file.h). Throws InputError naming `path` on failure.
void write_png(const std::string& path, const std::uint8_t* rgba, int width, int height);
// "DIR/frame_000042.png".
std::string png_frame_path(const std::string& dir, std::size_t index);

}  // namespace vascsim::render

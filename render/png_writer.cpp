#include "render/png_writer.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>

#include <zlib.h>

// stb's own deflate is simple and slow (~20 ms per 720p frame); zlib's level 1 gives similar
// sizes in a third of the time, and stb lets us plug it in.
static unsigned char* vascsim_zlib_compress(unsigned char* data, int length, int* out_length, int level) {
  uLongf size = compressBound(static_cast<uLong>(length));
  auto* out = static_cast<unsigned char*>(std::malloc(size));
  if (!out) return nullptr;
  if (compress2(out, &size, data, static_cast<uLong>(length), level) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *out_length = static_cast<int>(size);
  return out;
}
#define STBIW_ZLIB_COMPRESS vascsim_zlib_compress
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb_image_write.h>

#include "sim/io/output_file.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {

namespace {

void configure_stb() {
  // stb keeps these in globals; set them once, before any encoder thread starts.
  static std::once_flag once;
  std::call_once(once, [] {
    stbi_write_png_compression_level = 1;  // zlib level: fastest; renders are flat colour
    stbi_write_force_png_filter = 1;  // "sub": flat rows of a rendering become runs of zeros
  });
}

void append(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::vector<std::uint8_t> encode_png(const std::uint8_t* rgba, int width, int height) {
  configure_stb();
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * height * 3);
  for (std::size_t i = 0, n = static_cast<std::size_t>(width) * height; i < n; ++i)
    std::memcpy(&rgb[3 * i], &rgba[4 * i], 3);
  std::vector<std::uint8_t> out;
  if (!stbi_write_png_to_func(append, &out, width, height, 3, rgb.data(), 3 * width))
    throw std::runtime_error("PNG encoding failed");
  return out;
}

void write_png(const std::string& path, const std::uint8_t* rgba, int width, int height) {
  const std::vector<std::uint8_t> bytes = encode_png(rgba, width, height);
  // A temporary name of this process's own, then a rename (sim/io/output_file.h).
  write_file_atomically(path, std::string(bytes.begin(), bytes.end()));
}

std::string png_frame_path(const std::string& dir, std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06zu.png", index);
  return (std::filesystem::path(dir) / name).string();
}

}  // namespace vascsim::render

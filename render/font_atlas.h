// Text rasterising for the HUD, legends and plot labels: stb_truetype packs the glyphs of one
// TrueType font (DejaVu Sans from fonts-dejavu-core) at one pixel size into a coverage bitmap,
// and lays out UTF-8 strings as textured quads on it. No OpenGL here; the canvas uploads the
// bitmap.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace vascsim::render {

// The font file the renderer uses (compile-time default; tests and the docs name it).
const std::string& default_font_path();

// One glyph quad in pixel coordinates relative to the pen (baseline origin), with atlas
// texture coordinates in [0, 1].
struct GlyphQuad {
  float x0, y0, x1, y1;  // px, y down
  float s0, t0, s1, t1;
};

class FontAtlas {
 public:
  // Throws InputError naming the file if the font cannot be read.
  FontAtlas(const std::string& ttf_path, int pixel_height);
  ~FontAtlas();
  FontAtlas(const FontAtlas&) = delete;
  FontAtlas& operator=(const FontAtlas&) = delete;

  int pixel_height() const { return pixel_height_; }
  int atlas_width() const { return atlas_width_; }
  int atlas_height() const { return atlas_height_; }
  const std::vector<std::uint8_t>& bitmap() const { return bitmap_; }  // coverage, row-major
  // Appends the quads of `utf8` starting with the pen at x = 0 on the baseline; returns the
  // advance width in px. Characters outside the packed ranges show as '?'.
  float layout(const std::string& utf8, std::vector<GlyphQuad>* quads) const;
  float ascent() const { return ascent_; }  // px above the baseline

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int pixel_height_;
  int atlas_width_ = 512, atlas_height_ = 512;
  float ascent_ = 0;
  std::vector<std::uint8_t> bitmap_;
};

}  // namespace vascsim::render

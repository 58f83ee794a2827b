#include "render/font_atlas.h"

#include <fstream>
#include <iterator>

#define STB_TRUETYPE_IMPLEMENTATION
#include <stb_truetype.h>

#include "sim/scene/input_error.h"

namespace vascsim::render {

namespace {

// Printable ASCII and Latin-1 (µ, ±, °, ·, ×): every unit and symbol the renderer writes.
constexpr int kAsciiFirst = 32, kAsciiCount = 95;
constexpr int kLatinFirst = 160, kLatinCount = 96;

std::uint32_t next_codepoint(const std::string& s, std::size_t& i) {
  const auto c = static_cast<unsigned char>(s[i++]);
  if (c < 0x80) return c;
  int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : 1;
  std::uint32_t cp = c & (0x3F >> extra);
  while (extra-- > 0 && i < s.size()) cp = (cp << 6) | (static_cast<unsigned char>(s[i++]) & 0x3F);
  return cp;
}

}  // namespace

const std::string& default_font_path() {
  static const std::string path = VASCSIM_FONT_PATH;
  return path;
}

struct FontAtlas::Impl {
  std::vector<unsigned char> ttf;
  stbtt_packedchar ascii[kAsciiCount];
  stbtt_packedchar latin[kLatinCount];
};

FontAtlas::FontAtlas(const std::string& ttf_path, int pixel_height)
    : impl_(std::make_unique<Impl>()), pixel_height_(pixel_height) {
  std::ifstream in(ttf_path, std::ios::binary);
  impl_->ttf.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  stbtt_fontinfo info;
  if (impl_->ttf.empty() || !stbtt_InitFont(&info, impl_->ttf.data(), 0))
    throw InputError(ttf_path + ": cannot read the TrueType font (install fonts-dejavu-core)");
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&info, &ascent, &descent, &gap);
  ascent_ = ascent * stbtt_ScaleForPixelHeight(&info, static_cast<float>(pixel_height));

  // Grow the atlas until every glyph fits; large HUD sizes need more room.
  for (;;) {
    bitmap_.assign(static_cast<std::size_t>(atlas_width_) * atlas_height_, 0);
    stbtt_pack_context pack{};
    stbtt_PackBegin(&pack, bitmap_.data(), atlas_width_, atlas_height_, 0, 1, nullptr);
    stbtt_pack_range ranges[2] = {};
    ranges[0].font_size = static_cast<float>(pixel_height);
    ranges[0].first_unicode_codepoint_in_range = kAsciiFirst;
    ranges[0].num_chars = kAsciiCount;
    ranges[0].chardata_for_range = impl_->ascii;
    ranges[1] = ranges[0];
    ranges[1].first_unicode_codepoint_in_range = kLatinFirst;
    ranges[1].num_chars = kLatinCount;
    ranges[1].chardata_for_range = impl_->latin;
    const int ok = stbtt_PackFontRanges(&pack, impl_->ttf.data(), 0, ranges, 2);
    stbtt_PackEnd(&pack);
    if (ok) break;
    if (atlas_width_ >= 4096) throw InputError(ttf_path + ": font size too large for the glyph atlas");
    atlas_width_ *= 2;
    atlas_height_ *= 2;
  }
}

FontAtlas::~FontAtlas() = default;

float FontAtlas::layout(const std::string& utf8, std::vector<GlyphQuad>* quads) const {
  float x = 0, y = 0;
  for (std::size_t i = 0; i < utf8.size();) {
    const std::uint32_t cp = next_codepoint(utf8, i);
    const stbtt_packedchar* chars = impl_->ascii;
    int index = '?' - kAsciiFirst;
    if (cp >= kAsciiFirst && cp < kAsciiFirst + kAsciiCount) {
      index = static_cast<int>(cp) - kAsciiFirst;
    } else if (cp >= kLatinFirst && cp < kLatinFirst + kLatinCount) {
      chars = impl_->latin;
      index = static_cast<int>(cp) - kLatinFirst;
    }
    stbtt_aligned_quad q;
    stbtt_GetPackedQuad(chars, atlas_width_, atlas_height_, index, &x, &y, &q, 0);
    if (quads) quads->push_back({q.x0, q.y0, q.x1, q.y1, q.s0, q.t0, q.s1, q.t1});
  }
  return x;
}

}  // namespace vascsim::render

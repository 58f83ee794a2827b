// A 2D drawing surface on the GPU (OSMesa/llvmpipe): capsules, rings, triangles, rounded boxes,
// polylines, arrows, filled regions of any shape and text, in pixel coordinates with y down.
// Every shape is one instanced quad whose fragment shader evaluates the shape's signed distance,
// so edges are anti-aliased analytically at the cost of one distance per covered pixel (no
// multisample buffer); a region is rasterised as plain triangles with an anti-aliased outline.
// Shapes are queued and drawn in call order by finish(), which returns the picture.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace vascsim::render {

class GlContext;
class FontAtlas;

// Colour with straight (not premultiplied) alpha, components in [0, 1].
struct Rgba {
  float r = 0, g = 0, b = 0, a = 1;
};
// From 0xRRGGBB and an opacity.
constexpr Rgba hex(std::uint32_t rgb, float alpha = 1.0f) {
  return {((rgb >> 16) & 0xFF) / 255.0f, ((rgb >> 8) & 0xFF) / 255.0f, (rgb & 0xFF) / 255.0f, alpha};
}

enum class AntiAliasing {
  kAnalytic,  // coverage from the signed distance over a one-pixel ramp (default)
  kMsaa4,     // 4 samples per pixel, shaded per sample, hard-edged shapes (for comparison)
  kNone,      // hard edges, one sample (for tests of geometry)
};

enum class TextAlign { kLeft, kCenter, kRight };

class Canvas {
 public:
  // Throws std::runtime_error if no OpenGL context can be created.
  Canvas(int width, int height, AntiAliasing aa = AntiAliasing::kAnalytic);
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  std::string gl_description() const;

  void clear(Rgba colour);
  // A segment with round caps, radius in px; a == b gives a disc.
  void capsule(glm::vec2 a, glm::vec2 b, float radius, Rgba colour);
  void disc(glm::vec2 centre, float radius, Rgba colour) { capsule(centre, centre, radius, colour); }
  void ring(glm::vec2 centre, float radius, float stroke, Rgba colour);
  void triangle(glm::vec2 p0, glm::vec2 p1, glm::vec2 p2, Rgba colour);
  void box(glm::vec2 min, glm::vec2 max, Rgba colour, float corner_radius = 0);
  // An opaque rectangle snapped to whole pixels, filled by a scissored clear: far cheaper than
  // a shaded box for backgrounds and panels (llvmpipe shades every covered pixel).
  void fill_rect(glm::vec2 min, glm::vec2 max, Rgba colour);
  void box_outline(glm::vec2 min, glm::vec2 max, float stroke, Rgba colour, float corner_radius = 0);
  // Round-joined polyline of width `width` px. Opaque colours join seamlessly; translucent
  // ones darken slightly where consecutive capsules overlap.
  void polyline(const std::vector<glm::vec2>& points, float width, Rgba colour);
  void dashed_polyline(const std::vector<glm::vec2>& points, float width, float dash, float gap, Rgba colour);
  // Arrow from `tail` to `head` (px): a shaft of width `width` and a head sized with it. The
  // head's tip is exactly at `head`.
  void arrow(glm::vec2 tail, glm::vec2 head, float width, Rgba colour);
  // A region of any shape (a vessel lumen): `triangles` tile it, three vertices each (px), as
  // triangulate_even_odd (render/polygon_fill.h) gives them transformed to pixels; `outline`
  // holds its boundary as closed rings (px). Each pixel whose centre is inside is drawn exactly
  // once, so even a translucent colour comes out flat; the outline adds the anti-aliasing ramp
  // outside the edge (where a translucent colour darkens slightly, as in polyline).
  void region(const std::vector<glm::vec2>& triangles, const std::vector<std::vector<glm::vec2>>& outline,
              Rgba colour);

  // Text with its baseline at `pos.y`, aligned horizontally on `pos.x`. `angle` in radians,
  // counter-clockwise on screen (pi/2 for a vertical axis label reading bottom to top).
  void text(const std::string& utf8, glm::vec2 pos, int pixel_height, Rgba colour,
            TextAlign align = TextAlign::kLeft, float angle = 0);
  float text_width(const std::string& utf8, int pixel_height);

  // The most shapes, and triangle vertices (regions and text), one frame queues: 2^18 and 2^20
  // (14 and 32 MB here, a few times that in llvmpipe's bins), several times what a real frame
  // draws (a 200 x 200 maze's ~80000 walls, a path's dashes across a 4K frame, a traced mask's
  // lumen), so only a degenerate log reaches them (a path of millions of points winding over
  // the map, a title of megabytes). Beyond them a frame's drawing is dropped and counted, rather
  // than memory growing with the input until allocation fails.
  static constexpr std::size_t kMaxShapes = std::size_t(1) << 18;
  static constexpr std::size_t kMaxVertices = std::size_t(1) << 20;
  // Shapes queued since the last finish() (tests check that drawing stays bounded).
  std::size_t queued_shapes() const { return shapes_.size(); }
  // Shapes and vertices dropped over the limits above since the canvas was made.
  std::size_t dropped() const { return dropped_; }
  // Draws everything queued since the last finish() and reads the picture back as top-down
  // RGBA8 rows (width*height*4 bytes). The queue starts empty again.
  void finish(std::uint8_t* rgba);

 private:
  struct Shape {  // one instance, laid out as the vertex attributes
    glm::vec4 p;       // kind-dependent points (capsule a, b; triangle p0, p1; box min, max)
    glm::vec4 q;       // triangle p2 (xy), radius, stroke (0 = filled)
    glm::vec4 colour;  // straight alpha
    float kind;        // 0 capsule, 1 triangle, 2 box
  };
  struct Vertex {  // of glyph quads and regions, drawn as plain triangles
    glm::vec2 pos, uv;  // uv: glyph atlas coordinates (unused by regions)
    glm::vec4 colour;
  };
  enum class BatchKind {
    kShapes,  // instanced quads: shapes_[first, first + count)
    kText,    // glyph triangles of one font size: vertices_[first, first + count)
    kRegion,  // plain triangles in one colour: vertices_[first, first + count)
    kClear,   // a fill_rect: rect and colour below
  };
  struct Batch {
    static Batch of(BatchKind kind, std::size_t first, int font_size = 0) {
      Batch b;
      b.kind = kind;
      b.font_size = font_size;
      b.first = first;
      return b;
    }
    BatchKind kind = BatchKind::kShapes;
    int font_size = 0;
    std::size_t first = 0, count = 0;
    int rect[4] = {0, 0, 0, 0};  // kClear: x, y, width, height in px
    Rgba colour;                 // kClear
  };
  void push_shape(const Shape& s);
  FontAtlas& font(int pixel_height);
  unsigned font_texture(int pixel_height);
  void build_pipeline();

  int width_, height_;
  AntiAliasing aa_;
  std::unique_ptr<GlContext> gl_;
  std::vector<Shape> shapes_;
  std::vector<Vertex> vertices_;
  std::vector<Batch> batches_;
  std::map<int, std::unique_ptr<FontAtlas>> fonts_;
  std::map<int, unsigned> font_textures_;
  unsigned shape_program_ = 0, text_program_ = 0, region_program_ = 0;
  unsigned shape_vao_ = 0, shape_vbo_ = 0, vertex_vao_ = 0, vertex_vbo_ = 0;
  std::vector<glm::vec2> scratch_;
  std::size_t dropped_ = 0;
};

}  // namespace vascsim::render

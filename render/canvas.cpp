#include "render/canvas.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "render/font_atlas.h"
#include "render/gl_context.h"

namespace vascsim::render {

namespace {

// Each shape is a quad (4 vertices of a strip) around its bounding region, padded by the
// anti-aliasing ramp; the fragment shader turns the signed distance d (px, negative inside)
// into coverage clamp(0.5 - d, 0, 1): a box filter one pixel wide across the edge.
constexpr const char* kShapeVertex = R"(#version 330 core
layout(location = 0) in vec4 a_p;
layout(location = 1) in vec4 a_q;
layout(location = 2) in vec4 a_colour;
layout(location = 3) in float a_kind;
uniform vec2 u_size;
uniform float u_pad;
out vec2 v_pos;
flat out vec4 v_p;
flat out vec4 v_q;
flat out vec4 v_colour;
flat out float v_kind;
void main() {
  vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1)) * 2.0 - 1.0;
  float ext = a_q.z + 0.5 * a_q.w + u_pad;
  vec2 pos;
  if (a_kind < 0.5) {
    vec2 d = a_p.zw - a_p.xy;
    float len = length(d);
    vec2 dir = len > 1e-6 ? d / len : vec2(1.0, 0.0);
    vec2 n = vec2(-dir.y, dir.x);
    pos = 0.5 * (a_p.xy + a_p.zw) + dir * corner.x * (0.5 * len + ext) + n * corner.y * ext;
  } else if (a_kind < 1.5) {
    vec2 lo = min(min(a_p.xy, a_p.zw), a_q.xy) - vec2(0.5 * a_q.w + u_pad);
    vec2 hi = max(max(a_p.xy, a_p.zw), a_q.xy) + vec2(0.5 * a_q.w + u_pad);
    pos = mix(lo, hi, corner * 0.5 + 0.5);
  } else {
    vec2 lo = a_p.xy - vec2(0.5 * a_q.w + u_pad);
    vec2 hi = a_p.zw + vec2(0.5 * a_q.w + u_pad);
    pos = mix(lo, hi, corner * 0.5 + 0.5);
  }
  v_pos = pos;
  v_p = a_p;
  v_q = a_q;
  v_colour = a_colour;
  v_kind = a_kind;
  gl_Position = vec4(pos / u_size * 2.0 - 1.0, 0.0, 1.0);
}
)";

constexpr const char* kShapeFragment = R"(#version 330 core
in vec2 v_pos;
flat in vec4 v_p;
flat in vec4 v_q;
flat in vec4 v_colour;
flat in float v_kind;
uniform int u_analytic;
out vec4 frag;
float sd_segment(vec2 p, vec2 a, vec2 b) {
  vec2 pa = p - a, ba = b - a;
  float h = clamp(dot(pa, ba) / max(dot(ba, ba), 1e-12), 0.0, 1.0);
  return length(pa - ba * h);
}
// Exact signed distance to a triangle (Inigo Quilez, "2D distance functions").
float sd_triangle(vec2 p, vec2 p0, vec2 p1, vec2 p2) {
  vec2 e0 = p1 - p0, e1 = p2 - p1, e2 = p0 - p2;
  vec2 v0 = p - p0, v1 = p - p1, v2 = p - p2;
  vec2 pq0 = v0 - e0 * clamp(dot(v0, e0) / dot(e0, e0), 0.0, 1.0);
  vec2 pq1 = v1 - e1 * clamp(dot(v1, e1) / dot(e1, e1), 0.0, 1.0);
  vec2 pq2 = v2 - e2 * clamp(dot(v2, e2) / dot(e2, e2), 0.0, 1.0);
  float s = sign(e0.x * e2.y - e0.y * e2.x);
  vec2 d = min(min(vec2(dot(pq0, pq0), s * (v0.x * e0.y - v0.y * e0.x)),
                   vec2(dot(pq1, pq1), s * (v1.x * e1.y - v1.y * e1.x))),
                   vec2(dot(pq2, pq2), s * (v2.x * e2.y - v2.y * e2.x)));
  return -sqrt(d.x) * sign(d.y);
}
void main() {
  float d;
  if (v_kind < 0.5) {
    d = sd_segment(v_pos, v_p.xy, v_p.zw) - v_q.z;
  } else if (v_kind < 1.5) {
    d = sd_triangle(v_pos, v_p.xy, v_p.zw, v_q.xy);
  } else {
    vec2 c = 0.5 * (v_p.xy + v_p.zw), h = 0.5 * (v_p.zw - v_p.xy);
    float r = min(v_q.z, min(h.x, h.y));
    vec2 q = abs(v_pos - c) - h + r;
    d = length(max(q, 0.0)) + min(max(q.x, q.y), 0.0) - r;
  }
  if (v_q.w > 0.0) d = abs(d) - 0.5 * v_q.w;
  float coverage = u_analytic != 0 ? clamp(0.5 - d, 0.0, 1.0) : (d <= 0.0 ? 1.0 : 0.0);
  if (coverage <= 0.0) discard;
  frag = vec4(v_colour.rgb, v_colour.a * coverage);
}
)";

// Glyph quads and regions: plain triangles in pixels, coloured per vertex.
constexpr const char* kTextVertex = R"(#version 330 core
layout(location = 0) in vec2 a_pos;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in vec4 a_colour;
uniform vec2 u_size;
out vec2 v_uv;
out vec4 v_colour;
void main() {
  v_uv = a_uv;
  v_colour = a_colour;
  gl_Position = vec4(a_pos / u_size * 2.0 - 1.0, 0.0, 1.0);
}
)";

constexpr const char* kTextFragment = R"(#version 330 core
in vec2 v_uv;
in vec4 v_colour;
uniform sampler2D u_atlas;
out vec4 frag;
void main() {
  float coverage = texture(u_atlas, v_uv).r;
  if (coverage <= 0.0) discard;
  frag = vec4(v_colour.rgb, v_colour.a * coverage);
}
)";

// Regions need no distance: the rasteriser decides coverage (see Canvas::region).
constexpr const char* kRegionFragment = R"(#version 330 core
in vec2 v_uv;
in vec4 v_colour;
out vec4 frag;
void main() { frag = v_colour; }
)";

GLuint compile(GLenum type, const char* source) {
  GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("shader compilation failed: ") + log);
  }
  return s;
}

GLuint link(const char* vertex, const char* fragment) {
  GLuint vs = compile(GL_VERTEX_SHADER, vertex), fs = compile(GL_FRAGMENT_SHADER, fragment);
  GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  glLinkProgram(p);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048];
    glGetProgramInfoLog(p, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("shader link failed: ") + log);
  }
  return p;
}

glm::vec4 to_vec4(Rgba c) { return {c.r, c.g, c.b, c.a}; }

}  // namespace

Canvas::Canvas(int width, int height, AntiAliasing aa)
    : width_(width), height_(height), aa_(aa),
      gl_(std::make_unique<GlContext>(width, height, aa == AntiAliasing::kMsaa4 ? 4 : 0)) {
  build_pipeline();
}

Canvas::~Canvas() {
  gl_->make_current();
  for (auto& [size, tex] : font_textures_) glDeleteTextures(1, &tex);
  glDeleteBuffers(1, &shape_vbo_);
  glDeleteBuffers(1, &vertex_vbo_);
  glDeleteVertexArrays(1, &shape_vao_);
  glDeleteVertexArrays(1, &vertex_vao_);
  glDeleteProgram(shape_program_);
  glDeleteProgram(text_program_);
  glDeleteProgram(region_program_);
}

std::string Canvas::gl_description() const { return gl_->description(); }

void Canvas::build_pipeline() {
  shape_program_ = link(kShapeVertex, kShapeFragment);
  text_program_ = link(kTextVertex, kTextFragment);
  region_program_ = link(kTextVertex, kRegionFragment);
  glGenVertexArrays(1, &shape_vao_);
  glGenBuffers(1, &shape_vbo_);
  glGenVertexArrays(1, &vertex_vao_);
  glGenBuffers(1, &vertex_vbo_);

  glBindVertexArray(vertex_vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vertex_vbo_);
  const auto stride = static_cast<GLsizei>(sizeof(Vertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, pos)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, uv)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(offsetof(Vertex, colour)));
  glBindVertexArray(0);

  const float size[2] = {static_cast<float>(width_), static_cast<float>(height_)};
  glUseProgram(shape_program_);
  glUniform2fv(glGetUniformLocation(shape_program_, "u_size"), 1, size);
  // Pad quads by the anti-aliasing ramp so partly covered edge pixels are shaded.
  glUniform1f(glGetUniformLocation(shape_program_, "u_pad"), aa_ == AntiAliasing::kAnalytic ? 1.0f : 0.75f);
  glUniform1i(glGetUniformLocation(shape_program_, "u_analytic"), aa_ == AntiAliasing::kAnalytic ? 1 : 0);
  glUseProgram(text_program_);
  glUniform2fv(glGetUniformLocation(text_program_, "u_size"), 1, size);
  glUniform1i(glGetUniformLocation(text_program_, "u_atlas"), 0);
  glUseProgram(region_program_);
  glUniform2fv(glGetUniformLocation(region_program_, "u_size"), 1, size);
  glUseProgram(0);

  glEnable(GL_BLEND);
  // Colour: "over" compositing; alpha: accumulate coverage so an opaque background stays opaque.
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_DEPTH_TEST);
  if (aa_ == AntiAliasing::kMsaa4) {
    glEnable(GL_MULTISAMPLE);
#ifdef GL_SAMPLE_SHADING
    // Per-sample shading so the distance test runs at every sample, as geometric MSAA would.
    glEnable(GL_SAMPLE_SHADING);
    glMinSampleShading(1.0f);
#endif
  }
}

void Canvas::clear(Rgba c) {
  // A clear discards what is queued: nothing drawn before it could remain visible.
  shapes_.clear();
  vertices_.clear();
  batches_.clear();
  fill_rect({0, 0}, {static_cast<float>(width_), static_cast<float>(height_)}, c);
}

void Canvas::fill_rect(glm::vec2 min, glm::vec2 max, Rgba colour) {
  const int x0 = std::max(0, static_cast<int>(std::lround(min.x))), y0 = std::max(0, static_cast<int>(std::lround(min.y)));
  const int x1 = std::min(width_, static_cast<int>(std::lround(max.x)));
  const int y1 = std::min(height_, static_cast<int>(std::lround(max.y)));
  if (x1 <= x0 || y1 <= y0) return;
  Batch b = Batch::of(BatchKind::kClear, 0);
  b.rect[0] = x0;
  b.rect[1] = y0;  // pixel rows map to GL rows one to one (see GlContext::read_pixels)
  b.rect[2] = x1 - x0;
  b.rect[3] = y1 - y0;
  b.colour = colour;
  batches_.push_back(b);
}

void Canvas::push_shape(const Shape& s) {
  if (shapes_.size() >= kMaxShapes) {
    ++dropped_;
    return;
  }
  if (batches_.empty() || batches_.back().kind != BatchKind::kShapes)
    batches_.push_back(Batch::of(BatchKind::kShapes, shapes_.size()));
  shapes_.push_back(s);
  ++batches_.back().count;
}

void Canvas::capsule(glm::vec2 a, glm::vec2 b, float radius, Rgba colour) {
  push_shape({{a.x, a.y, b.x, b.y}, {0, 0, radius, 0}, to_vec4(colour), 0.0f});
}

void Canvas::ring(glm::vec2 centre, float radius, float stroke, Rgba colour) {
  push_shape({{centre.x, centre.y, centre.x, centre.y}, {0, 0, radius, stroke}, to_vec4(colour), 0.0f});
}

void Canvas::triangle(glm::vec2 p0, glm::vec2 p1, glm::vec2 p2, Rgba colour) {
  push_shape({{p0.x, p0.y, p1.x, p1.y}, {p2.x, p2.y, 0, 0}, to_vec4(colour), 1.0f});
}

void Canvas::box(glm::vec2 min, glm::vec2 max, Rgba colour, float corner_radius) {
  push_shape({{min.x, min.y, max.x, max.y}, {0, 0, corner_radius, 0}, to_vec4(colour), 2.0f});
}

void Canvas::box_outline(glm::vec2 min, glm::vec2 max, float stroke, Rgba colour, float corner_radius) {
  push_shape({{min.x, min.y, max.x, max.y}, {0, 0, corner_radius, stroke}, to_vec4(colour), 2.0f});
}

void Canvas::polyline(const std::vector<glm::vec2>& points, float width, Rgba colour) {
  if (points.size() == 1) disc(points[0], 0.5f * width, colour);
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (shapes_.size() >= kMaxShapes) {
      dropped_ += points.size() - i;
      return;
    }
    capsule(points[i - 1], points[i], 0.5f * width, colour);
  }
}

namespace {

// The part [t0, t1] of the segment a + t d, t in [0, 1], inside the box [lo, hi] (Liang-Barsky);
// false if none of it is.
bool clip_segment(glm::dvec2 a, glm::dvec2 d, glm::dvec2 lo, glm::dvec2 hi, double& t0, double& t1) {
  t0 = 0;
  t1 = 1;
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0) {
      if (a[k] < lo[k] || a[k] > hi[k]) return false;
      continue;
    }
    double ta = (lo[k] - a[k]) / d[k], tb = (hi[k] - a[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

void Canvas::dashed_polyline(const std::vector<glm::vec2>& points, float width, float dash, float gap, Rgba colour) {
  if (!(dash > 0) || !(gap > 0)) return polyline(points, width, colour);
  // The pattern runs on across vertices so dense polylines keep an even dash rhythm. Only the
  // part of each segment on the canvas is dashed (the pattern is advanced over the rest), so a
  // segment far longer than the canvas (a zoomed-in view, a far point in a log) costs a few
  // dashes, not one per 7 px of its length; in double, so the pattern keeps its place however
  // far the segment runs.
  const double period = double(dash) + gap, margin = width + 1.0;
  const glm::dvec2 lo(-margin, -margin), hi(width_ + margin, height_ + margin);
  double phase = 0;  // distance into the current dash+gap period
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (shapes_.size() >= kMaxShapes) {  // full: the rest would only be counted as dropped
      dropped_ += points.size() - i;
      return;
    }
    const glm::dvec2 a(points[i - 1]), d = glm::dvec2(points[i]) - a;
    const double len = std::sqrt(d.x * d.x + d.y * d.y);
    if (!(len > 0) || !std::isfinite(len)) continue;
    double t0 = 0, t1 = 0;
    if (!clip_segment(a, d, lo, hi, t0, t1)) {
      phase = std::fmod(phase + len, period);
      continue;
    }
    double s = t0 * len;
    const double end = t1 * len;
    phase = std::fmod(phase + s, period);
    while (s < end) {
      const double step = std::min(end - s, phase < dash ? dash - phase : period - phase);
      if (phase < dash)
        capsule(glm::vec2(a + d * (s / len)), glm::vec2(a + d * ((s + step) / len)), 0.5f * width, colour);
      s += step;
      phase = std::fmod(phase + step, period);
    }
    phase = std::fmod(phase + (len - end), period);
  }
}

void Canvas::arrow(glm::vec2 tail, glm::vec2 head, float width, Rgba colour) {
  const glm::vec2 d = head - tail;
  const float len = std::sqrt(d.x * d.x + d.y * d.y);
  if (len < 1e-3f) return;
  const glm::vec2 dir = d / len, n(-dir.y, dir.x);
  const float head_len = std::min(len, std::max(3.5f * width, 7.0f));
  const float head_half = 0.55f * head_len;
  const glm::vec2 base = head - dir * head_len;
  if (len > head_len) capsule(tail, base + dir * (0.3f * head_len), 0.5f * width, colour);
  triangle(head, base + n * head_half, base - n * head_half, colour);
}

// Why not one distance-shaded quad per triangle like the other shapes: a quad shades its whole
// bounding box (about four times a thin trapezoid's area, and llvmpipe pays per shaded pixel: a
// 720p frame of a 763-vertex vessel network took 4.6 ms that way against 1.8 ms rasterised),
// and triangles with anti-aliased edges leave a faint seam where they meet unless each is
// dilated, which then draws the overlaps twice (wrong for translucent colours). The
// rasteriser's fill rule instead gives each pixel centre to exactly one of two triangles sharing
// an edge, so a tiling with exactly shared edges (triangulate_even_odd's) is seamless. Only the
// region's own boundary needs anti-aliasing: a zero-radius capsule on every outline edge adds
// coverage 0.5 - d to the pixels within half a pixel outside it, the analytic ramp of the edge;
// inside it the raster's full coverage makes the edge about a quarter pixel fuller on average.
// With MSAA the rasteriser anti-aliases the edge itself, and without AA there is nothing to add.
void Canvas::region(const std::vector<glm::vec2>& triangles, const std::vector<std::vector<glm::vec2>>& outline,
                    Rgba colour) {
  std::size_t n = triangles.size() - triangles.size() % 3;
  if (vertices_.size() + n > kMaxVertices) {
    dropped_ += n;
    n = 0;
  }
  if (n > 0) {
    if (batches_.empty() || batches_.back().kind != BatchKind::kRegion)
      batches_.push_back(Batch::of(BatchKind::kRegion, vertices_.size()));
    const glm::vec4 col = to_vec4(colour);
    for (std::size_t i = 0; i < n; ++i) vertices_.push_back({triangles[i], {0, 0}, col});
    batches_.back().count += n;
  }
  if (aa_ != AntiAliasing::kAnalytic) return;
  for (const auto& ring : outline)
    for (std::size_t i = 0; ring.size() >= 2 && i < ring.size() && shapes_.size() < kMaxShapes; ++i)
      capsule(ring[i], ring[(i + 1) % ring.size()], 0.0f, colour);
}

FontAtlas& Canvas::font(int pixel_height) {
  auto& f = fonts_[pixel_height];
  if (!f) f = std::make_unique<FontAtlas>(default_font_path(), pixel_height);
  return *f;
}

unsigned Canvas::font_texture(int pixel_height) {
  auto it = font_textures_.find(pixel_height);
  if (it != font_textures_.end()) return it->second;
  FontAtlas& f = font(pixel_height);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, f.atlas_width(), f.atlas_height(), 0, GL_RED, GL_UNSIGNED_BYTE,
               f.bitmap().data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  font_textures_[pixel_height] = tex;
  return tex;
}

float Canvas::text_width(const std::string& utf8, int pixel_height) {
  return font(pixel_height).layout(utf8, nullptr);
}

void Canvas::text(const std::string& utf8, glm::vec2 pos, int pixel_height, Rgba colour, TextAlign align,
                  float angle) {
  // At most one glyph per byte: a text that could not fit is dropped before it is laid out.
  if (vertices_.size() + 6 * utf8.size() > kMaxVertices) {
    dropped_ += 6 * utf8.size();
    return;
  }
  FontAtlas& f = font(pixel_height);
  std::vector<GlyphQuad> quads;
  const float advance = f.layout(utf8, &quads);
  float shift = align == TextAlign::kLeft ? 0.0f : align == TextAlign::kCenter ? -0.5f * advance : -advance;
  const float c = std::cos(angle), s = std::sin(angle);
  // Unrotated text snaps to whole pixels so glyphs are sampled texel for texel (crisp).
  if (angle == 0) {
    pos = glm::vec2(std::round(pos.x + shift), std::round(pos.y));
    shift = 0;
  }
  auto place = [&](float x, float y) {
    x += shift;
    return glm::vec2(pos.x + x * c + y * s, pos.y - x * s + y * c);
  };
  if (batches_.empty() || batches_.back().kind != BatchKind::kText || batches_.back().font_size != pixel_height)
    batches_.push_back(Batch::of(BatchKind::kText, vertices_.size(), pixel_height));
  const glm::vec4 col = to_vec4(colour);
  for (const auto& q : quads) {
    const Vertex v00{place(q.x0, q.y0), {q.s0, q.t0}, col}, v10{place(q.x1, q.y0), {q.s1, q.t0}, col};
    const Vertex v01{place(q.x0, q.y1), {q.s0, q.t1}, col}, v11{place(q.x1, q.y1), {q.s1, q.t1}, col};
    for (const auto& v : {v00, v10, v11, v00, v11, v01}) vertices_.push_back(v);
    batches_.back().count += 6;
  }
}

void Canvas::finish(std::uint8_t* rgba) {
  gl_->make_current();
  gl_->bind_draw_framebuffer();
  glViewport(0, 0, width_, height_);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  // Fonts first: creating a texture between draws would not change the result but keeps the
  // draw loop free of state changes other than program and buffer.
  for (const auto& b : batches_)
    if (b.kind == BatchKind::kText) font_texture(b.font_size);

  glBindBuffer(GL_ARRAY_BUFFER, shape_vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(shapes_.size() * sizeof(Shape)), shapes_.data(),
               GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, vertex_vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices_.size() * sizeof(Vertex)), vertices_.data(),
               GL_STREAM_DRAW);

  const auto stride = static_cast<GLsizei>(sizeof(Shape));
  for (const auto& b : batches_) {
    if (b.kind == BatchKind::kClear) {
      glEnable(GL_SCISSOR_TEST);
      glScissor(b.rect[0], b.rect[1], b.rect[2], b.rect[3]);
      glClearColor(b.colour.r, b.colour.g, b.colour.b, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      glDisable(GL_SCISSOR_TEST);
      continue;
    }
    if (b.count == 0) continue;
    if (b.kind == BatchKind::kText) {
      glUseProgram(text_program_);
      glBindVertexArray(vertex_vao_);
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D, font_textures_[b.font_size]);
      glDrawArrays(GL_TRIANGLES, static_cast<GLint>(b.first), static_cast<GLsizei>(b.count));
    } else if (b.kind == BatchKind::kRegion) {
      glUseProgram(region_program_);
      glBindVertexArray(vertex_vao_);
      glDrawArrays(GL_TRIANGLES, static_cast<GLint>(b.first), static_cast<GLsizei>(b.count));
    } else {
      glUseProgram(shape_program_);
      glBindVertexArray(shape_vao_);
      glBindBuffer(GL_ARRAY_BUFFER, shape_vbo_);
      // Point the per-instance attributes at this batch (base instance needs GL 4.2).
      const std::size_t base = b.first * sizeof(Shape);
      const GLint sizes[4] = {4, 4, 4, 1};
      const std::size_t offsets[4] = {offsetof(Shape, p), offsetof(Shape, q), offsetof(Shape, colour),
                                      offsetof(Shape, kind)};
      for (GLuint a = 0; a < 4; ++a) {
        glEnableVertexAttribArray(a);
        glVertexAttribPointer(a, sizes[a], GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(base + offsets[a]));
        glVertexAttribDivisor(a, 1);
      }
      glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(b.count));
    }
  }
  glBindVertexArray(0);
  glUseProgram(0);
  gl_->read_pixels(rgba);
  shapes_.clear();
  vertices_.clear();
  batches_.clear();
}

}  // namespace vascsim::render

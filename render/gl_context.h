// An offscreen OpenGL context through OSMesa, with one framebuffer of a fixed size that the
// canvas draws into and reads back as top-down RGBA8 rows. Optional 4x multisampling (MSAA) is
// kept for the anti-aliasing comparison in `vascsim bench render`; the renderer's default is
// analytic edge anti-aliasing in the shaders (docs/rendering.md says why).
#pragma once

#include <cstdint>
#include <string>

namespace vascsim::render {

class GlContext {
 public:
  // Creates a core-profile context (4.5, else 3.3) and a width x height framebuffer with
  // `samples` samples per pixel (0 or 1: none; at most 4 on llvmpipe). Throws std::runtime_error
  // if OSMesa cannot give a context. The context is current on the calling thread only.
  GlContext(int width, int height, int samples);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }
  // GL_VERSION and GL_RENDERER, for the benchmark report.
  std::string description() const;
  // Makes this context current on the calling thread and binds its draw framebuffer.
  void make_current();
  void bind_draw_framebuffer();
  // Resolves multisampling if any and copies the image into `rgba` (width*height*4 bytes, first
  // row at the top of the picture).
  void read_pixels(std::uint8_t* rgba);

 private:
  int width_, height_, samples_;
  void* context_ = nullptr;          // OSMesaContext
  unsigned char dummy_[16 * 16 * 4];  // OSMesa needs a bound buffer; drawing goes to our FBOs
  unsigned draw_fbo_ = 0, draw_rb_ = 0;      // multisampled (or the only) target
  unsigned resolve_fbo_ = 0, resolve_rb_ = 0;  // single-sample target when samples > 1
};

}  // namespace vascsim::render

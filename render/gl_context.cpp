#include "render/gl_context.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <stdexcept>

namespace vascsim::render {

namespace {

OSMesaContext create_context() {
  // Core profile: only the programmable pipeline, which the canvas shaders use. 4.5 lets the
  // MSAA comparison shade per sample; 3.3 is enough for everything else.
  for (int major_minor : {45, 33}) {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, major_minor / 10,
                              OSMESA_CONTEXT_MINOR_VERSION, major_minor % 10, 0};
    if (OSMesaContext c = OSMesaCreateContextAttribs(attributes, nullptr)) return c;
  }
  throw std::runtime_error("OSMesa could not create an OpenGL 3.3 core context");
}

}  // namespace

GlContext::GlContext(int width, int height, int samples)
    : width_(width), height_(height), samples_(samples > 1 ? samples : 0) {
  context_ = create_context();
  make_current();
  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (samples_ > max_samples) samples_ = max_samples;

  glGenFramebuffers(1, &draw_fbo_);
  glGenRenderbuffers(1, &draw_rb_);
  glBindRenderbuffer(GL_RENDERBUFFER, draw_rb_);
  if (samples_ > 1)
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width, height);
  else
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, draw_rb_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("OpenGL framebuffer incomplete");
  if (samples_ > 1) {
    glGenFramebuffers(1, &resolve_fbo_);
    glGenRenderbuffers(1, &resolve_rb_);
    glBindRenderbuffer(GL_RENDERBUFFER, resolve_rb_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolve_rb_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("OpenGL resolve framebuffer incomplete");
  }
  bind_draw_framebuffer();
  glViewport(0, 0, width, height);
}

GlContext::~GlContext() {
  make_current();
  glDeleteFramebuffers(1, &draw_fbo_);
  glDeleteRenderbuffers(1, &draw_rb_);
  if (resolve_fbo_) glDeleteFramebuffers(1, &resolve_fbo_);
  if (resolve_rb_) glDeleteRenderbuffers(1, &resolve_rb_);
  OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

std::string GlContext::description() const {
  auto text = [](GLenum e) {
    const GLubyte* s = glGetString(e);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return text(GL_VERSION) + ", " + text(GL_RENDERER);
}

void GlContext::make_current() {
  if (!OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), dummy_, GL_UNSIGNED_BYTE, 16, 16))
    throw std::runtime_error("OSMesaMakeCurrent failed");
}

void GlContext::bind_draw_framebuffer() { glBindFramebuffer(GL_FRAMEBUFFER, draw_fbo_); }

void GlContext::read_pixels(std::uint8_t* rgba) {
  if (samples_ > 1) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, draw_fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_);
  } else {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, draw_fbo_);
  }
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  // The canvas projection puts pixel row 0 at GL's bottom row, so GL's bottom-up read order
  // is already the top-down order image files want.
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  bind_draw_framebuffer();
}

}  // namespace vascsim::render

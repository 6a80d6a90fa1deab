#include "render/gl/gl_context.hpp"

#include <stdexcept>

#include "render/gl/drop_alpha.hpp"
#include "render/gl/gl.hpp"
#include "render/sphere_camera.hpp"

namespace sl {

GlContext::GlContext(int width, int height) : width_(width), height_(height) {
  // Asking for 3.3 core; llvmpipe answers with its newest core profile (4.5 on Debian 12).
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!context) throw std::runtime_error("OSMesa: could not create an OpenGL 3.3 core context");
  context_ = context;
  clientBuffer_.assign(4, 0);
  if (!OSMesaMakeCurrent(context, clientBuffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
    OSMesaDestroyContext(context);
    throw std::runtime_error("OSMesa: could not make the context current");
  }
  if (!glGetString(GL_VERSION)) {
    OSMesaDestroyContext(context);
    throw std::runtime_error("OpenGL: GL_VERSION is NULL (is libGL linked next to OSMesa?)");
  }
  try {
    frame_ = std::make_unique<GlLayer>(width, height);
  } catch (...) {
    OSMesaDestroyContext(context);
    throw;
  }
}

GlContext::~GlContext() {
  frame_.reset();  // GL objects go before their context
  OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

void GlContext::bindFramebuffer() const {
  if (OSMesaGetCurrentContext() != static_cast<OSMesaContext>(context_))
    throw std::logic_error("Renderer used from a thread other than the one that created it");
  frame_->bind();
}

void GlContext::readRgb(std::vector<std::uint8_t>& rgb) const {
  // Read as RGBA (a row copy in llvmpipe) and packed by dropAlpha: the driver's own GL_RGB conversion costs more.
  const std::size_t pixels = static_cast<std::size_t>(width_) * height_;
  rgb.resize(pixels * 3);
  frame_->bind();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  rgba_.resize(pixels * 4);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba_.data());
  dropAlpha(rgba_.data(), rgb.data(), pixels);
}

GlLayer::GlLayer(int width, int height) : width_(width), height_(height) {
  glGenFramebuffers(1, &framebuffer_);
  glGenRenderbuffers(1, &colorBuffer_);
  glBindRenderbuffer(GL_RENDERBUFFER, colorBuffer_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colorBuffer_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("OpenGL: offscreen framebuffer " + std::to_string(width) + "x" + std::to_string(height) +
                             " is incomplete");
}

GlLayer::~GlLayer() {
  glDeleteRenderbuffers(1, &colorBuffer_);
  glDeleteFramebuffers(1, &framebuffer_);
}

void GlLayer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width_, height_);
}

void GlLayer::copyTo(unsigned framebuffer, const PixelRect& rect) const {
  const GLint x0 = GLint(rect.x), y0 = GLint(rect.y), x1 = GLint(rect.x + rect.width), y1 = GLint(rect.y + rect.height);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  glBlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
}

unsigned GlContext::framebuffer() const { return frame_->framebuffer(); }

std::string GlContext::rendererName() const {
  const auto* name = glGetString(GL_RENDERER);
  return name ? reinterpret_cast<const char*>(name) : "";
}

std::string GlContext::version() const {
  const auto* name = glGetString(GL_VERSION);
  return name ? reinterpret_cast<const char*>(name) : "";
}

}  // namespace sl

#include "render/gl/gl_context.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "contracts/limits.hpp"

#include "render/gl/drop_alpha.hpp"
#include "render/gl/gl.hpp"
#include "render/gl/gl_platform.hpp"
#include "render/sphere_camera.hpp"

namespace sl {
namespace {
constexpr std::size_t kReadBackBandBytes = 256 * 1024;  // well inside a core's L2 (1-2 MiB on current x86)

// A GL context's set-up fails with the reason, never with a signal: under too small an address-space limit
// llvmpipe's shader compiler crashes, so the limit is checked first (limits::kMinGlAddressSpaceBytes).
void requireAddressSpace(int width, int height) {
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return;
  const double needed = limits::kMinGlAddressSpaceBytes + limits::kGlAddressSpaceBytesPerPixel * width * height;
  if (double(limit.rlim_cur) >= needed) return;
  const auto megabytes = [](double bytes) { return std::to_string(long(bytes / (1 << 20))); };
  throw GlUnavailable("the address-space limit (ulimit -v, or a batch system's memory request) is " +
                      megabytes(double(limit.rlim_cur)) + " MB; drawing " + std::to_string(width) + "x" +
                      std::to_string(height) + " frames needs at least " + megabytes(needed) +
                      " MB (Mesa's shader compiler fails below it): raise the limit");
}

}  // namespace

GlContext::GlContext(int width, int height)
    : width_(width),
      height_(height),
      context_((requireAddressSpace(width, height), makeCurrentGlContext())),
      backend_(*glBackendInUse()) {
  frame_ = std::make_unique<GlLayer>(width, height);
}

GlContext::~GlContext() {
  frame_.reset();  // GL objects go before their context
}

void GlContext::bindFramebuffer() const {
  if (!context_->isCurrent())
    throw std::logic_error("Renderer used from a thread other than the one that created it");
  frame_->bind();
}

void GlContext::readRgb(std::vector<std::uint8_t>& rgb) const {
  // Read as RGBA (a row copy in llvmpipe) and packed by dropAlpha: the driver's own GL_RGB conversion costs more.
  // In bands of rows that stay in the core's cache between the copy and the packing (a whole 720p frame would
  // be read back from memory).
  const std::size_t rowPixels = static_cast<std::size_t>(width_);
  rgb.resize(rowPixels * height_ * 3);
  frame_->bind();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  const int bandRows = std::max(1, int(kReadBackBandBytes / (rowPixels * 4)));
  rgba_.resize(rowPixels * 4 * std::min(bandRows, height_));
  for (int y = 0; y < height_; y += bandRows) {
    const int rows = std::min(bandRows, height_ - y);
    glReadPixels(0, y, width_, rows, GL_RGBA, GL_UNSIGNED_BYTE, rgba_.data());
    dropAlpha(rgba_.data(), rgb.data() + rowPixels * 3 * y, rowPixels * rows);
  }
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

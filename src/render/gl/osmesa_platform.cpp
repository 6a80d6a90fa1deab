// OSMesa: Mesa's off-screen interface, llvmpipe in the library itself. Removed from Mesa in 25.1 (EGL's software
// device draws the same bytes: egl_platform.cpp); built where Debian still ships libosmesa6.

#include "render/gl/gl.hpp"  // glad's declarations first: osmesa.h's own <GL/gl.h> then adds nothing

#include <GL/osmesa.h>

#include <vector>

#include "render/gl/gl_platform.hpp"

namespace sl {
namespace {

class OsMesaContext final : public GlPlatformContext {
 public:
  OsMesaContext() {
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
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) throw GlUnavailable("osmesa: could not create an OpenGL 3.3 core context");
    // OSMesaMakeCurrent needs a buffer; the frames are drawn into framebuffer objects, so 1x1 is enough.
    if (!OSMesaMakeCurrent(context_, clientBuffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      OSMesaDestroyContext(context_);
      throw GlUnavailable("osmesa: could not make the context current");
    }
  }
  ~OsMesaContext() override { OSMesaDestroyContext(context_); }
  bool isCurrent() const override { return OSMesaGetCurrentContext() == context_; }
  void (*procAddress(const char* name) const)() override { return OSMesaGetProcAddress(name); }

 private:
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> clientBuffer_ = std::vector<unsigned char>(4, 0);
};

}  // namespace

std::unique_ptr<GlPlatformContext> makeOsMesaContext() { return std::make_unique<OsMesaContext>(); }

}  // namespace sl

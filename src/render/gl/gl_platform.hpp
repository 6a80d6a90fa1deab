#pragma once
// A GL context made current on this thread without a window or a surface; it draws into framebuffer objects only
// (gl_context.hpp). One class per backend (egl_platform.cpp, osmesa_platform.cpp), each built only where its
// library is; gl_backend.cpp chooses among them and loads the GL entry points from the first.

#include <memory>

#include "render/gl_backend.hpp"

namespace sl {

class GlPlatformContext {
 public:
  virtual ~GlPlatformContext() = default;
  virtual bool isCurrent() const = 0;
  // The address of a GL function of this backend (glad's loader asks for each).
  virtual void (*procAddress(const char* name) const)() = 0;
};

// A current OpenGL 3.3 core context of the process's backend (requestGlBackend). Throws GlUnavailable.
std::unique_ptr<GlPlatformContext> makeCurrentGlContext();

// Each backend's own maker, throwing GlUnavailable; declared whether built or not, defined only where built.
std::unique_ptr<GlPlatformContext> makeEglContext(bool gpu);
std::unique_ptr<GlPlatformContext> makeOsMesaContext();

}  // namespace sl

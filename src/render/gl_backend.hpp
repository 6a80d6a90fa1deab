#pragma once
// Which OpenGL backend draws this process's frames (docs/rendering.md, "GL backends"): EGL without a display on
// Mesa's software device, EGL on a GPU, or OSMesa. The GL entry points are loaded once per process, from the
// backend that makes the first context, so the choice is the process's: made once at the command line's edge
// (--gl, LINKAGE_GL) before the first Renderer, and every Renderer after it draws through the same backend.

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "contracts/registry.hpp"

namespace sl {

// A backend that cannot start here (not built in, no such device, the driver refused): what() says why.
class GlUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The backends this binary was built with, in kGlBackends' order (Auto, when any is).
std::vector<GlBackend> builtGlBackends();

// Asks for `backend` for this process's renderers (Auto, the default: EGL's software device, else OSMesa).
// Throws GlUnavailable if the binary was built without it, std::logic_error once a context of another backend
// exists.
void requestGlBackend(GlBackend backend);

// The backend this process draws through, once its first context exists (nullopt before).
std::optional<GlBackend> glBackendInUse();
// Why Auto did not take EGL (empty when it did, or when Auto was not asked for).
std::string glFallbackReason();

// What llvmpipe's generated code depends on besides Mesa's version: the machine's architecture and the vector
// extensions it may use (e.g. "x86-64 sse4.1 sse4.2 avx f16c fma avx2"), as the CPU reports them.
std::string llvmpipeCpuFeatures();

}  // namespace sl

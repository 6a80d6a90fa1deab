// The process's GL backend: what was asked for, what was built, and the one that made the first context. glad's
// entry points are process-wide, so the first context decides and every later one must be of the same backend.

#include <mutex>
#include <string>

#include "render/gl/gl.hpp"
#include "render/gl/gl_platform.hpp"

namespace sl {
namespace {

struct Selection {
  std::mutex mutex;
  GlBackend requested = GlBackend::Auto;
  std::optional<GlBackend> inUse;  // set with the first context, which loaded glad's entry points
  std::string fallbackReason;
};
Selection& selection() {
  static Selection s;
  return s;
}

constexpr bool kBuilt[] = {
    true,  // Auto
#ifdef SL_HAVE_EGL
    true, true,  // Egl, EglGpu
#else
    false, false,
#endif
#ifdef SL_HAVE_OSMESA
    true,
#else
    false,
#endif
};
bool built(GlBackend backend) { return kBuilt[static_cast<int>(backend)]; }
GlUnavailable notBuilt(GlBackend backend) { return GlUnavailable("this linkage was built without " + nameOf(backend)); }

}  // namespace

// A backend not built has a maker that says so (never called: built() is asked first).
#ifndef SL_HAVE_EGL
std::unique_ptr<GlPlatformContext> makeEglContext(bool) { throw notBuilt(GlBackend::Egl); }
#endif
#ifndef SL_HAVE_OSMESA
std::unique_ptr<GlPlatformContext> makeOsMesaContext() { throw notBuilt(GlBackend::OsMesa); }
#endif

namespace {

std::unique_ptr<GlPlatformContext> makeContextOf(GlBackend backend) {
  if (!built(backend)) throw notBuilt(backend);
  switch (backend) {
    case GlBackend::Egl:
      return makeEglContext(false);
    case GlBackend::EglGpu:
      return makeEglContext(true);
    case GlBackend::OsMesa:
      return makeOsMesaContext();
    case GlBackend::Auto:
      break;
  }
  throw std::logic_error("makeContextOf: Auto is resolved by the caller");
}

// glad asks the current context's backend for each entry point.
thread_local const GlPlatformContext* loading = nullptr;
GLADapiproc loadProc(const char* name) { return loading->procAddress(name); }

}  // namespace

std::vector<GlBackend> builtGlBackends() {
  std::vector<GlBackend> backends;
  for (const auto& b : kGlBackends)
    if (built(b.kind) && (b.kind != GlBackend::Auto || built(GlBackend::Egl) || built(GlBackend::OsMesa)))
      backends.push_back(b.kind);
  return backends;
}

void requestGlBackend(GlBackend backend) {
  Selection& s = selection();
  const std::lock_guard lock(s.mutex);
  if (!built(backend)) throw notBuilt(backend);
  if (s.inUse && backend != GlBackend::Auto && backend != *s.inUse)
    throw std::logic_error("this process already draws through " + nameOf(*s.inUse) + "; cannot switch to " +
                           nameOf(backend));
  s.requested = backend;
}

std::optional<GlBackend> glBackendInUse() {
  Selection& s = selection();
  const std::lock_guard lock(s.mutex);
  return s.inUse;
}

std::string glFallbackReason() {
  Selection& s = selection();
  const std::lock_guard lock(s.mutex);
  return s.fallbackReason;
}

std::unique_ptr<GlPlatformContext> makeCurrentGlContext() {
  Selection& s = selection();
  const std::lock_guard lock(s.mutex);
  if (s.inUse) return makeContextOf(*s.inUse);

  GlBackend backend = s.requested;
  std::unique_ptr<GlPlatformContext> context;
  if (backend == GlBackend::Auto) {
    // EGL's software device first (the same llvmpipe as OSMesa, and the backend that outlives OSMesa), OSMesa
    // where EGL cannot start (no libegl-mesa0, an EGL without device enumeration). Never a GPU: see kGlBackends.
    std::string eglError = notBuilt(GlBackend::Egl).what();
    if (built(GlBackend::Egl)) {
      try {
        context = makeEglContext(false);
        backend = GlBackend::Egl;
      } catch (const GlUnavailable& error) {
        eglError = error.what();
      }
    }
    if (!context) {
      if (!built(GlBackend::OsMesa)) throw GlUnavailable(eglError + "; and " + notBuilt(GlBackend::OsMesa).what());
      try {
        context = makeOsMesaContext();
      } catch (const GlUnavailable& error) {
        throw GlUnavailable(eglError + "; " + error.what());
      }
      backend = GlBackend::OsMesa;
      s.fallbackReason = eglError;
    }
  } else {
    context = makeContextOf(backend);
  }
  loading = context.get();
  const int version = gladLoadGL(loadProc);
  loading = nullptr;
  if (version == 0 || glGetString == nullptr || glGetString(GL_VERSION) == nullptr)
    throw GlUnavailable(nameOf(backend) + ": the OpenGL entry points could not be loaded");
  if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33)
    throw GlUnavailable(nameOf(backend) + ": OpenGL " + std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                        std::to_string(GLAD_VERSION_MINOR(version)) + "; the renderer needs 3.3 core");
  s.inUse = backend;
  return context;
}

std::string llvmpipeCpuFeatures() {
#if defined(__x86_64__) || defined(__i386__)
  std::string features = "x86-64";
  // The extensions gallivm (Mesa 22.3) hands to LLVM's code generator whose absence changes llvmpipe's pixels
  // (docs/rendering.md, "Across machines"): without SSSE3 (its 8-bit blends round instead of truncating) up to 18%
  // of a frame's pixels differ, mostly by 1-3 levels; without AVX (and so FMA, F16C, AVX2) up to 0.1%, by a level
  // (a few edge pixels by up to 20). AVX-512 changes nothing in this Mesa (its vectors stay 256 bits; the vector
  // width is in GL_RENDERER), so it is left out: nodes with and without it draw the same bytes and may share a render.
  __builtin_cpu_init();
  const std::pair<const char*, bool> flags[] = {
      {"ssse3", __builtin_cpu_supports("ssse3")}, {"sse4.1", __builtin_cpu_supports("sse4.1")},
      {"avx", __builtin_cpu_supports("avx")},     {"f16c", __builtin_cpu_supports("f16c")},
      {"fma", __builtin_cpu_supports("fma")},     {"avx2", __builtin_cpu_supports("avx2")},
  };
  for (const auto& [name, present] : flags)
    if (present) features += std::string(" ") + name;
  return features;
#elif defined(__aarch64__)
  return "aarch64";
#else
  return "unknown architecture";
#endif
}

}  // namespace sl

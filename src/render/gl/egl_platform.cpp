// EGL without a display or a surface (EGL_EXT_platform_device, EGL_KHR_surfaceless_context): a context on one of
// EGL's devices, drawing into framebuffer objects only. Mesa's software device (EGL_MESA_device_software) is
// llvmpipe, the same as OSMesa's, and gives the same bytes; a GPU device is used only when asked for (egl-gpu).
// The device is picked by its extensions, not by EGL's surfaceless platform, which takes a GPU when it finds one.

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <optional>
#include <mutex>
#include <string>
#include <vector>

#include "render/gl/gl_platform.hpp"

namespace sl {
namespace {

bool hasExtension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t length = std::strlen(name);
  for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + 1, name))
    if ((p == list || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0')) return true;
  return false;
}

std::string eglErrorText() {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(eglGetError()));
  return std::string("EGL error ") + code;
}

template <class Function>
Function entryPoint(const char* name) {
  auto* function = reinterpret_cast<Function>(eglGetProcAddress(name));
  if (!function) throw GlUnavailable(std::string("egl: no ") + name);
  return function;
}

// A display on the first software device (gpu: the first other device), initialised once per process and never
// terminated: every context of the process shares it, on whichever thread draws.
struct Device {
  EGLDisplay display = EGL_NO_DISPLAY;
  bool noConfigContext = false;
};

Device openDevice(bool gpu) {
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  for (const char* needed : {"EGL_EXT_device_enumeration", "EGL_EXT_platform_device"})
    if (!hasExtension(clientExtensions, needed))
      throw GlUnavailable(std::string("egl: this EGL has no ") + needed + " (is libegl1 from libglvnd installed?)");
  const auto queryDevices = entryPoint<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  const auto queryDeviceString = entryPoint<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  const auto platformDisplay = entryPoint<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");

  EGLint count = 0;
  std::vector<EGLDeviceEXT> devices(16);
  if (!queryDevices(EGLint(devices.size()), devices.data(), &count) || count <= 0)
    throw GlUnavailable("egl: no devices (" + eglErrorText() + "; is libegl-mesa0 installed?)");
  for (EGLint i = 0; i < count; ++i) {
    const bool software = hasExtension(queryDeviceString(devices[i], EGL_EXTENSIONS), "EGL_MESA_device_software");
    if (software == gpu) continue;
    Device device;
    device.display = platformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
    EGLint major = 0, minor = 0;
    if (device.display == EGL_NO_DISPLAY || !eglInitialize(device.display, &major, &minor)) continue;
    const char* extensions = eglQueryString(device.display, EGL_EXTENSIONS);
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context")) continue;
    device.noConfigContext = hasExtension(extensions, "EGL_KHR_no_config_context");
    return device;
  }
  throw GlUnavailable(gpu ? "egl-gpu: none of EGL's " + std::to_string(count) +
                                " devices is a GPU that can draw without a surface (is its driver installed?)"
                          : "egl: none of EGL's " + std::to_string(count) +
                                " devices is Mesa's software device (is libegl-mesa0 installed?)");
}

const Device& device(bool gpu) {
  static std::mutex mutex;
  static std::optional<Device> opened[2];
  static std::string failed[2];
  const std::lock_guard lock(mutex);
  auto& slot = opened[gpu ? 1 : 0];
  if (!slot) {
    if (!failed[gpu ? 1 : 0].empty()) throw GlUnavailable(failed[gpu ? 1 : 0]);
    try {
      slot = openDevice(gpu);
    } catch (const GlUnavailable& error) {
      failed[gpu ? 1 : 0] = error.what();
      throw;
    }
  }
  return *slot;
}

class EglContext final : public GlPlatformContext {
 public:
  explicit EglContext(bool gpu) : display_(device(gpu).display) {
    // The client API is per thread, and EGL's default is OpenGL ES.
    if (!eglBindAPI(EGL_OPENGL_API)) throw GlUnavailable("egl: desktop OpenGL unavailable (" + eglErrorText() + ")");
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!device(gpu).noConfigContext) {
      const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
      EGLint found = 0;
      if (!eglChooseConfig(display_, wanted, &config, 1, &found) || found < 1)
        throw GlUnavailable("egl: no configuration for desktop OpenGL (" + eglErrorText() + ")");
    }
    // 3.3 core asked for; llvmpipe answers with its newest core profile (4.5 on Debian 12), as OSMesa does.
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, attributes);
    if (context_ == EGL_NO_CONTEXT)
      throw GlUnavailable("egl: could not create an OpenGL 3.3 core context (" + eglErrorText() + ")");
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      const std::string why = eglErrorText();
      eglDestroyContext(display_, context_);
      throw GlUnavailable("egl: could not make the context current (" + why + ")");
    }
  }
  ~EglContext() override {
    if (isCurrent()) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
  }
  bool isCurrent() const override { return eglGetCurrentContext() == context_; }
  void (*procAddress(const char* name) const)() override { return eglGetProcAddress(name); }

 private:
  EGLDisplay display_;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlPlatformContext> makeEglContext(bool gpu) { return std::make_unique<EglContext>(gpu); }

}  // namespace sl

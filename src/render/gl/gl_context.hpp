#pragma once
// A headless OpenGL core context (of the process's backend: gl_platform.hpp) with an offscreen RGBA framebuffer
// object.
// The context is current on the thread that created it; draw and read back on that thread only.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "contracts/registry.hpp"

namespace sl {

struct PixelRect;
class GlPlatformContext;

// An offscreen RGBA8 framebuffer of the frame's size: the frame, and cached layers.
class GlLayer {
 public:
  GlLayer(int width, int height);
  ~GlLayer();
  GlLayer(const GlLayer&) = delete;
  GlLayer& operator=(const GlLayer&) = delete;

  void bind() const;
  unsigned framebuffer() const { return framebuffer_; }
  // Copies a rectangle (pixels, y down = GL rows) into the same place of another framebuffer.
  void copyTo(unsigned framebuffer, const PixelRect& rect) const;

 private:
  int width_, height_;
  unsigned framebuffer_ = 0, colorBuffer_ = 0;
};

class GlContext {
 public:
  GlContext(int width, int height);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Binds the framebuffer and the full viewport. Throws if the context is not current any more.
  void bindFramebuffer() const;
  // Reads the framebuffer as RGB rows. Rows come out in GL order (row 0 = y 0); the renderer draws
  // with y pointing down, so row 0 is the top of the image and no flip is needed.
  void readRgb(std::vector<std::uint8_t>& rgb) const;

  unsigned framebuffer() const;
  int width() const { return width_; }
  int height() const { return height_; }
  std::string rendererName() const;
  std::string version() const;
  GlBackend backend() const { return backend_; }

 private:
  int width_, height_;
  std::unique_ptr<GlPlatformContext> context_;
  GlBackend backend_;
  std::unique_ptr<GlLayer> frame_;          // the frame itself
  mutable std::vector<std::uint8_t> rgba_;  // readRgb: the framebuffer as read, before its alpha is dropped
};

}  // namespace sl

#pragma once
// The renderer: FrameState in, RGB pixels out. Knows panels, shaders and OpenGL (EGL or OSMesa); knows
// nothing of integrators or scenes: it sees only the contracts (frame state, view settings, image).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contracts/frame_state.hpp"
#include "contracts/image.hpp"
#include "contracts/view_settings.hpp"

namespace sl {

class Renderer {
 public:
  // Throws std::invalid_argument for a size outside contracts/limits.hpp. `shaderFolder`, when not empty, is read
  // for the shaders instead of the ones built in.
  Renderer(const ViewSettings& view, ImageSize size, const std::string& shaderFolder = "");
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Draws one frame. Deterministic: the same FrameState gives the same bytes, whatever came before.
  Image render(const FrameState& frame);
  // The same into `image`, reusing its buffer where it has the size (ImageRecycler).
  void render(const FrameState& frame, Image& image);

  std::string glRenderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string glVersion() const;   // GL_VERSION

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sl

#pragma once
// The renderer: FrameState in, RGB pixels out. Knows panels, shaders and OpenGL (OSMesa); knows
// nothing of integrators or scenes. Contract shared with frames/ and cli/; render/ owns the implementation.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frames/frame_state.hpp"

namespace sl {

enum class PanelKind { Linkage, Sphere, Plot, Text };

struct PanelSpec {
  PanelKind kind = PanelKind::Sphere;
  // Placement in the frame as fractions [x, y, width, height] from the top-left; empty = automatic layout.
  std::optional<std::array<double, 4>> rect;
  int plotIndex = 0;  // for Plot panels: which FrameState::plots entry to draw
};

struct CameraSpec {
  Vec3 viewDirection{1.0, 0.6, 0.5};  // from the sphere's centre towards the eye
  double orbitDegreesPerSecond = 0;   // slow orbit about the vertical axis; 0 = fixed camera
  double fieldOfViewDegrees = 30;
};

enum class LinkageLayout { SingleRun, SideBySide, Overlay };

struct RenderSettings {
  int width = 1280, height = 720;
  std::vector<PanelSpec> panels;  // layout order
  CameraSpec camera;
  LinkageLayout linkageLayout = LinkageLayout::SingleRun;
  int linkageRun = 0;          // for SingleRun
  double pathFadeSeconds = 0;  // 0 = the path never fades
  double trailFadeSeconds = 2;
  ColorRGB background{0.96f, 0.95f, 0.92f};
  std::string resourceDir;  // folder holding shaders/ and fonts (default: the source tree)
  bool antialias = true;
};

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width*height*3 bytes, rows top-down
};

class Renderer {
 public:
  explicit Renderer(const RenderSettings& settings);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Draws one frame. Deterministic: the same FrameState gives the same bytes, whatever came before.
  Image render(const FrameState& frame);

  std::string glRenderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string glVersion() const;   // GL_VERSION
  static int maxSize();            // largest width or height this renderer supports

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sl

#pragma once
// What a scene says about the picture: panels, camera, linkage layout, fades, plots. Read by the scene
// loader, used by the frame builder (plots, trails, path sampling) and by the renderer (everything else).
// The frame size is the output's (output_settings.hpp).

#include <array>
#include <optional>
#include <vector>

#include "contracts/registry.hpp"
#include "contracts/values.hpp"

namespace sl {

struct PanelSpec {
  PanelKind kind = PanelKind::Sphere;
  // Placement in the frame as fractions [x, y, width, height] from the top-left; empty = automatic layout.
  std::optional<std::array<double, 4>> rect;
  int plotIndex = 0;  // for Plot panels: which FrameState::plots entry to draw
};

struct CameraSpec {
  // Directed: the frames stage plans a direction per frame (FrameState::cameraDirection); the renderer uses it.
  CameraMode mode = CameraMode::Directed;
  Vec3 viewDirection{1.0, 0.6, 0.5};  // from the sphere's centre towards the eye (fixed and orbit; directed: the ball)
  double orbitDegreesPerSecond = 0;   // slow orbit about the vertical axis (orbit mode); 0 = fixed camera
  double fieldOfViewDegrees = 30;
};

// One plot panel: what it shows and how.
struct PlotSpec {
  PlotKind kind = PlotKind::Divergence;
  bool logY = true;
  std::optional<std::array<double, 2>> yRange;  // by hand; default: the data of the whole animation
};

// The sphere panel's surface (4 rods only): colour by a geometric quantity, stiffness ellipses on top.
struct SphereSurfaceSpec {
  SphereColoring colorBy = SphereColoring::None;
  bool stiffness = false;
  bool seam = false;  // the seams t = +-pi/2 drawn and named
  bool closedGeodesics = false;  // the simple closed geodesics drawn faintly (inverse/periodic.hpp)
  bool holonomy = false;  // a vector carried round a geodesic polygon (the scene's view.sphere.holonomy corners)
  bool decorated() const {
    return colorBy != SphereColoring::None || stiffness || seam || closedGeodesics || holonomy;
  }
};

// The page each theme draws on, unless the scene names its own background.
constexpr ColorRGB themeBackground(Theme theme) {
  return theme == Theme::Dark ? ColorRGB{0.11f, 0.12f, 0.14f} : ColorRGB{0.96f, 0.95f, 0.92f};
}

struct ViewSettings {
  std::vector<PanelSpec> panels;  // layout order; empty = sphere + linkage + text
  CameraSpec camera;
  SphereSurfaceSpec sphereSurface;
  LinkageLayout linkageLayout = LinkageLayout::SingleRun;
  int linkageRun = 0;          // for SingleRun
  double pathFadeSeconds = 0;  // 0 = the path never fades
  double trailFadeSeconds = 2;
  Theme theme = Theme::Light;
  ColorRGB background = themeBackground(Theme::Light);  // view.background, else the theme's
  bool antialias = true;
  // Without a text panel, the scene's title and the time on a line across the top of the frame.
  bool titleLine = true;

  std::vector<PlotSpec> plots;   // one per Plot panel, in layout order (PanelSpec::plotIndex)
  std::vector<int> trailHinges;  // 1-based hinge numbers with fading trails
  int pathSamplesPerFrame = 4;   // sphere-path points recorded per frame interval
};

}  // namespace sl

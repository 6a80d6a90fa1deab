#pragma once
// A frame as the CPU part of the renderer describes it: per panel, its pixel rectangle, its shapes, and
// for a sphere panel the impostor sphere drawn under them. The GL part (render/gl/) only executes this,
// so everything about layout, text and panels is testable without a GL context.

#include <memory>
#include <optional>
#include <vector>

#include "contracts/frame_state.hpp"
#include "contracts/image.hpp"
#include "contracts/values.hpp"
#include "render/shape_batch.hpp"
#include "render/sphere_camera.hpp"

namespace sl::render {

// How the unit sphere of a sphere panel is shaded: opaque with the chart grid (4 rods), glass (the ball
// of 5+ rods, the circle of 3), or opaque and coloured by DrawList::sphereField (4 rods, view.sphere.color_by).
enum class SphereLook { Opaque = 0, Glass = 1, Colored = 2 };

// The sphere a sphere panel draws by ray casting (shaders/sphere.frag), seen by the panel's camera.
struct SphereImpostor {
  SphereCamera camera;
  SphereLook look;
};

struct PanelDrawing {
  PixelRect rect;
  ShapeBatch shapes;                     // drawn in order, after the sphere
  std::optional<SphereImpostor> sphere;  // sphere panels only
};

struct DrawList {
  ImageSize size;
  ColorRGB background;
  bool antialias = true;
  // The sphere looks the same in every frame (fixed camera): a backend may draw it once and reuse it.
  bool sphereIsStatic = true;
  ViewSpace viewSpace = ViewSpace::Sphere;  // the sphere's look follows it
  // For SphereLook::Colored: the field whose colours (render/color_map.hpp) cover the sphere; shared with the
  // frame state, the same object in every frame of a render.
  std::shared_ptr<const SphereDecoration> sphereDecoration;
  std::vector<PanelDrawing> panels;         // in layout order
};

}  // namespace sl::render

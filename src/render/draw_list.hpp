#pragma once
// A frame as the CPU part of the renderer describes it: per panel, its pixel rectangle, its shapes, and
// for a sphere panel the impostor sphere drawn under them. The GL part (render/gl/) only executes this,
// so everything about layout, text and panels is testable without a GL context.

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "contracts/frame_state.hpp"
#include "contracts/image.hpp"
#include "contracts/values.hpp"
#include "render/shape_batch.hpp"
#include "render/sphere_camera.hpp"

namespace sl {

// How the unit sphere of a sphere panel is shaded: opaque with the chart grid (4 rods), glass (the ball
// of 5+ rods, the circle of 3), or opaque and coloured by DrawList::sphereField (4 rods, view.sphere.color_by).
enum class SphereLook { Opaque = 0, Glass = 1, Colored = 2 };

// The sphere a sphere panel draws by ray casting (shaders/sphere.frag), seen by the panel's camera.
struct SphereImpostor {
  SphereCamera camera;
  SphereLook look;
  std::vector<PixelRect> labels;  // the boxes of the labels placed on the sphere (poles, seams)
  std::vector<PixelRect> balls;   // the boxes kept free around the runs' balls
  std::vector<std::array<P2, 2>> leaders;  // the leader lines (from, to) of labels placed away from their anchors
  PixelRect colorBar{};           // the colour bar's strip (ticks, caption and note included); empty without one
};

struct PanelDrawing {
  PixelRect rect;
  ShapeBatch shapes;                     // drawn in order, after the sphere
  std::optional<SphereImpostor> sphere;  // sphere panels only
};

// The frame's unit of length: pixels per 720 px of its shorter side. Every line width, marker, glyph and gap is a
// multiple of it, so a frame at any size is the same picture (1 at 1280x720, 3 at 3840x2160, 0.25 at 320x180).
inline float frameUnit(ImageSize size) { return float(size.width < size.height ? size.width : size.height) / 720.0f; }
// The unit of the smallest size a mark (a pin, a ball, a start cross) may have: frameUnit, but never below 720p's,
// so that small frames keep their marks legible (lines there thin with the frame).
inline float markUnit(float unit) { return unit > 1.0f ? unit : 1.0f; }

struct DrawList {
  ImageSize size;
  ColorRGB background;
  bool antialias = true;
  // The sphere looks the same in every frame with the same camera (none orbits): a backend may draw it once and
  // reuse it while the camera stays (a directed camera at rest keeps its direction bit for bit).
  bool sphereIsStatic = true;
  ViewSpace viewSpace = ViewSpace::Sphere;  // the sphere's look follows it
  // For SphereLook::Colored: the field whose colours (render/color_map.hpp) cover the sphere; shared with the
  // frame state, the same object in every frame of a render.
  std::shared_ptr<const SphereDecoration> sphereDecoration;
  std::vector<PanelDrawing> panels;         // in layout order
};

}  // namespace sl

#pragma once
// The four panel kinds. Each turns a FrameState into shapes inside its pixel rectangle; the sphere
// panel also returns its camera and how the sphere itself is drawn (by the impostor shader).

#include <optional>

#include "contracts/frame_state.hpp"
#include "contracts/view_settings.hpp"
#include "render/draw_list.hpp"
#include "render/font_atlas.hpp"
#include "render/shape_batch.hpp"
#include "render/sphere_camera.hpp"

namespace sl::render {

struct PanelContext {
  const FrameState& frame;
  const ViewSettings& settings;
  const FontAtlas& font;
  PixelRect rect;
};

void drawLinkagePanel(const PanelContext& context, ShapeBatch& batch);
SphereImpostor drawSpherePanel(const PanelContext& context, ShapeBatch& batch);
void drawPlotPanel(const PanelContext& context, int plotIndex, ShapeBatch& batch);
void drawTextPanel(const PanelContext& context, ShapeBatch& batch);

// Run colour of the frame state as a shape colour.
inline Rgba toRgba(const ColorRGB& c, float alpha = 1) { return {c.r, c.g, c.b, alpha}; }

}  // namespace sl::render

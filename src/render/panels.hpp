#pragma once
// The four panel kinds. Each turns a FrameState into shapes inside its pixel rectangle; the sphere
// panel also returns its camera and how the sphere itself is drawn (by the impostor shader).

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "contracts/frame_state.hpp"
#include "contracts/view_settings.hpp"
#include "render/draw_list.hpp"
#include "render/font_atlas.hpp"
#include "render/palette.hpp"
#include "render/shape_batch.hpp"
#include "render/sphere_camera.hpp"

namespace sl {

struct PanelContext {
  const FrameState& frame;
  const ViewSettings& settings;
  const FontAtlas& font;
  PixelRect rect;
  float unit;  // frameUnit: pixels per 720 px of the frame's shorter side
  // The ink of what is drawn on the background (text, axes, labels), by view.theme.
  const palette::PageInk& page() const { return palette::pageInk(settings.theme); }
};

void drawLinkagePanel(const PanelContext& context, ShapeBatch& batch);
SphereImpostor drawSpherePanel(const PanelContext& context, ShapeBatch& batch);
void drawPlotPanel(const PanelContext& context, int plotIndex, ShapeBatch& batch);

// Where a plot panel puts its parts (render/plot_panel.cpp), in pixels: the title's baseline, the legend's first
// baseline and left end (beside the title or in rows of its own below it; `legendShown` false when it does not fit),
// the bottom of the legend's last row, and the plot area, which nothing but the data and its grid covers.
struct PlotLayout {
  TextSize titleSize;
  std::string title;  // fitted to the panel
  float titleBaseline;
  bool legendShown;
  float legendX, legendRight, legendBaseline, legendBottom;
  int legendRows;  // at most this many rows (1 beside the title, 2 below it)
  float areaX0, areaY0, areaX1, areaY1;
  int yTicks;      // at most this many labelled y ticks: what the area's height has room for
  bool valueLabelShown;       // the y axis's name and unit, above its top tick label (not in a compact panel)
  float valueLabelBaseline;
  bool areaShown;  // false when the panel has room for the title only
};
PlotLayout layoutPlot(const PanelContext& context, const PlotFrame& plot);  // titled by render/frame_words.hpp
// With its title's forms, longest first (render/frame_words.hpp's fittedForm picks one).
PlotLayout layoutPlot(const PanelContext& context, const PlotFrame& plot, const std::vector<std::string>& titles);
void drawTextPanel(const PanelContext& context, ShapeBatch& batch);
// The title and the time across the top of the frame (context.rect: the whole frame), for layouts without a text
// panel (ViewSettings::titleLine).
void drawTitleLine(const PanelContext& context, ShapeBatch& batch);
// The line kept under each side-by-side linkage for its run's name (linkage_panel.cpp).
inline float captionHeight(const FontAtlas& font) { return 1.3f * font.lineHeight(TextSize::Small); }
// The height of that line's band (the layout keeps it free).
inline float titleLineHeight(const FontAtlas& font) { return std::ceil(1.3f * font.lineHeight(TextSize::Normal)); }

// Run colour of the frame state as a shape colour.
inline Rgba toRgba(const ColorRGB& c, float alpha = 1) { return {c.r, c.g, c.b, alpha}; }

// The line style of run k of `count` beside its colour: its width relative to the first run's, narrowing from 1
// to 0.45, so that coinciding runs nest (paths on the sphere, linkage outlines in overlay) and each stays visible.
inline float runStyleWidth(std::size_t k, std::size_t count) {
  return count > 1 ? 1.0f - 0.55f * float(k) / float(count - 1) : 1.0f;
}

// Member m of a family of `count`: the run's colour ramped from darker (first member) to lighter (last), so the
// order of the members, and so the wavefront's orientation, can be read off the picture.
inline Rgba memberColor(const ColorRGB& c, std::size_t m, std::size_t count, float alpha = 1) {
  const float u = count > 1 ? float(m) / float(count - 1) : 0.5f;
  const float dark = 0.55f, light = 0.55f;  // at the ends: 55% of the colour, or 55% of the way to white
  auto ramp = [&](float x) { return u < 0.5f ? x * (1 - dark * (1 - 2 * u)) : x + (1 - x) * light * (2 * u - 1); };
  return {ramp(c.r), ramp(c.g), ramp(c.b), alpha};
}

}  // namespace sl

// The linkage panel: the chain in its plane, drawn as lit 2D shapes (silver rods as cylinders, joints
// as balls), the two pins as charcoal bolts on a floor line, and fading trails of chosen hinges.
// The view is fixed per scene (from n and the runs' L alone), so the picture never jumps as the chain moves.

#include <algorithm>
#include <cmath>

#include "render/palette.hpp"
#include "render/panels.hpp"
#include "render/plane_view.hpp"

namespace sl {
namespace {

void drawFloor(const PlaneView& view, double base, float rod, float unit, ShapeBatch& batch) {
  batch.capsule(view(0, 0), view(base, 0), std::max(unit, 0.25f * rod), palette::floorGrey);
  for (double pin : {0.0, base}) {  // ground hatching under each pin
    for (int k = -2; k <= 2; ++k) {
      const P2 top = view(pin + 0.06 * k, -0.02);
      batch.capsule(top, {top.x - 0.8f * rod, top.y + 1.6f * rod}, std::max(0.6f * unit, 0.12f * rod), palette::floorGrey);
    }
  }
}

// The pin at the origin, the hinges, the pin at (L, 0), on screen; a broken state's hinges are not drawn.
std::vector<P2> chainJoints(const std::vector<Vec2>& hinges, const PlaneView& view, double base) {
  std::vector<P2> joints{view(0, 0)};
  for (const Vec2& h : hinges)
    if (std::isfinite(h.x) && std::isfinite(h.y)) joints.push_back(view(h));
  joints.push_back(view(base, 0));
  return joints;
}

void drawTrails(const RunFrame& run, const PlaneView& view, float rod, float unit, ShapeBatch& batch) {
  for (const auto& trail : run.trails) {
    std::vector<PolylinePoint> points;
    for (std::size_t i = 0; i < trail.size(); ++i) {
      if (!std::isfinite(trail[i].x) || !std::isfinite(trail[i].y)) continue;
      const float age = trail.size() > 1 ? float(i) / float(trail.size() - 1) : 1.0f;  // oldest first
      points.push_back({view(trail[i]), std::max(0.8f * unit, 0.22f * rod), toRgba(run.color, 0.75f * age), {}});
    }
    batch.polyline(points);
  }
}

void drawChain(const RunFrame& run, const PlaneView& view, double base, float rod, float outline, float unit,
               ShapeBatch& batch) {
  const std::vector<P2> joints = chainJoints(run.hinges, view, base);
  // Joints as balls while a rod is long enough on screen to show them apart (8 px at 720p); a long chain's hinges
  // would only blot it, and its rods, hairlines then, are drawn in the run's colour to stand out.
  const bool jointsApart = view.scale >= 8 * unit;
  const Rgba rodColor = jointsApart ? palette::silver : toRgba(run.color);
  // In overlay, each run's rods sit on an outline of its colour, narrower for each later run: runs that coincide
  // show as nested rings of their colours around the silver.
  if (outline > 0)
    for (std::size_t k = 0; k + 1 < joints.size(); ++k)
      batch.capsule(joints[k], joints[k + 1], rod + outline, toRgba(run.color));
  for (std::size_t k = 0; k + 1 < joints.size(); ++k)
    batch.capsule(joints[k], joints[k + 1], rod, rodColor, jointsApart, 0.6f);
  for (std::size_t k = 1; jointsApart && k + 1 < joints.size(); ++k) {
    batch.disc(joints[k], 1.75f * rod, palette::jointSilver, true, 0.5f);
    batch.disc(joints[k], 0.85f * rod, toRgba(run.color), true, 0.4f);
  }
  const float pinRadius = std::max(2.2f * rod, 3.3f * markUnit(unit));  // the pins stay visible however long the chain
  for (const P2& pin : {joints.front(), joints.back()}) {
    batch.disc(pin, pinRadius, palette::pinCharcoal, true, 0.3f);
    batch.disc(pin, pinRadius * (0.7f / 2.2f), palette::silver);
  }
}

// The family's "feather": every member's chain as thin faint rods in the run's colour ramp, under the run's own.
void drawFeather(const RunFrame& run, const PlaneView& view, double base, float rod, float unit, ShapeBatch& batch) {
  const std::size_t count = run.members.size();
  const float alpha = std::clamp(6.0f / float(count), 0.12f, 0.5f);  // many members: fainter each
  for (std::size_t m = 0; m < count; ++m) {
    const std::vector<P2> joints = chainJoints(run.members[m].hinges, view, base);
    for (std::size_t k = 0; k + 1 < joints.size(); ++k)
      batch.capsule(joints[k], joints[k + 1], std::max(0.6f * unit, 0.3f * rod), memberColor(run.color, m, count, alpha));
  }
}

// outline: the width of the run's coloured outline around its rods (overlay), 0 for none.
void drawRun(const PanelContext& context, const RunFrame* run, const PixelRect& area, bool label, float outline,
             ShapeBatch& batch) {
  // One scale for every run (runs may differ in L): each is drawn on its own pins. A labelled run keeps a caption
  // line at the foot of its area, and its caption sits just under the lowest place its chain can reach.
  const float line = context.font.lineHeight(TextSize::Small);
  const PlaneView view = fitFrameView(context.frame, area, label ? captionHeight(context.font) : 0);
  // Rod half width: 4.5% of a rod's length on screen, at least 1.5 px at 720p while rods are long enough to carry it
  // (a chain of hundreds of rods is drawn with hairline rods instead of a solid band).
  const float u = context.unit;
  const float rod = std::max(std::min(1.5f * u, std::max(0.9f * u, float(0.12 * view.scale))), float(0.045 * view.scale));
  const double base = run ? run->baseLength : context.frame.rods - 1;
  drawFloor(view, base, rod, u, batch);
  if (!run) return;
  drawTrails(*run, view, rod, u, batch);
  drawFeather(*run, view, base, rod, u, batch);
  drawChain(*run, view, base, rod, outline * rod, u, batch);
  if (label) {
    const std::string name = context.font.fitted(run->name, TextSize::Small, area.width);
    const float width = context.font.width(name, TextSize::Small);
    const float baseline = std::min(view.boxBottom + 1.1f * line, area.y + area.height - 0.3f * line);
    context.font.draw(batch, name, TextSize::Small, area.x + 0.5f * (area.width - width), baseline,
                      toRgba(run->color));
  }
}

}  // namespace

void drawLinkagePanel(const PanelContext& context, ShapeBatch& batch) {
  const auto& runs = context.frame.runs;
  const auto layout = context.settings.linkageLayout;
  if (runs.empty() || layout == LinkageLayout::SingleRun) {
    const int chosen = std::clamp(context.settings.linkageRun, 0, std::max(0, int(runs.size()) - 1));
    drawRun(context, runs.empty() ? nullptr : &runs[chosen], context.rect, false, 0, batch);
  } else if (layout == LinkageLayout::Overlay) {
    for (std::size_t k = 0; k < runs.size(); ++k)
      drawRun(context, &runs[k], context.rect, false, 1.6f * runStyleWidth(k, runs.size()), batch);
  } else {
    const float column = context.rect.width / float(runs.size());
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const PixelRect area{context.rect.x + column * float(k), context.rect.y, column, context.rect.height};
      drawRun(context, &runs[k], area, true, 0, batch);
    }
  }
}

}  // namespace sl

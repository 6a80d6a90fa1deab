// The linkage panel: the chain in its plane, drawn as lit 2D shapes (silver rods as cylinders, joints
// as balls), the two pins as charcoal bolts on a floor line, and fading trails of chosen hinges.
// The physics shows: a hinge's ball grows with its mass (a massless hinge is a dark rivet), a rod thickens with its
// mass, a stopped chain is grey and crossed out, a push or drag start is an arrow at each pushed hinge in the first
// frames.
// The view is fixed per scene (plane_view.hpp), so the picture never jumps as the chain moves.

#include <algorithm>
#include <cmath>

#include "render/palette.hpp"
#include "render/panels.hpp"
#include "render/plane_view.hpp"

namespace sl {
namespace {

void drawFloor(const PlaneView& view, double base, float rod, float unit, const palette::PageInk& page,
               ShapeBatch& batch) {
  batch.capsule(view(0, 0), view(base, 0), std::max(unit, 0.25f * rod), page.floorGrey);
  for (double pin : {0.0, base}) {  // ground hatching under each pin
    for (int k = -2; k <= 2; ++k) {
      const P2 top = view(pin + 0.06 * k, -0.02);
      batch.capsule(top, {top.x - 0.8f * rod, top.y + 1.6f * rod}, std::max(0.6f * unit, 0.12f * rod), page.floorGrey);
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
      const Rgba color = run.stopped ? palette::stoppedGrey : toRgba(run.color);
      points.push_back({view(trail[i]), std::max(0.8f * unit, 0.22f * rod), palette::withAlpha(color, 0.75f * age), {}});
    }
    batch.polyline(points);
  }
}

// A hinge's ball radius relative to a unit mass's: as the cube root of the mass (a ball of that mass), within
// [0.45, 2.2]; 0 for a massless hinge (no ball). Masses not given are the spec's unit masses.
float hingeBallScale(const RunFrame& run, std::size_t hinge) {
  const double mass = hinge < run.hingeMasses.size() ? run.hingeMasses[hinge] : 1.0;
  return mass > 0 ? std::clamp(float(std::cbrt(mass)), 0.45f, 2.2f) : 0.0f;
}

// A rod's half width relative to a massless rod's: as the square root of 1 + its mass (a cross-section growing
// with the mass), at most 3.
float rodWidthScale(const RunFrame& run, std::size_t rod) {
  const double mass = rod < run.rodMasses.size() ? run.rodMasses[rod] : 0.0;
  return mass > 0 ? std::min(3.0f, float(std::sqrt(1 + mass))) : 1.0f;
}

// Rods k of the drawn joints: the rod between drawn joints k and k+1 is the chain's rod k while no hinge is left out
// (a broken state's are); else every rod is drawn as massless.
bool allJointsDrawn(const RunFrame& run, const std::vector<P2>& joints) { return joints.size() == run.hinges.size() + 2; }

void drawCross(P2 at, float arm, float width, Rgba color, ShapeBatch& batch) {
  batch.capsule({at.x - arm, at.y - arm}, {at.x + arm, at.y + arm}, width, color);
  batch.capsule({at.x - arm, at.y + arm}, {at.x + arm, at.y - arm}, width, color);
}

void drawChain(const RunFrame& run, const PlaneView& view, double base, float rod, float outline, float unit,
               const palette::PageInk& page, ShapeBatch& batch) {
  const std::vector<P2> joints = chainJoints(run.hinges, view, base);
  const bool massesKnown = allJointsDrawn(run, joints);
  // Joints as balls while a rod is long enough on screen to show them apart (8 px at 720p); a long chain's hinges
  // would only blot it, and its rods, hairlines then, are drawn in the run's colour to stand out. A stopped chain is
  // grey throughout.
  const bool jointsApart = view.scale >= 8 * unit;
  const Rgba runColor = run.stopped ? palette::stoppedGrey : toRgba(run.color);
  const Rgba rodColor = jointsApart ? (run.stopped ? palette::stoppedGrey : palette::silver) : runColor;
  auto rodWidth = [&](std::size_t k) { return massesKnown ? rod * rodWidthScale(run, k) : rod; };
  // In overlay, each run's rods sit on an outline of its colour, narrower for each later run: runs that coincide
  // show as nested rings of their colours around the silver.
  if (outline > 0)
    for (std::size_t k = 0; k + 1 < joints.size(); ++k)
      batch.capsule(joints[k], joints[k + 1], rodWidth(k) + outline, runColor);
  for (std::size_t k = 0; k + 1 < joints.size(); ++k)
    batch.capsule(joints[k], joints[k + 1], rodWidth(k), rodColor, jointsApart, 0.6f);
  for (std::size_t k = 1; jointsApart && k + 1 < joints.size(); ++k) {
    const float ball = massesKnown ? hingeBallScale(run, k - 1) : 1.0f;
    if (ball == 0) {  // a massless hinge: a rivet where its rods meet, so thick rods still read as a chain of rods
      const float width = std::max(rodWidth(k - 1), rodWidth(k));
      const float rivet = std::min(width, std::max(0.5f * width, 1.2f * markUnit(unit)));  // legible when small
      batch.disc(joints[k], rivet, run.stopped ? palette::stoppedGrey : palette::pinCharcoal, true, 0.3f);
      continue;
    }
    batch.disc(joints[k], 1.75f * ball * rod, run.stopped ? palette::stoppedGrey : palette::jointSilver, true, 0.5f);
    batch.disc(joints[k], 0.85f * ball * rod, runColor, true, 0.4f);
  }
  const float pinRadius = std::max(2.2f * rod, 3.3f * markUnit(unit));  // the pins stay visible however long the chain
  for (const P2& pin : {joints.front(), joints.back()}) {
    batch.disc(pin, pinRadius, page.pinCharcoal, true, 0.3f);
    batch.disc(pin, pinRadius * (0.7f / 2.2f), palette::silver);
  }
  if (run.stopped) {  // crossed out over the middle of the chain, at most a fifth of its span (a small frame's
                      // mark floor made the cross larger than the chain)
    const P2 middle = joints[joints.size() / 2];
    const float span = std::hypot(joints.back().x - joints.front().x, joints.back().y - joints.front().y);
    const float arm = std::min(9 * markUnit(unit), std::max(0.2f * span, 3 * unit));
    drawCross(middle, arm, std::min(1.6f * markUnit(unit), 0.18f * arm), page.stopRed, batch);
  }
}

// A push or drag start: an arrow from each pushed hinge along its start velocity, the fastest 55 units long, fading
// out over the first frames.
void drawPush(const RunFrame& run, const PlaneView& view, float unit, const palette::PageInk& page, ShapeBatch& batch) {
  double top = 0;
  for (const RunFrame::HingeArrow& arrow : run.push) top = std::max(top, std::hypot(arrow.velocity.x, arrow.velocity.y));
  if (!(top > 0) || run.pushShown <= 0) return;
  const Rgba color = palette::withAlpha(page.ink, 0.85f * run.pushShown);
  const float width = 1.3f * markUnit(unit), head = 9 * markUnit(unit);
  for (const RunFrame::HingeArrow& arrow : run.push) {
    const std::size_t k = std::size_t(arrow.hinge - 1);
    if (k >= run.hinges.size() || !std::isfinite(run.hinges[k].x) || !std::isfinite(run.hinges[k].y)) continue;
    const P2 from = view(run.hinges[k]);
    const double length = 55 * unit * std::hypot(arrow.velocity.x, arrow.velocity.y) / top;
    const double dx = arrow.velocity.x / top * 55 * unit, dy = -arrow.velocity.y / top * 55 * unit;  // y down
    if (length < 2 * head) continue;
    const P2 tip{float(from.x + dx), float(from.y + dy)};
    const float ux = float(dx / length), uy = float(dy / length);
    batch.capsule(from, tip, width, color);
    for (const float side : {1.0f, -1.0f})
      batch.capsule(tip, {tip.x - head * (0.87f * ux - side * 0.5f * uy), tip.y - head * (0.87f * uy + side * 0.5f * ux)},
                    width, color);
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
  drawFloor(view, base, rod, u, context.page(), batch);
  if (!run) return;
  drawTrails(*run, view, rod, u, batch);
  drawFeather(*run, view, base, rod, u, batch);
  drawChain(*run, view, base, rod, outline * rod, u, context.page(), batch);
  drawPush(*run, view, u, context.page(), batch);
  if (label) {
    // Centred under the chain; a name wider than the column wraps onto a second line where the column has room
    // below (cut at a word, "single…" beside "chart…", the names of small frames could not be told apart).
    const float baseline = std::min(view.boxBottom + 1.1f * line, area.y + area.height - 0.3f * line);
    std::vector<std::string> lines = context.font.wrapped(run->name, TextSize::Small, area.width, 2);
    if (lines.size() > 1 && baseline + line > area.y + area.height - 0.3f * line)
      lines = {context.font.fitted(run->name, TextSize::Small, area.width)};
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const float width = context.font.width(lines[i], TextSize::Small);
      context.font.draw(batch, lines[i], TextSize::Small, area.x + 0.5f * (area.width - width),
                        baseline + float(i) * line, toRgba(run->color));
    }
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

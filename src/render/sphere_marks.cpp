#include "render/sphere_parts.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include "render/color_map.hpp"
#include "render/frame_words.hpp"
#include "render/palette.hpp"
#include "render/panel_layout.hpp"

namespace sl::detail {

namespace {

// n as superscript digits (U+2070.., as the plot ticks write exponents): S³, S¹⁰.
std::string superscript(int n) {
  static const char* const digits[] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                       "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  std::string out;
  for (const char c : std::to_string(n)) out += c == '-' ? "\u207b" : digits[c - '0'];
  return out;
}

// Phrases packed greedily into lines no wider than `width` ("; " between phrases on one line), each line fitted.
std::vector<std::string> packPhrases(const std::vector<std::string>& phrases, const FontAtlas& font, TextSize size,
                                     float width) {
  std::vector<std::string> lines;
  for (const std::string& phrase : phrases) {
    if (!lines.empty() && font.width(lines.back() + "; " + phrase, size) <= width)
      lines.back() += "; " + phrase;
    else
      lines.push_back(phrase);
  }
  for (std::string& line : lines) line = font.fitted(line, size, width);
  return lines;
}

}  // namespace

void drawBallGuide(const PanelContext& context, const SphereCamera& camera, ShapeBatch& batch) {
  const Vec3 centre{0, 0, 0};
  const P2 at = camera.project(centre);
  const float half = float(0.5 * camera.pixelsPerUnitAt(centre));
  std::vector<PolylinePoint> ring;
  for (int k = 0; k <= 96; ++k) {
    const double a = 2 * std::acos(-1.0) * k / 96;
    ring.push_back({{at.x + half * float(std::cos(a)), at.y + half * float(std::sin(a))},
                    0.8f * context.unit,
                    palette::withAlpha(context.page().softInk, 0.55f),
                    {}});
  }
  batch.polyline(ring);
  const int rods = context.frame.rods;
  std::vector<std::string> phrases = {"S" + superscript(rods - 2) + " drawn in a ball", "+ the start",
                                      "distance from it = angle / \u03c0", "ring = 90\u00b0", "rim = the antipode"};
  if (rods > 5) phrases.push_back("first 3 of " + std::to_string(rods - 2) + " directions");
  const float pad = 0.02f * context.rect.height, line = context.font.lineHeight(TextSize::Small);
  std::vector<std::string> lines = packPhrases(phrases, context.font, TextSize::Small, context.rect.width - 2 * pad);
  if (lines.size() > 2) {  // a small panel: the essentials in at most two lines, clear of the ball
    lines = packPhrases({"+ start", "radius = angle / \u03c0", "ring 90\u00b0"}, context.font, TextSize::Small,
                        context.rect.width - 2 * pad);
    lines.resize(std::min<std::size_t>(lines.size(), 2));
  }
  float y = context.rect.y + context.rect.height - pad - line * float(lines.size() - 1);
  for (const std::string& text : lines) {
    context.font.draw(batch, text, TextSize::Small, context.rect.x + pad, y, context.page().softInk);
    y += line;
  }
}

void drawBallStart(const PanelContext& context, const SphereCamera& camera, ShapeBatch& batch) {
  const Vec3 centre{0, 0, 0};
  const P2 at = camera.project(centre);
  const float arm = std::max(4.0f * markUnit(context.unit), 0.035f * float(camera.pixelsPerUnitAt(centre)));
  const float width = std::max(0.9f * markUnit(context.unit), 0.12f * arm);
  const ColorRGB& b = context.settings.background;
  const Rgba halo{b.r, b.g, b.b, 0.9f};
  batch.capsule({at.x - arm, at.y}, {at.x + arm, at.y}, width + 1.2f * markUnit(context.unit), halo);
  batch.capsule({at.x, at.y - arm}, {at.x, at.y + arm}, width + 1.2f * markUnit(context.unit), halo);
  batch.capsule({at.x - arm, at.y}, {at.x + arm, at.y}, width, context.page().ink);
  batch.capsule({at.x, at.y - arm}, {at.x, at.y + arm}, width, context.page().ink);
}

void drawEquator(const SphereCamera& camera, float unit, ShapeBatch& batch) {
  std::vector<PolylinePoint> points;
  const double pi = std::acos(-1.0);
  for (int k = 0; k <= 256; ++k) {
    const Vec3 p{std::cos(2 * pi * k / 256), std::sin(2 * pi * k / 256), 0};
    points.push_back({camera.project(p), 1.2f * unit, palette::withAlpha(palette::softInk, 0.8f), {}});
  }
  batch.polyline(points);
}

void drawEllipses(const std::vector<SphereEllipse>& ellipses, const SphereCamera& camera, const Placement& placement,
                  const PixelRect& rect, float unit, ShapeBatch& batch) {
  constexpr int kSegments = 40;
  const float halfWidth = std::max(0.6f * unit, 0.0011f * rect.height);
  const Vec3 eye = camera.eye();
  const double eyeDistance = std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
  for (const SphereEllipse& e : ellipses) {
    // Seen edge-on near the outline an ellipse is a meaningless dash: fade it out there. The outline is where the
    // sight line grazes the sphere, facing = 1 / eyeDistance in perspective (not 0): measured from there, so that
    // no ellipse just behind the outline hangs past it (stiffness.json frame 300 at 4K had faint ones outside).
    const double facing = (e.centre.x * eye.x + e.centre.y * eye.y + e.centre.z * eye.z) / eyeDistance;
    const float alpha = float(0.85 * std::clamp((facing - 1.0 / eyeDistance - 0.12) / 0.25, 0.0, 1.0));
    if (alpha <= 0) continue;
    const Rgba color{1, 1, 1, alpha};
    const Rgba halo = palette::withAlpha(palette::ink, 0.25f * alpha);
    std::vector<PolylinePoint> points;
    bool visible = true;
    for (int k = 0; k <= kSegments && visible; ++k) {
      const double a = 2 * std::acos(-1.0) * k / kSegments;
      const Vec3 p{e.centre.x + std::cos(a) * e.major.x + std::sin(a) * e.minor.x,
                   e.centre.y + std::cos(a) * e.major.y + std::sin(a) * e.minor.y,
                   e.centre.z + std::cos(a) * e.major.z + std::sin(a) * e.minor.z};
      const Vec3 placed = placement.place(p);
      visible = camera.inFront(placed);
      points.push_back({camera.project(placed), halfWidth, color, placement.world(placed)});
    }
    if (!visible) continue;
    // Filled, faintly: a strip along the major axis whose half width follows the ellipse's minor extent there.
    std::vector<PolylinePoint> fill;
    const P2 middle = camera.project(placement.place(e.centre));
    for (int k = 0; k <= 16; ++k) {
      const double s = -std::cos(std::acos(-1.0) * k / 16), across = std::sqrt(std::max(0.0, 1 - s * s));
      const Vec3 p{e.centre.x + s * e.major.x, e.centre.y + s * e.major.y, e.centre.z + s * e.major.z};
      const Vec3 side{e.centre.x + across * e.minor.x, e.centre.y + across * e.minor.y,
                      e.centre.z + across * e.minor.z};
      const Vec3 placed = placement.place(p);
      const P2 edge = camera.project(placement.place(side));
      const float half = std::hypot(edge.x - middle.x, edge.y - middle.y);
      fill.push_back({camera.project(placed), half, Rgba{1, 1, 1, 0.5f * alpha}, placement.world(placed)});
    }
    batch.polyline(fill);
    std::vector<PolylinePoint> under = points;
    for (PolylinePoint& point : under) {
      point.halfWidth += 0.6f * unit;
      point.color = halo;
    }
    batch.polyline(under);
    batch.polyline(points);
  }
}

void drawLabel(const std::string& text, P2 anchor, bool hidden, const PanelContext& context, LabelPlacer& placer,
               std::vector<PixelRect>& placed, ShapeBatch& batch) {
  const float ascent = context.font.ascent(TextSize::Small), pad = 0.25f * ascent;
  const float width = context.font.width(text, TextSize::Small) + 2 * pad, height = 1.45f * ascent + 2 * pad;
  const auto spot = placer.place(anchor, width, height, 0.9f * ascent);
  if (!spot) return;  // no room in the panel
  const Box& box = spot->first;
  // A label names something on the sphere and mostly sits on it: it keeps the light page's ink and pad in either
  // theme (on the dark page's pad it read as a hole in the cream ball).
  const bool light = context.settings.theme == Theme::Light;
  const Rgba ink = hidden ? ghost(palette::kLightPage.softInk) : palette::kLightPage.softInk;
  if (spot->second) {  // the leader: from the anchor (or the edge of a ball over it) to the nearest point of the box
    const P2 to{std::clamp(anchor.x, box.x0, box.x1), std::clamp(anchor.y, box.y0, box.y1)};
    const P2 from = placer.leaderStart(anchor, to);
    if (std::hypot(to.x - from.x, to.y - from.y) > markUnit(context.unit)) {
      batch.capsule(from, to, 0.5f * markUnit(context.unit), ink);
      placer.recordLeader(from, to);
    }
  }
  const ColorRGB b = light ? context.settings.background : themeBackground(Theme::Light);
  batch.rect(box.x0, box.y0, box.x1, box.y1, {b.r, b.g, b.b, 0.7f});
  context.font.draw(batch, text, TextSize::Small, box.x0 + pad, box.y0 + pad + 1.1f * ascent, ink);
  placed.push_back({box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0});
}

float labelBudget(const SphereCamera& camera) { return 0.5f * float(camera.pixelsPerUnitAt(Vec3{0, 0, 0})); }

void labelChartPoles(const PanelContext& context, const SphereCamera& camera, LabelPlacer& placer,
                     std::vector<PixelRect>& placed, ShapeBatch& back, ShapeBatch& batch) {
  for (const double z : {1.0, -1.0}) {
    const Vec3 pole{0, 0, z * 1.001};
    if (!camera.inFront(pole)) continue;
    const P2 at = camera.project(pole);
    const bool hidden = behindSphere(camera, pole);
    const float mark = markUnit(context.unit);
    if (hidden) ringBehind(context, at, 4 * mark, 0.6f * mark, ghost(palette::poleMark), back);
    drawLabel(fittedForm(context.font, chartPoleLabels(z > 0), TextSize::Small, labelBudget(camera)), at, hidden,
              context, placer, placed, batch);
  }
}

void drawSeams(const PanelContext& context, const SphereCamera& camera, LabelPlacer& placer,
               std::vector<PixelRect>& placed, ShapeBatch& surface, ShapeBatch& back, ShapeBatch& labels) {
  const double pi = std::acos(-1.0);
  const Rgba red = palette::withAlpha(palette::stopRed, 0.85f);
  std::optional<P2> named;
  double namedFacing = 0.2;  // only a seam facing the eye this much is named
  for (const double t : {pi / 2, -pi / 2}) {
    std::vector<PolylinePoint> front_, back_;
    auto flush = [&] {
      for (auto* points : {&front_, &back_})
        for (PolylinePoint& point : *points) point.at = withinOutline(camera, point.at, point.halfWidth);
      surface.dashedPolyline(front_, 7 * context.unit, 3 * context.unit);
      dashedBehind(context, back_, back);
      front_.clear();
      back_.clear();
    };
    for (int k = 0; k <= 128; ++k) {
      const double phi = -pi / 2 + pi * k / 128;
      const Vec3 p{1.003 * std::cos(phi) * std::cos(t), 1.003 * std::cos(phi) * std::sin(t), 1.003 * std::sin(phi)};
      if (!camera.inFront(p)) continue;
      const bool hidden = surfaceBehind(camera, p);
      auto& side = hidden ? back_ : front_;
      auto& other = hidden ? front_ : back_;
      if (!other.empty()) flush();
      side.push_back({camera.project(p), (hidden ? 0.6f : 1.0f) * context.unit, hidden ? ghost(red) : red, {}});
      if (!hidden) placer.avoidPoint(camera.project(p));  // labels keep off the seam as off the paths
      const Vec3 eye = camera.eye();
      const double facing =
          (p.x * eye.x + p.y * eye.y + p.z * eye.z) / std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
      // A seam is named at a point of it in sight: not under a ball (a state on the seam covers it there).
      if (!hidden && std::abs(phi) < 1.2 && facing > namedFacing && !placer.onBall(camera.project(p))) {
        namedFacing = facing;
        named = camera.project(p);
      }
    }
    flush();
  }
  if (named)
    drawLabel(fittedForm(context.font, seamLabels(), TextSize::Small, labelBudget(camera)), *named, false, context,
              placer, placed, labels);
}

void drawLoci(const SphereDecoration& decoration, const PanelContext& context, const SphereCamera& camera,
              LabelPlacer& placer, std::vector<PixelRect>& placed, ShapeBatch& surface, ShapeBatch& back,
              ShapeBatch& labels) {
  const Placement onSurface{true, 0.006};
  const float halfWidth = std::max(1.1f * markUnit(context.unit), 0.0021f * context.rect.height);
  const float ghostHalfWidth = 0.6f * markUnit(context.unit);
  const Vec3 eye = camera.eye();
  const double eyeDistance = std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
  struct Named {
    double facing = 0.15;  // only a point facing the eye this much is named
    std::optional<P2> at;
  };
  std::map<SphereCurveKind, Named> names;
  for (const SphereCurve& curve : decoration.curves) {
    const bool faint = curve.kind == SphereCurveKind::ClosedGeodesic;  // a guide under the runs, no halo
    const Rgba color = curve.kind == SphereCurveKind::CutLocus         ? palette::cutLocus
                       : curve.kind == SphereCurveKind::ConjugateLocus ? palette::conjugateLocus
                                                                       : palette::withAlpha(palette::ink, 0.6f);
    const Rgba halo = palette::withAlpha(palette::ink, faint ? 0.0f : 0.55f);
    std::vector<PolylinePoint> line, under, hidden;
    auto flush = [&] {
      for (auto* points : {&under, &line, &hidden})
        for (PolylinePoint& point : *points) point.at = withinOutline(camera, point.at, point.halfWidth);
      surface.polyline(under);
      surface.polyline(line);
      dashedBehind(context, hidden, back);
      line.clear();
      under.clear();
      hidden.clear();
    };
    bool wasHidden = false;
    for (const Vec3& point : curve.points) {
      const Vec3 p = onSurface.place(point);
      if (!drawable(point) || !camera.inFront(p)) {
        flush();
        continue;
      }
      const P2 at = camera.project(p);
      const bool behind = surfaceBehind(camera, p);
      if (behind != wasHidden) {  // across the limb: the dashes reach the solid line
        if (behind && !line.empty()) hidden.push_back({line.back().at, ghostHalfWidth, ghost(color), {}});
        if (!behind) hidden.push_back({at, ghostHalfWidth, ghost(color), {}});
        flush();
      }
      wasHidden = behind;
      if (behind) {
        hidden.push_back({at, ghostHalfWidth, ghost(color), {}});
        continue;
      }
      line.push_back({at, faint ? 0.85f * halfWidth : halfWidth, color, onSurface.world(p)});
      if (!faint) under.push_back({at, halfWidth + 0.7f * markUnit(context.unit), halo, onSurface.world(p)});
      placer.avoidPoint(at);
      const double facing = (p.x * eye.x + p.y * eye.y + p.z * eye.z) / eyeDistance;
      Named& name = names[curve.kind];
      if (facing > name.facing) {
        name.facing = facing;
        name.at = at;
      }
    }
    flush();
  }
  if (decoration.distance && !decoration.distance->fromStart) {
    const Vec3& x = decoration.distance->point;
    const Vec3 p = onSurface.place(x);
    if (camera.inFront(p)) {
      const bool behind = behindSphere(camera, p);
      const float radius = std::max(5 * markUnit(context.unit), 0.012f * context.rect.height);
      (behind ? back : labels)
          .ring(camera.project(p), radius, (behind ? 0.6f : 1.2f) * markUnit(context.unit),
                behind ? ghost(palette::ink) : palette::ink);  // over the paths
      drawLabel("distance measured from here", camera.project(p), behind, context, placer, placed, labels);
    }
  }
  for (const auto& [kind, name] : names)
    if (name.at) drawLabel(curveName(kind), *name.at, false, context, placer, placed, labels);
}

void drawTransport(const SphereTransport& transport, const PanelContext& context, const SphereCamera& camera,
                   LabelPlacer& placer, ShapeBatch& back, ShapeBatch& front) {
  const Placement onSurface{true, 0.012};
  const float mark = markUnit(context.unit);
  const Rgba halo{1, 1, 1, 0.75f};  // over the sphere's colours, not the background
  const auto drawArrow = [&](const SphereTransport::Arrow& arrow, Rgba color, float weight) {
    const Vec3 tip{arrow.base.x + kTransportArrowLength * arrow.direction.x,
                   arrow.base.y + kTransportArrowLength * arrow.direction.y,
                   arrow.base.z + kTransportArrowLength * arrow.direction.z};
    const Vec3 from3 = onSurface.place(arrow.base), to3 = onSurface.place(tip);
    if (!camera.inFront(from3) || !camera.inFront(to3)) return;
    const P2 from = camera.project(from3), to = camera.project(to3);
    const float length = std::hypot(to.x - from.x, to.y - from.y);
    if (!(length > 2 * mark)) return;  // seen end-on
    const bool hidden = surfaceBehind(camera, from3) || surfaceBehind(camera, to3);
    const float shaft = weight * mark, head = 3.2f * shaft;
    const P2 dir = unitDirection(from, to), neck = plus(to, dir, -std::min(0.45f * length, 3.0f * head));
    const auto draw = [&](ShapeBatch& into, float grow, Rgba c) {
      into.polyline({{plus(from, dir, -grow), shaft + grow, c, {}}, {neck, shaft + grow, c, {}}});
      into.polyline({{neck, head + grow, c, {}}, {plus(to, dir, grow), 0.3f * shaft + grow, c, {}}});
    };
    if (hidden) {
      draw(back, 0, ghost(color));
      return;
    }
    draw(front, 1.2f * mark, palette::withAlpha(halo, halo.a * color.a));
    draw(front, 0, color);
    placer.avoidPoint(from);
    placer.avoidPoint(to);
    placer.avoidPoint({0.5f * (from.x + to.x), 0.5f * (from.y + to.y)});
  };
  const double reached = SphereTransport::carriedFraction(context.frame.time, context.frame.duration);
  const std::size_t perSide = std::size_t(transport.samplesPerSide) + 1;
  for (std::size_t i = 0; i < transport.arrows.size(); ++i) {  // the arrows left behind, fading as the paths do
    const SphereTransport::Arrow& arrow = transport.arrows[i];
    const std::size_t k = i % perSide;
    if (k % 2 != 0 || k == 0 || k + 1 == perSide || !(arrow.fraction < reached)) continue;
    const float alpha = pathAlpha(context.settings, (reached - arrow.fraction) * context.frame.duration);
    if (alpha > 0) drawArrow(arrow, palette::withAlpha(palette::ink, alpha), 1.0f);
  }
  drawArrow(transport.arrows.front(), palette::ink, 1.5f);
  const std::size_t sides = transport.corners.size();
  for (std::size_t side = 0; side < sides; ++side) {  // the carried vectors, the last side's returning at the end
    const bool returning = side + 1 == sides && reached >= 1.0;
    if (side == 0 && reached == 0) continue;  // the starting vector, drawn
    drawArrow(transport.carriedAt(side, reached), returning ? palette::returningVector : palette::ink, 1.5f);
  }
  if (!transport.corners.empty()) {
    const Vec3 corner = onSurface.place(transport.corners.front());
    if (camera.inFront(corner) && !surfaceBehind(camera, corner))
      front.ring(camera.project(corner), 4.5f * mark, 0.9f * mark, palette::ink);
  }
}

}  // namespace sl::detail

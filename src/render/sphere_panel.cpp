// The sphere panel: configuration-space paths of every run on (or, for 5+ rods, inside) the sphere.
// The sphere itself is drawn by shaders/sphere.frag; here the paths become shaded tubes that fade with
// age, lifted just above the surface and hidden per pixel where the sphere is in front of them.

#include <algorithm>
#include <cmath>

#include "render/color_map.hpp"
#include "render/palette.hpp"
#include "render/panels.hpp"

namespace sl::render {
namespace {

constexpr double kTubeRadius = 0.014;  // world units (sphere radius 1)
constexpr double kBallRadius = 0.055;

V3 toV3(const Vec3& p) { return {p.x, p.y, p.z}; }
// Finite and not absurdly far (the frame state promises the unit ball or sphere; this guards the drawing).
bool drawable(const Vec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && p.x * p.x + p.y * p.y + p.z * p.z < 400.0;
}

// The ball view's jump through the antipode (from one side of the boundary to the other) is drawn as a gap,
// never a line. Consecutive path samples lie a few thousandths apart at the shipped sampling; a jump is a
// chord of nearly 2. Only the ball view can jump: other views never break a path on length.
constexpr double kMaxPathChord = 0.5;
double distance(const Vec3& a, const Vec3& b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

// On the opaque sphere, points ride on a shell just outside it so the tube's front half is never
// inside the sphere; lines elsewhere are not occluded.
struct Placement {
  bool onSphere;
  double lift;
  V3 place(const Vec3& p) const {
    if (!onSphere) return toV3(p);
    const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    const double s = r > 1e-12 ? (1.0 + lift) / r : 0.0;
    return {p.x * s, p.y * s, p.z * s};
  }
  Occludable world(const V3& p) const { return {float(p.x), float(p.y), float(p.z), onSphere ? 1.0f : 0.0f}; }
};

float pathAlpha(const ViewSettings& settings, double age) {
  if (settings.pathFadeSeconds <= 0) return 1.0f;
  return static_cast<float>(std::clamp(1.0 - age / settings.pathFadeSeconds, 0.0, 1.0));
}

void drawPath(const RunFrame& run, const PanelContext& context, const SphereCamera& camera, const Placement& placement,
              bool throughAntipode, ShapeBatch& batch) {
  std::vector<PolylinePoint> points;
  points.reserve(run.path.size() + 1);
  for (std::size_t i = 0; i < run.path.size(); ++i) {
    const double age = i < run.pathTimes.size() ? context.frame.time - run.pathTimes[i] : 0.0;
    const float alpha = pathAlpha(context.settings, age);
    const V3 p = placement.place(run.path[i]);
    const bool hidden = alpha <= 0.0f || !drawable(run.path[i]) || !camera.inFront(p);
    const bool jump = throughAntipode && i > 0 && distance(run.path[i - 1], run.path[i]) > kMaxPathChord;
    if (hidden || jump) {  // a gap: draw what came before, start afresh (with this point, unless hidden)
      batch.polyline(points, true, 0.35f);
      points.clear();
    }
    if (hidden) continue;
    const float halfWidth = std::max(1.0f, float(kTubeRadius * camera.pixelsPerUnitAt(p)));
    points.push_back({camera.project(p), halfWidth, toRgba(run.color, alpha), placement.world(p)});
  }
  batch.polyline(points, true, 0.35f);
}

void drawBall(const RunFrame& run, const SphereCamera& camera, const Placement& placement, ShapeBatch& batch) {
  Placement ballPlacement = placement;
  ballPlacement.lift = kBallRadius;
  const V3 centre = ballPlacement.place(run.current);
  if (!drawable(run.current) || !camera.inFront(centre)) return;
  const float pixelsPerUnit = float(camera.pixelsPerUnitAt(centre));
  const float radius = std::max(2.5f, float(kBallRadius) * pixelsPerUnit);
  const P2 at = camera.project(centre);
  const Occludable world = ballPlacement.world(centre);
  // A stopped run's ball sits on a red halo (a larger ball behind it, hidden with it by the sphere).
  if (run.stopped) batch.disc(at, radius + 2.5f, palette::stopRed, true, 0.2f, world, (radius + 2.5f) / pixelsPerUnit);
  batch.disc(at, radius, toRgba(run.color), true, 0.55f, world, radius / pixelsPerUnit);
}

// 3 rods: the configuration circle, the equator.
void drawEquator(const SphereCamera& camera, ShapeBatch& batch) {
  std::vector<PolylinePoint> points;
  const double pi = std::acos(-1.0);
  for (int k = 0; k <= 256; ++k) {
    const V3 p{std::cos(2 * pi * k / 256), std::sin(2 * pi * k / 256), 0};
    points.push_back({camera.project(p), 1.2f, palette::withAlpha(palette::softInk, 0.8f), {}});
  }
  batch.polyline(points);
}

// Stiffness ellipses as thin dark rings riding on the sphere, hidden where the sphere is in front of them.
void drawEllipses(const std::vector<SphereEllipse>& ellipses, const SphereCamera& camera, const Placement& placement,
                  const PixelRect& rect, ShapeBatch& batch) {
  constexpr int kSegments = 40;
  const float halfWidth = std::max(0.6f, 0.0011f * rect.height);
  const V3 eye = camera.eye();
  const double eyeDistance = std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
  for (const SphereEllipse& e : ellipses) {
    // Seen edge-on near the outline an ellipse is a meaningless dash: fade it out there.
    const double facing = (e.centre.x * eye.x + e.centre.y * eye.y + e.centre.z * eye.z) / eyeDistance;
    const float alpha = float(0.85 * std::clamp((facing - 0.2) / 0.25, 0.0, 1.0));
    if (alpha <= 0) continue;
    const Rgba color = palette::withAlpha(palette::ink, alpha);
    std::vector<PolylinePoint> points;
    bool visible = true;
    for (int k = 0; k <= kSegments && visible; ++k) {
      const double a = 2 * std::acos(-1.0) * k / kSegments;
      const Vec3 p{e.centre.x + std::cos(a) * e.major.x + std::sin(a) * e.minor.x,
                   e.centre.y + std::cos(a) * e.major.y + std::sin(a) * e.minor.y,
                   e.centre.z + std::cos(a) * e.major.z + std::sin(a) * e.minor.z};
      const V3 placed = placement.place(p);
      visible = camera.inFront(placed);
      points.push_back({camera.project(placed), halfWidth, color, placement.world(placed)});
    }
    if (visible) batch.polyline(points);
  }
}

// The strip at the panel's right kept for the colour bar (the sphere is framed in the rest).
float colorBarStrip(const PixelRect& rect) { return std::min(0.24f * rect.width, 0.45f * rect.height); }

}  // namespace

SphereImpostor drawSpherePanel(const PanelContext& context, ShapeBatch& batch) {
  const ViewSpace space = context.frame.viewSpace;
  const SphereDecoration* decoration =
      space == ViewSpace::Sphere ? context.frame.sphereDecoration.get() : nullptr;  // 4 rods only
  const bool colored = decoration && decoration->field;
  PixelRect sphereRect = context.rect;
  if (colored) sphereRect.width -= colorBarStrip(context.rect);
  SphereCamera camera(context.settings.camera, context.frame.time, sphereRect);
  const Placement placement{space == ViewSpace::Sphere, kTubeRadius};
  if (space == ViewSpace::Circle) drawEquator(camera, batch);
  if (decoration) {
    const float pad = 0.02f * context.rect.height;
    const Placement onSurface{true, 0.004};
    drawEllipses(decoration->ellipses, camera, onSurface, context.rect, batch);
    if (!decoration->ellipseCaption.empty()) {
      context.font.draw(batch, decoration->ellipseCaption, TextSize::Small, context.rect.x + pad,
                        context.rect.y + context.rect.height - pad, palette::softInk);
    }
    if (colored) {
      const SphereField& field = *decoration->field;
      const PixelRect bar{context.rect.x + context.rect.width - colorBarStrip(context.rect), context.rect.y + pad,
                          colorBarStrip(context.rect) - pad, 0.8f * context.rect.height};
      drawColorBar(scaleOf(field), field.label, field.diverging ? "each sign on its own scale" : "", bar,
                   context.font, batch);
    }
  }
  for (const RunFrame& run : context.frame.runs)
    drawPath(run, context, camera, placement, space == ViewSpace::Ball, batch);
  for (const RunFrame& run : context.frame.runs) drawBall(run, camera, placement, batch);
  const SphereLook look = colored ? SphereLook::Colored : space == ViewSpace::Sphere ? SphereLook::Opaque : SphereLook::Glass;
  return {camera, look};
}

}  // namespace sl::render

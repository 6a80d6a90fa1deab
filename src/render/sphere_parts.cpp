#include "render/sphere_parts.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/color_map.hpp"
#include "render/frame_words.hpp"
#include "render/palette.hpp"
#include "render/panel_layout.hpp"

namespace sl::detail {

bool drawable(const Vec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && p.x * p.x + p.y * p.y + p.z * p.z < 400.0;
}

double distance(const Vec3& a, const Vec3& b) {
  return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

bool behindSphere(const SphereCamera& camera, const Vec3& p) {
  const Vec3 e = camera.eye();
  const Vec3 d{p.x - e.x, p.y - e.y, p.z - e.z};
  const double dd = d.x * d.x + d.y * d.y + d.z * d.z;
  if (!(dd > 0)) return false;
  const double s = -(e.x * d.x + e.y * d.y + e.z * d.z) / dd;  // the sight line's closest approach to the centre
  if (s <= 0 || s >= 1) return false;
  const Vec3 c{e.x + s * d.x, e.y + s * d.y, e.z + s * d.z};
  return c.x * c.x + c.y * c.y + c.z * c.z < 1.0;
}

bool surfaceBehind(const SphereCamera& camera, const Vec3& lifted) {
  const double r = std::sqrt(lifted.x * lifted.x + lifted.y * lifted.y + lifted.z * lifted.z);
  if (!(r > 0)) return false;
  const double s = (1.0 - 1e-9) / r;  // just inside the surface: a point exactly on the limb counts as hidden
  return behindSphere(camera, {lifted.x * s, lifted.y * s, lifted.z * s});
}

P2 withinOutline(const SphereCamera& camera, P2 at, float inset) {
  const P2 c = camera.centre();
  const float limit = std::max(0.0f, float(camera.outlineRadius()) - inset);
  const float dx = at.x - c.x, dy = at.y - c.y, r = std::hypot(dx, dy);
  if (r <= limit || r <= 0) return at;
  return {c.x + dx * limit / r, c.y + dy * limit / r};
}

SphereCover sphereCoverNear(const SphereCamera& camera, const Vec3& p, double reach) {
  const Vec3 e = camera.eye();
  const Vec3 d{p.x - e.x, p.y - e.y, p.z - e.z};
  const double toPoint = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  if (!(toPoint > 0)) return SphereCover::PerPixel;
  const double closest = -(e.x * d.x + e.y * d.y + e.z * d.z) / toPoint;
  const double miss = std::sqrt(std::max(e.x * e.x + e.y * e.y + e.z * e.z - closest * closest, 0.0));
  const double pixel = closest / camera.focal();  // world size of a pixel at the sphere
  if (!(pixel > 0)) return SphereCover::PerPixel;
  const double spread = (reach + 2.0) * pixel;
  if (miss - spread > 1.0) return SphereCover::Clear;  // every sight line misses the sphere
  auto nearHit = [&](double m) { return closest - std::sqrt(std::max(1.0 - m * m, 0.0)); };
  if (toPoint <= nearHit(std::max(miss - spread, 0.0)) - 2.0 * pixel) return SphereCover::Clear;
  if (miss + spread < 1.0 && toPoint >= nearHit(miss + spread) + 2.0 * pixel) return SphereCover::Hidden;
  return SphereCover::PerPixel;
}

Rgba ghost(Rgba c) { return palette::withAlpha(c, c.a * kGhostAlpha); }

float hiddenHalfWidth(float own, float inFront) { return std::min(own, 0.6f * inFront); }

bool onDarkEndedMap(const PanelContext& context) {
  return context.frame.viewSpace == ViewSpace::Sphere && context.frame.sphereDecoration &&
         context.frame.sphereDecoration->field && !context.frame.sphereDecoration->field->diverging;
}

float colorBarStrip(const PixelRect& rect) { return std::min(0.24f * rect.width, 0.45f * rect.height); }

Rgba farSideHalo(Rgba ghostColor) { return {1, 1, 1, 0.8f * ghostColor.a}; }

void dashedBehind(const PanelContext& context, const std::vector<PolylinePoint>& points, ShapeBatch& back) {
  const float mark = markUnit(context.unit);
  if (onDarkEndedMap(context) && points.size() >= 2) {
    std::vector<PolylinePoint> halo = points;
    // The halo is part of a line, not a mark: it thins with the frame, where a mark's floor made the far side's
    // dashes at 320x180 wider than the path in front (2.6 px of light dash beside a 2 px path).
    for (PolylinePoint& point : halo) {
      point.halfWidth += 0.6f * context.unit;
      point.color = farSideHalo(point.color);
    }
    back.dashedPolyline(halo, kGhostDash * mark, kGhostGap * mark);
  }
  back.dashedPolyline(points, kGhostDash * mark, kGhostGap * mark);
}

void ringBehind(const PanelContext& context, P2 at, float radius, float halfWidth, Rgba color, ShapeBatch& back) {
  if (onDarkEndedMap(context)) back.ring(at, radius, halfWidth + 0.6f * markUnit(context.unit), farSideHalo(color));
  back.ring(at, radius, halfWidth, color);
}

P2 plus(P2 a, P2 b, float s) { return {a.x + s * b.x, a.y + s * b.y}; }

P2 unitDirection(P2 from, P2 to) {
  const float dx = to.x - from.x, dy = to.y - from.y, len = std::hypot(dx, dy);
  return len > 1e-6f ? P2{dx / len, dy / len} : P2{1, 0};
}

void shiftAcross(std::vector<PolylinePoint>& points, float offset) {
  if (offset == 0 || points.size() < 2) return;
  std::vector<P2> across(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const P2 d = unitDirection(points[i == 0 ? 0 : i - 1].at, points[i + 1 < points.size() ? i + 1 : i].at);
    across[i] = {-d.y, d.x};
  }
  for (std::size_t i = 0; i < points.size(); ++i)
    points[i].at = plus(points[i].at, across[i], offset * points[i].halfWidth);
}

float pathAlpha(const ViewSettings& settings, double age) {
  if (settings.pathFadeSeconds <= 0) return 1.0f;
  return static_cast<float>(std::clamp(1.0 - age / settings.pathFadeSeconds, 0.0, 1.0));
}

}  // namespace sl::detail

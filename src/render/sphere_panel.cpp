// The sphere panel: configuration-space paths of every run on (or, for 5+ rods, inside) the sphere.
// The sphere itself is drawn by shaders/sphere.frag; here the paths become shaded tubes that fade with
// age, lifted just above the surface and hidden per pixel where the sphere is in front of them.
//
// One convention for the far side: whatever the sphere hides (a path's section, a ball, a member's dot, a mark, a
// pole) is drawn over the sphere faint and hollow (paths dashed and flat, balls and dots as rings), never as a
// filled disc, so front and back are never confused. Time: a bar across each path's start, an arrowhead at the
// current state along its last section, older sections thinner and fainter where several runs share the sphere.
// Coinciding runs lie side by side (each path and ball shifted across its direction by its place among the runs),
// never nested by width, which would read as a ranking. Labels are placed where they cover nothing (LabelPlacer).

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "render/color_map.hpp"
#include "render/frame_words.hpp"
#include "render/palette.hpp"
#include "render/panels.hpp"
#include "render/panel_layout.hpp"

namespace sl {
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

// Hidden by the opaque unit sphere: the sight line from the eye to p passes through the sphere's inside before
// reaching p (p itself lies on or outside the sphere).
bool behindSphere(const SphereCamera& camera, const V3& p) {
  const V3 e = camera.eye();
  const V3 d{p.x - e.x, p.y - e.y, p.z - e.z};
  const double dd = d.x * d.x + d.y * d.y + d.z * d.z;
  if (!(dd > 0)) return false;
  const double s = -(e.x * d.x + e.y * d.y + e.z * d.z) / dd;  // the sight line's closest approach to the centre
  if (s <= 0 || s >= 1) return false;
  const V3 c{e.x + s * d.x, e.y + s * d.y, e.z + s * d.z};
  return c.x * c.x + c.y * c.y + c.z * c.z < 1.0;
}

// Whether the surface point under a lifted one is on the far side. Lifted points just beyond the limb are still in
// sight past the sphere, and drawn as in front they would hang outside its outline.
bool surfaceBehind(const SphereCamera& camera, const V3& lifted) {
  const double r = std::sqrt(lifted.x * lifted.x + lifted.y * lifted.y + lifted.z * lifted.z);
  if (!(r > 0)) return false;
  const double s = (1.0 - 1e-9) / r;  // just inside the surface: a point exactly on the limb counts as hidden
  return behindSphere(camera, {lifted.x * s, lifted.y * s, lifted.z * s});
}

// A point drawn on the sphere kept within its outline, `inset` pixels inside it: what is shifted sideways
// (coinciding runs side by side) or lifted off the surface never hangs past the limb.
P2 withinOutline(const SphereCamera& camera, P2 at, float inset) {
  const P2 c = camera.centre();
  const float limit = std::max(0.0f, float(camera.outlineRadius()) - inset);
  const float dx = at.x - c.x, dy = at.y - c.y, r = std::hypot(dx, dy);
  if (r <= limit || r <= 0) return at;
  return {c.x + dx * limit / r, c.y + dy * limit / r};
}

// How the opaque unit sphere covers every pixel within `reach` pixels of p's image, by shaders/lit.frag's own test
// (hiddenBySphere: the sight line's near hit against the fragment's distance, blended over a pixel) evaluated at
// the nearest and farthest sight lines of that reach, with two pixels to spare: clear where no such pixel can be
// hidden, hidden where all are, else left to the shader.
SphereCover sphereCoverNear(const SphereCamera& camera, const V3& p, double reach) {
  const V3 e = camera.eye();
  const V3 d{p.x - e.x, p.y - e.y, p.z - e.z};
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

// The far side's look: the colour at a fraction of its opacity, drawn flat over the sphere.
constexpr float kGhostAlpha = 0.55f;
Rgba ghost(Rgba c) { return palette::withAlpha(c, c.a * kGhostAlpha); }
// Dashes and gaps of hidden paths, in frame units.
constexpr float kGhostDash = 5.0f, kGhostGap = 3.5f;
// A hidden line's half width: its own, but never bolder than the line in front would be there (a small frame's floor
// of a mark unit made hidden dashes bolder than the paths in front).
float hiddenHalfWidth(float own, float inFront) { return std::min(own, 0.6f * inFront); }

// Over a sequential colour map the far side's faint lines would vanish on its dark end (viridis' purple): there
// they are drawn on a light halo, faint with them. The plain sphere and the diverging map (light in the middle, its
// ends mid-tones) keep them bare: a halo there changed little and doubled the hidden dashes a fan of 64 draws.
bool onDarkEndedMap(const PanelContext& context) {
  return context.frame.viewSpace == ViewSpace::Sphere && context.frame.sphereDecoration &&
         context.frame.sphereDecoration->field && !context.frame.sphereDecoration->field->diverging;
}
Rgba farSideHalo(Rgba ghostColor) { return {1, 1, 1, 0.8f * ghostColor.a}; }
// A hidden line, dashed and faint (on its halo over a dark-ended map); the halo's dashes are the line's own.
void dashedBehind(const PanelContext& context, const std::vector<PolylinePoint>& points, ShapeBatch& back) {
  const float mark = markUnit(context.unit);
  if (onDarkEndedMap(context) && points.size() >= 2) {
    std::vector<PolylinePoint> halo = points;
    for (PolylinePoint& point : halo) {
      point.halfWidth += 0.6f * mark;
      point.color = farSideHalo(point.color);
    }
    back.dashedPolyline(halo, kGhostDash * mark, kGhostGap * mark);
  }
  back.dashedPolyline(points, kGhostDash * mark, kGhostGap * mark);
}
// A hidden ring, faint (on its halo over a dark-ended map).
void ringBehind(const PanelContext& context, P2 at, float radius, float halfWidth, Rgba color, ShapeBatch& back) {
  if (onDarkEndedMap(context)) back.ring(at, radius, halfWidth + 0.6f * markUnit(context.unit), farSideHalo(color));
  back.ring(at, radius, halfWidth, color);
}

P2 plus(P2 a, P2 b, float s = 1) { return {a.x + s * b.x, a.y + s * b.y}; }
P2 unitDirection(P2 from, P2 to) {
  const float dx = to.x - from.x, dy = to.y - from.y, len = std::hypot(dx, dy);
  return len > 1e-6f ? P2{dx / len, dy / len} : P2{1, 0};
}

// Each point moved sideways (across the line's direction there) by `offset` times its half width.
void shiftAcross(std::vector<PolylinePoint>& points, float offset) {
  if (offset == 0 || points.size() < 2) return;
  std::vector<P2> across(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const P2 d = unitDirection(points[i == 0 ? 0 : i - 1].at, points[i + 1 < points.size() ? i + 1 : i].at);
    across[i] = {-d.y, d.x};
  }
  for (std::size_t i = 0; i < points.size(); ++i) points[i].at = plus(points[i].at, across[i], offset * points[i].halfWidth);
}

// The labels and marks of the panel, as boxes, for a label to find a place that covers none of them.
struct Box {
  float x0, y0, x1, y1;
};
float overlapArea(const Box& a, const Box& b) {
  const float w = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), h = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return w > 0 && h > 0 ? w * h : 0;
}

// Candidate places around an anchor: 8 directions, near and then at growing distances (with a leader line). A
// candidate that overlaps anything already placed (a ball, a label) or leaves the area is refused; of the others the
// one covering the fewest path points wins, nearer first on a tie. Nothing outside the area: a label never reaches
// the title band, a neighbouring panel or the colour bar's strip. No place at all: no label.
class LabelPlacer {
 public:
  explicit LabelPlacer(const PixelRect& area) : area_(area) {}
  void avoid(const Box& box) { taken_.push_back(box); }
  void avoidPoint(P2 p) { points_.push_back(p); }
  // A ball: its square is avoided as a box; its disc is where a leader line may not run (over the ball).
  void avoidBall(P2 at, float radius) {
    avoid({at.x - radius, at.y - radius, at.x + radius, at.y + radius});
    balls_.push_back({at, radius});
  }
  bool onBall(P2 p) const {
    return std::any_of(balls_.begin(), balls_.end(),
                       [&](const auto& ball) { return std::hypot(p.x - ball.first.x, p.y - ball.first.y) < ball.second; });
  }
  // Where a leader line from `anchor` to `to` starts: the anchor, or for an anchor under a ball (a pole or a seam a
  // state sits on) the edge of the ball, of the balls spread over it one after another: a leader never strikes
  // through the ball over its anchor.
  P2 leaderStart(P2 anchor, P2 to) const {
    const float dx = to.x - anchor.x, dy = to.y - anchor.y, length = std::hypot(dx, dy);
    if (length <= 0) return anchor;
    float from = 0;  // along the line, as a fraction of its length
    for (std::size_t pass = 0; pass < balls_.size(); ++pass) {
      bool moved = false;
      for (const auto& [at, radius] : balls_) {
        // The line's parameters s where |anchor + s (to - anchor) - at| = radius: entry and exit.
        const float ox = anchor.x - at.x, oy = anchor.y - at.y;
        const float b = (ox * dx + oy * dy) / (length * length);
        const float c = (ox * ox + oy * oy - radius * radius) / (length * length);
        if (b * b - c <= 0) continue;
        const float exit = -b + std::sqrt(b * b - c), entry = -b - std::sqrt(b * b - c);
        if (entry <= from && exit > from) {
          from = std::min(exit, 1.0f);
          moved = true;
        }
      }
      if (!moved) break;
    }
    return {anchor.x + from * dx, anchor.y + from * dy};
  }
  // Whether the leader from `anchor` to the nearest point of `box` runs over a ball (past those over the anchor,
  // which it starts beyond): a leader strikes through no ball.
  bool leaderCrossesABall(P2 anchor, const Box& box) const {
    const P2 to{std::clamp(anchor.x, box.x0, box.x1), std::clamp(anchor.y, box.y0, box.y1)};
    const P2 from = leaderStart(anchor, to);
    const float dx = to.x - from.x, dy = to.y - from.y, length2 = dx * dx + dy * dy;
    return std::any_of(balls_.begin(), balls_.end(), [&](const auto& ball) {
      const auto& [at, radius] = ball;
      const float s = length2 > 0 ? std::clamp(((at.x - from.x) * dx + (at.y - from.y) * dy) / length2, 0.0f, 1.0f) : 0.0f;
      return std::hypot(from.x + s * dx - at.x, from.y + s * dy - at.y) < 0.99f * radius;
    });
  }
  void recordLeader(P2 from, P2 to) { leaders_.push_back({from, to}); }
  const std::vector<std::array<P2, 2>>& leaders() const { return leaders_; }
  // The box of a label of `width` x `height` placed near `anchor`, and whether it is far enough to need a leader.
  std::optional<std::pair<Box, bool>> place(P2 anchor, float width, float height, float clearance) {
    std::optional<std::pair<Box, bool>> best;
    float bestScore = 0;
    for (const float reach : {1.0f, 2.5f, 4.5f, 7.0f}) {
      for (int k = 0; k < 8; ++k) {
        const float a = 0.7853982f * float(k) - 0.7853982f;  // up-right first, then clockwise
        const float dx = std::cos(a), dy = std::sin(a);
        const float r = reach * clearance;
        // The box touches the circle of radius r about the anchor on the side facing it.
        const float cx = anchor.x + dx * (r + 0.5f * width * std::abs(dx));
        const float cy = anchor.y + dy * (r + 0.5f * height * std::abs(dy));
        const Box box{cx - 0.5f * width, cy - 0.5f * height, cx + 0.5f * width, cy + 0.5f * height};
        // A wide box on a diagonal reaches back over its anchor and the mark drawn there (a pole's ring): refused.
        const float nearX = std::clamp(anchor.x, box.x0, box.x1) - anchor.x, nearY = std::clamp(anchor.y, box.y0, box.y1) - anchor.y;
        if (std::hypot(nearX, nearY) < 0.6f * clearance) continue;
        if (box.x0 < area_.x || box.y0 < area_.y || box.x1 > area_.x + area_.width || box.y1 > area_.y + area_.height)
          continue;
        if (std::any_of(taken_.begin(), taken_.end(), [&](const Box& t) { return overlapArea(box, t) > 0; }))
          continue;
        if (reach > 1 && leaderCrossesABall(anchor, box)) continue;
        float score = reach;  // nearer wins a tie
        for (const P2& p : points_)
          if (p.x > box.x0 && p.x < box.x1 && p.y > box.y0 && p.y < box.y1) score += 10;
        if (!best || score < bestScore) {
          best = std::make_pair(box, reach > 1);
          bestScore = score;
        }
      }
    }
    if (best) taken_.push_back(best->first);
    return best;
  }

 private:
  PixelRect area_;
  std::vector<Box> taken_;
  std::vector<P2> points_;
  std::vector<std::pair<P2, float>> balls_;
  std::vector<std::array<P2, 2>> leaders_;
};

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

// How a path is drawn: a tube of `radius` (world units, at least `minHalfWidth` pixels) in `color`, or for `thin`
// paths (a family's members, many at once) flat lines with points closer than a pixel merged: the same picture at a
// fraction of the fill. `offset`: shifted sideways by that many half widths (coinciding runs side by side).
// `aging`: sections thinner and fainter the older they are (down to 60% of the width and 45% of the opacity at the
// start), so a long path carries its time.
// How far (pixels per frame unit) a thin path's drawn line may stray from its points to save vertices.
constexpr float kThinPathTolerance = 0.05f;

struct PathLook {
  Rgba color;
  double radius;
  float minHalfWidth;
  bool thin = false;
  float offset = 0;
  bool aging = false;
};

// The path, fading with age (view.path_fade_seconds); sections the sphere hides go dashed and faint into `back`
// (drawn before everything in front). The points drawn in front are added to `drawn` (for label placement).
void drawPath(const SharedSpan<Vec3>& path, const SharedSamples& times, const PathLook& look,
              const PanelContext& context, const SphereCamera& camera, const Placement& placement,
              bool throughAntipode, ShapeBatch& back, ShapeBatch& front, std::vector<P2>* drawn = nullptr) {
  std::vector<PolylinePoint> points, hiddenPoints;
  points.reserve(path.size() + 1);
  const double start = times.size() > 0 ? times[0] : 0.0;
  const double span = context.frame.time - start;
  const float ghostHalfWidth = (look.thin ? 0.4f : 0.7f) * markUnit(context.unit);
  auto flushHidden = [&] {
    for (PolylinePoint& point : hiddenPoints) point.at = withinOutline(camera, point.at, point.halfWidth);
    dashedBehind(context, hiddenPoints, back);
    hiddenPoints.clear();
  };
  auto flush = [&] {
    shiftAcross(points, look.offset);
    if (placement.onSphere)
      for (PolylinePoint& point : points) {
        const P2 kept = withinOutline(camera, point.at, point.halfWidth);
        // Moved onto the sphere's image, a point's quad no longer clears the sphere: the shader decides per pixel.
        if (kept.x != point.at.x || kept.y != point.at.y) point.cover = SphereCover::PerPixel;
        point.at = kept;
      }
    // A thin path (a family's member, many at once) gives every fourth point: enough for labels to keep off it.
    if (drawn)
      for (std::size_t i = 0; i < points.size(); i += look.thin ? 4 : 1) drawn->push_back(points[i].at);
    if (look.thin) mergeStraightRuns(points, kThinPathTolerance * context.unit);
    front.polyline(points, !look.thin, 0.35f);
    points.clear();
  };
  for (std::size_t i = 0; i < path.size(); ++i) {
    const double age = i < times.size() ? context.frame.time - times[i] : 0.0;
    float alpha = pathAlpha(context.settings, age);
    float widthScale = 1;
    if (look.aging && span > 0 && i < times.size()) {
      const float young = float(std::clamp((times[i] - start) / span, 0.0, 1.0));
      alpha *= 0.45f + 0.55f * young;
      widthScale = 0.6f + 0.4f * young;
    }
    const V3 p = placement.place(path[i]);
    const bool hidden = alpha <= 0.0f || !drawable(path[i]) || !camera.inFront(p);
    const bool jump = throughAntipode && i > 0 && distance(path[i - 1], path[i]) > kMaxPathChord;
    const bool behind = !hidden && placement.onSphere && surfaceBehind(camera, p);
    if (hidden || jump) {  // a gap: draw what came before, start afresh (with this point, unless hidden)
      flush();
      flushHidden();
    }
    if (hidden) continue;
    const P2 at = camera.project(p);
    const Rgba color = palette::withAlpha(look.color, look.color.a * alpha);
    const float halfWidth = widthScale * std::max(look.minHalfWidth, float(look.radius * camera.pixelsPerUnitAt(p)));
    const float dashHalfWidth = hiddenHalfWidth(ghostHalfWidth, halfWidth);
    if (behind) {
      hiddenPoints.push_back({at, dashHalfWidth, ghost(color), {}});
    } else if (!hiddenPoints.empty()) {  // out from behind: the dashes reach the limb
      hiddenPoints.push_back({at, dashHalfWidth, ghost(color), {}});
      flushHidden();
    }
    const bool last = i + 1 == path.size();
    if (look.thin && !points.empty() && !last &&
        std::abs(at.x - points.back().at.x) + std::abs(at.y - points.back().at.y) < 1.5f * context.unit)
      continue;
    const SphereCover cover = placement.onSphere
                                  ? sphereCoverNear(camera, p, (2.0 + std::abs(look.offset)) * halfWidth + 1.0)
                                  : SphereCover::PerPixel;
    points.push_back({at, halfWidth, color, placement.world(p), cover});
  }
  flush();
  flushHidden();
}

// A run's family: each member's path as a thin line in the run's colour ramp, then the wavefront, the curve
// through the members' current points in member order, as a dark line over them, and a dot per member (a
// stopped member's dot on a red halo, as a stopped run's ball). Behind the sphere: dashed lines and rings.
void drawFamily(const RunFrame& run, const PanelContext& context, const SphereCamera& camera,
                const Placement& placement, bool throughAntipode, ShapeBatch& back, ShapeBatch& front,
                std::vector<P2>& drawn) {
  const std::size_t count = run.members.size();
  for (std::size_t m = 0; m < count; ++m) {
    const PathLook look{memberColor(run.color, m, count, 0.85f), 0.3 * kTubeRadius, 0.6f * context.unit, true, 0, false};
    drawPath(run.members[m].path, run.members[m].pathTimes, look, context, camera, placement, throughAntipode, back,
             front, &drawn);
  }
  std::vector<PolylinePoint> wavefront, hiddenWavefront;
  auto flush = [&] {
    front.polyline(wavefront, true, 0.2f);
    wavefront.clear();
    dashedBehind(context, hiddenWavefront, back);
    hiddenWavefront.clear();
  };
  const Rgba waveInk = palette::withAlpha(palette::ink, 0.9f);
  for (std::size_t m = 0; m < count; ++m) {
    const Vec3& at = run.members[m].current;
    const V3 p = placement.place(at);
    const bool jump = throughAntipode && m > 0 && distance(run.members[m - 1].current, at) > kMaxPathChord;
    if (!drawable(at) || !camera.inFront(p) || jump) flush();
    if (!drawable(at) || !camera.inFront(p)) continue;
    const float halfWidth = std::max(context.unit, float(0.45 * kTubeRadius * camera.pixelsPerUnitAt(p)));
    if (placement.onSphere && surfaceBehind(camera, p))
      hiddenWavefront.push_back(
          {camera.project(p), hiddenHalfWidth(0.7f * markUnit(context.unit), halfWidth), ghost(waveInk), {}});
    const P2 on = placement.onSphere ? withinOutline(camera, camera.project(p), halfWidth) : camera.project(p);
    wavefront.push_back({on, halfWidth, waveInk, placement.world(p)});
  }
  flush();
  for (std::size_t m = 0; m < count; ++m) {
    const MemberFrame& member = run.members[m];
    const V3 p = placement.place(member.current);
    if (!drawable(member.current) || !camera.inFront(p)) continue;
    const float pixelsPerUnit = float(camera.pixelsPerUnitAt(p));
    const float radius = std::max(1.5f * context.unit, 0.35f * float(kBallRadius) * pixelsPerUnit);
    if (placement.onSphere && surfaceBehind(camera, p)) {
      ringBehind(context, camera.project(p), radius, 0.5f * context.unit, ghost(memberColor(run.color, m, count)),
                 back);
      continue;
    }
    drawn.push_back(camera.project(p));  // a member's dot: labels keep off it as off the paths
    if (member.stopped) front.disc(camera.project(p), radius + 1.5f * context.unit, palette::stopRed, false, 0, placement.world(p));
    front.disc(camera.project(p), radius, memberColor(run.color, m, count), true, 0.3f, placement.world(p),
               radius / pixelsPerUnit);
  }
}

// Where a run's state is drawn: its ball's centre and radius on the screen, the direction of its last section
// (the velocity's, seen from the eye), and whether the sphere hides it. The direction mark is measured from
// `markAt` (the ball's centre, or the centre of the group of coinciding balls it is spread in) and drawn only by a
// `marksDirection` ball: one mark per group, as one state moves one way.
struct BallPlace {
  bool shown = false;
  P2 at;
  float radius = 0;
  P2 heading{1, 0};
  bool headingKnown = false;
  bool behind = false;
  V3 centre;
  P2 markAt;
  bool marksDirection = true;
};

BallPlace placeBall(const RunFrame& run, float unit, const SphereCamera& camera, const Placement& placement) {
  BallPlace ball;
  if (!drawable(run.current)) return ball;
  Placement ballPlacement = placement;
  ballPlacement.lift = kBallRadius;
  ball.centre = ballPlacement.place(run.current);
  if (!camera.inFront(ball.centre)) return ball;
  ball.shown = true;
  ball.at = camera.project(ball.centre);
  ball.radius = std::max(3.5f * markUnit(unit), float(kBallRadius * camera.pixelsPerUnitAt(ball.centre)));
  ball.behind = placement.onSphere && surfaceBehind(camera, ball.centre);
  // At the limb a ball resting on the surface would stand out past the outline: its centre stays on or inside it.
  if (placement.onSphere) ball.at = withinOutline(camera, ball.at, 0.0f);
  ball.markAt = ball.at;
  // The heading: from the last path point at least a few units back on the screen to the state, both as the path
  // is placed (the ball's centre, lifted higher, is shifted away from the sphere's centre on the screen: measured from
  // it, the heading would point outwards wherever the ball is off the centre).
  const V3 state = placement.place(run.current);
  if (!camera.inFront(state)) return ball;
  const P2 now = camera.project(state);
  for (std::size_t i = run.path.size(); i-- > 0;) {
    if (!drawable(run.path[i])) break;
    const V3 p = placement.place(run.path[i]);
    if (!camera.inFront(p)) break;
    const P2 q = camera.project(p);
    if (std::hypot(now.x - q.x, now.y - q.y) >= 3 * unit) {
      ball.heading = unitDirection(q, now);
      ball.headingKnown = true;
      break;
    }
  }
  return ball;
}

// Balls whose places coincide on the screen (runs in the same state) are spread across their heading, side by side
// in run order, as their paths are: each stays visible and none looks larger or ranked. The group's direction mark
// is one arrowhead from the group's centre, drawn by its first moving member (one per ball read as a double mark).
void spreadCoincidingBalls(const std::vector<RunFrame>& runs, std::vector<BallPlace>& balls) {
  std::vector<bool> done(balls.size(), false);
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (!balls[i].shown || done[i]) continue;
    std::vector<std::size_t> group{i};
    for (std::size_t j = i + 1; j < balls.size(); ++j)
      if (balls[j].shown && !done[j] &&
          std::hypot(balls[j].at.x - balls[i].at.x, balls[j].at.y - balls[i].at.y) < 0.5f * balls[i].radius)
        group.push_back(j);
    if (group.size() < 2) continue;
    const P2 centre = balls[i].at;
    const P2 across{-balls[i].heading.y, balls[i].heading.x};
    const float step = 0.9f * balls[i].radius;
    bool marked = false;
    for (std::size_t g = 0; g < group.size(); ++g) {
      BallPlace& ball = balls[group[g]];
      done[group[g]] = true;
      ball.at = plus(centre, across, step * (float(g) - 0.5f * float(group.size() - 1)));
      ball.markAt = centre;
      ball.marksDirection = !marked && !runs[group[g]].stopped && ball.headingKnown;
      marked = marked || ball.marksDirection;
    }
  }
}

// The current state of a run. In front: a shaded ball on a thin dark rim (a stopped run's on a red halo), hidden
// per pixel where the sphere's outline passes in front of it. Behind the sphere: a hollow ring in its colour (a red
// one around it when stopped), nothing inside, so it never reads as a spot on the front. The direction mark: a
// filled arrowhead just past the ball pointing along the last section of the path (a moving run only; one for a group of
// coinciding balls, past the group's centre), dark on a light halo in front (it reads on a dark path or colour map),
// faint alone behind. The arrowhead and the hidden rings are kept within the sphere's outline (a ball in front,
// standing on the surface, may stand out past it at the limb). Returns the box of an arrowhead drawn in front, for
// labels to keep clear of.
std::optional<Box> drawBall(const RunFrame& run, const BallPlace& ball, const PanelContext& context,
                            const SphereCamera& camera, const Placement& placement, ShapeBatch& back, ShapeBatch& front) {
  std::optional<Box> arrowhead;
  if (!ball.shown) return arrowhead;
  const float unit = context.unit;
  const ColorRGB& background = context.settings.background;
  const float radius = ball.radius;
  const P2 at = ball.at;
  const float mark = markUnit(unit);
  // The arrowhead starts clear of the ball: measured from the path (markAt) it could fall under the ball, which is
  // lifted off the surface and so shifted outwards on the screen near the limb. A filled arrowhead (a ribbon
  // tapering from its base to a point) reads as a direction at any angle, where two strokes pointing up and to the
  // right read as the digit 7.
  auto drawArrowhead = [&] {
    if (run.stopped || !ball.headingKnown || !ball.marksDirection) return;
    const P2 d = ball.heading, n{-d.y, d.x};
    // In mark units, but never much larger than the ball it belongs to (a small frame's floor made the arrowhead
    // twice the ball's size at 320x180).
    const float size = std::min(mark, std::max(unit, 0.15f * radius));
    const float halfWidth = (ball.behind ? 0.8f : 0.9f) * size;
    const float clear = radius + 3 * size;
    const float ox = ball.markAt.x - at.x, oy = ball.markAt.y - at.y, b = ox * d.x + oy * d.y;
    const float exit = -b + std::sqrt(std::max(b * b - (ox * ox + oy * oy - clear * clear), 0.0f));
    const float from = std::max(clear, exit);
    const P2 base = plus(ball.markAt, d, from);
    P2 tip = plus(ball.markAt, d, from + 10 * size), left = plus(base, n, 4.5f * size), right = plus(base, n, -4.5f * size);
    if (placement.onSphere) {  // moved within the outline as one piece, so it keeps its shape
      P2 shift{0, 0};
      for (const P2& point : {tip, left, right}) {
        const P2 kept = withinOutline(camera, point, halfWidth);
        if (std::hypot(kept.x - point.x, kept.y - point.y) > std::hypot(shift.x, shift.y)) shift = {kept.x - point.x, kept.y - point.y};
      }
      for (P2* point : {&tip, &left, &right}) *point = withinOutline(camera, plus(*point, shift), halfWidth);
    }
    const P2 middle{0.5f * (left.x + right.x), 0.5f * (left.y + right.y)};
    const float baseHalf = 0.5f * std::hypot(left.x - right.x, left.y - right.y);
    const auto draw = [&](ShapeBatch& into, float grow, Rgba color) {
      const P2 dir = unitDirection(middle, tip);
      into.polyline({{plus(middle, dir, -grow), baseHalf + grow, color, {}}, {plus(tip, dir, grow), 0.35f * size + grow, color, {}}});
    };
    if (ball.behind) {
      draw(back, 0, ghost(palette::ink));
    } else {
      const Rgba halo{background.r, background.g, background.b, 0.75f};
      draw(front, 0.9f * size, halo);
      draw(front, 0, palette::ink);
      const float w = halfWidth + 0.9f * size;
      arrowhead = Box{std::min({tip.x, left.x, right.x}) - w, std::min({tip.y, left.y, right.y}) - w,
                      std::max({tip.x, left.x, right.x}) + w, std::max({tip.y, left.y, right.y}) + w};
    }
  };
  if (ball.behind) {
    const float outer = 0.8f * radius + (run.stopped ? 2.5f : 0.0f) * mark + 0.9f * mark;
    const P2 ring = placement.onSphere ? withinOutline(camera, at, outer) : at;
    ringBehind(context, ring, 0.8f * radius, 0.9f * mark, ghost(toRgba(run.color)), back);
    if (run.stopped) ringBehind(context, ring, 0.8f * radius + 2.5f * mark, 0.8f * mark, ghost(palette::stopRed), back);
    drawArrowhead();
    return arrowhead;
  }
  Placement ballPlacement = placement;
  ballPlacement.lift = kBallRadius;
  const Occludable world = ballPlacement.world(ball.centre);
  const float pixelsPerUnit = float(camera.pixelsPerUnitAt(ball.centre));
  // A stopped run's ball sits on a red halo (a larger ball behind it, hidden with it by the sphere).
  if (run.stopped) front.disc(at, radius + 2.5f * unit, palette::stopRed, true, 0.2f, world, (radius + 2.5f * unit) / pixelsPerUnit);
  // A thin dark rim sets the ball off from its own path, which has its colour (small frames lost it in the tube).
  else front.disc(at, radius + unit, palette::withAlpha(palette::ink, 0.75f), false, 0, world, (radius + unit) / pixelsPerUnit);
  front.disc(at, radius, toRgba(run.color), true, 0.55f, world, radius / pixelsPerUnit);
  drawArrowhead();  // over the ball: where the outline pushes it back, it is never hidden by its own ball
  return arrowhead;
}

// The start of a run's path: a short dark bar across its first section (faint where the sphere hides it), kept
// within the sphere's outline as the path is (each end a half width inside it, so a bar at the limb is shortened).
void drawStart(const RunFrame& run, float offset, float unit, const SphereCamera& camera, const Placement& placement,
               ShapeBatch& back, ShapeBatch& front) {
  if (run.path.size() < 2 || !drawable(run.path[0])) return;
  const V3 p = placement.place(run.path[0]);
  if (!camera.inFront(p)) return;
  const P2 at = camera.project(p);
  P2 along{1, 0};
  for (std::size_t i = 1; i < run.path.size() && drawable(run.path[i]); ++i) {
    const P2 q = camera.project(placement.place(run.path[i]));
    if (std::hypot(q.x - at.x, q.y - at.y) >= 2 * unit) {
      along = unitDirection(at, q);
      break;
    }
  }
  const float mark = markUnit(unit);
  const P2 across{-along.y, along.x};
  const float tube = std::max(1.8f * unit, float(kTubeRadius * camera.pixelsPerUnitAt(p)));
  const float half = 2.2f * tube + 2 * mark;
  const bool behind = placement.onSphere && surfaceBehind(camera, p);
  const float halfWidth = (behind ? 0.7f : 1.1f) * mark;
  const P2 middle = plus(at, across, offset * tube);
  P2 from = plus(middle, across, -half), to = plus(middle, across, half);
  if (placement.onSphere) {
    from = withinOutline(camera, from, halfWidth);
    to = withinOutline(camera, to, halfWidth);
  }
  if (behind) {
    back.capsule(from, to, halfWidth, ghost(palette::ink));
    return;
  }
  front.capsule(from, to, halfWidth, palette::ink, false, 0, placement.world(p));
}

// Conjugate points on the path (runs with Jacobi fields): an ink ring around a dot of the run's colour, where
// the geodesics leaving the start together meet again; behind the sphere the faint ring alone.
void drawConjugatePoints(const RunFrame& run, float unit, const SphereCamera& camera, const Placement& placement,
                         ShapeBatch& back, ShapeBatch& front) {
  Placement markPlacement = placement;
  markPlacement.lift = 1.5 * kTubeRadius;
  for (const Vec3& point : run.conjugatePoints) {
    const V3 p = markPlacement.place(point);
    if (!drawable(point) || !camera.inFront(p)) continue;
    const float pixelsPerUnit = float(camera.pixelsPerUnitAt(p));
    const float radius = std::max(3.0f * markUnit(unit), 0.7f * float(kBallRadius) * pixelsPerUnit);
    if (placement.onSphere && surfaceBehind(camera, p)) {
      back.ring(camera.project(p), 0.85f * radius, 0.8f * markUnit(unit), ghost(palette::ink));
      continue;
    }
    const Occludable world = markPlacement.world(p);
    front.disc(camera.project(p), radius, palette::ink, false, 0, world, radius / pixelsPerUnit);
    front.disc(camera.project(p), 0.6f * radius, toRgba(run.color), true, 0.3f, world, 0.6f * radius / pixelsPerUnit);
  }
}

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

// 5+ rods: the ball view explained (frames/configuration_view.hpp): the ring of radius 1/2 (the great sphere at a
// right angle from the start) outlined, and a caption, wrapped to the panel, saying what the start mark, the
// radius, the ring and the rim mean and, for n > 5, which directions are shown.
void drawBallGuide(const PanelContext& context, const SphereCamera& camera, ShapeBatch& batch) {
  const V3 centre{0, 0, 0};
  const P2 at = camera.project(centre);
  const float half = float(0.5 * camera.pixelsPerUnitAt(centre));
  std::vector<PolylinePoint> ring;
  for (int k = 0; k <= 96; ++k) {
    const double a = 2 * std::acos(-1.0) * k / 96;
    ring.push_back({{at.x + half * float(std::cos(a)), at.y + half * float(std::sin(a))}, 0.8f * context.unit,
                    palette::withAlpha(palette::softInk, 0.55f), {}});
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
    context.font.draw(batch, text, TextSize::Small, context.rect.x + pad, y, palette::softInk);
    y += line;
  }
}

// The start of a 5+ rod path, the ball's centre: a cross drawn over the paths, on a halo of the background so it
// stays visible where a path runs through it.
void drawBallStart(const PanelContext& context, const SphereCamera& camera, ShapeBatch& batch) {
  const V3 centre{0, 0, 0};
  const P2 at = camera.project(centre);
  const float arm = std::max(4.0f * markUnit(context.unit), 0.035f * float(camera.pixelsPerUnitAt(centre)));
  const float width = std::max(0.9f * markUnit(context.unit), 0.12f * arm);
  const ColorRGB& b = context.settings.background;
  const Rgba halo{b.r, b.g, b.b, 0.9f};
  batch.capsule({at.x - arm, at.y}, {at.x + arm, at.y}, width + 1.2f * markUnit(context.unit), halo);
  batch.capsule({at.x, at.y - arm}, {at.x, at.y + arm}, width + 1.2f * markUnit(context.unit), halo);
  batch.capsule({at.x - arm, at.y}, {at.x + arm, at.y}, width, palette::ink);
  batch.capsule({at.x, at.y - arm}, {at.x, at.y + arm}, width, palette::ink);
}

// 3 rods: the configuration circle, the equator.
void drawEquator(const SphereCamera& camera, float unit, ShapeBatch& batch) {
  std::vector<PolylinePoint> points;
  const double pi = std::acos(-1.0);
  for (int k = 0; k <= 256; ++k) {
    const V3 p{std::cos(2 * pi * k / 256), std::sin(2 * pi * k / 256), 0};
    points.push_back({camera.project(p), 1.2f * unit, palette::withAlpha(palette::softInk, 0.8f), {}});
  }
  batch.polyline(points);
}

// Stiffness ellipses as light filled glyphs riding on the sphere (over the dark end of a colour map as over its
// light end: a half-white fill, a white stroke on a faint dark halo), hidden where the sphere is in front of them.
void drawEllipses(const std::vector<SphereEllipse>& ellipses, const SphereCamera& camera, const Placement& placement,
                  const PixelRect& rect, float unit, ShapeBatch& batch) {
  constexpr int kSegments = 40;
  const float halfWidth = std::max(0.6f * unit, 0.0011f * rect.height);
  const V3 eye = camera.eye();
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
      const V3 placed = placement.place(p);
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
      const Vec3 side{e.centre.x + across * e.minor.x, e.centre.y + across * e.minor.y, e.centre.z + across * e.minor.z};
      const V3 placed = placement.place(p);
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

// A label at `anchor` placed by `placer` where it covers nothing else: on a pad of the background, joined to its
// anchor by a thin leader line when it had to move away. Faint (the far side's look) when `hidden`.
void drawLabel(const std::string& text, P2 anchor, bool hidden, const PanelContext& context, LabelPlacer& placer,
               std::vector<PixelRect>& placed, ShapeBatch& batch) {
  const float ascent = context.font.ascent(TextSize::Small), pad = 0.25f * ascent;
  const float width = context.font.width(text, TextSize::Small) + 2 * pad, height = 1.45f * ascent + 2 * pad;
  const auto spot = placer.place(anchor, width, height, 0.9f * ascent);
  if (!spot) return;  // no room in the panel
  const Box& box = spot->first;
  const Rgba ink = hidden ? ghost(palette::softInk) : palette::softInk;
  if (spot->second) {  // the leader: from the anchor (or the edge of a ball over it) to the nearest point of the box
    const P2 to{std::clamp(anchor.x, box.x0, box.x1), std::clamp(anchor.y, box.y0, box.y1)};
    const P2 from = placer.leaderStart(anchor, to);
    if (std::hypot(to.x - from.x, to.y - from.y) > markUnit(context.unit)) {
      batch.capsule(from, to, 0.5f * markUnit(context.unit), ink);
      placer.recordLeader(from, to);
    }
  }
  const ColorRGB& b = context.settings.background;
  batch.rect(box.x0, box.y0, box.x1, box.y1, {b.r, b.g, b.b, 0.7f});
  context.font.draw(batch, text, TextSize::Small, box.x0 + pad, box.y0 + pad + 1.1f * ascent, ink);
  placed.push_back({box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0});
}

// The widest a label on the sphere may be: a share of the sphere's radius on the screen, so that a label is as large
// a part of the picture at every frame size. Text has a legibility floor (10 px), so a small frame takes a label's
// shorter form (render/frame_words.hpp: "φ = 90°", then "N"), never a label that crowds the sphere.
float labelBudget(const SphereCamera& camera) { return 0.5f * float(camera.pixelsPerUnitAt(V3{0, 0, 0})); }

// 4 rods: the chart's poles (phi = +-pi/2, where t is undefined and the published single-chart methods fail) are
// marked by the sphere shader on the front; both are named, a pole behind the sphere as a faint ring and label.
void labelChartPoles(const PanelContext& context, const SphereCamera& camera, LabelPlacer& placer,
                     std::vector<PixelRect>& placed, ShapeBatch& back, ShapeBatch& batch) {
  for (const double z : {1.0, -1.0}) {
    const V3 pole{0, 0, z * 1.001};
    if (!camera.inFront(pole)) continue;
    const P2 at = camera.project(pole);
    const bool hidden = behindSphere(camera, pole);
    const float mark = markUnit(context.unit);
    if (hidden) ringBehind(context, at, 4 * mark, 0.6f * mark, ghost(palette::poleMark), back);
    drawLabel(fittedForm(context.font, chartPoleLabels(z > 0), TextSize::Small, labelBudget(camera)), at, hidden, context,
              placer, placed, batch);
  }
}

// The seams t = +-pi/2 (view.sphere.seam), where the published metric divides by zero: two meridians drawn as dashed
// red lines on the sphere (fainter behind it), one named where it faces the eye. The lines ride on the sphere under
// the paths and balls (`surface`), kept within its outline; the name goes with the labels.
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
      const V3 p{1.003 * std::cos(phi) * std::cos(t), 1.003 * std::cos(phi) * std::sin(t), 1.003 * std::sin(phi)};
      if (!camera.inFront(p)) continue;
      const bool hidden = surfaceBehind(camera, p);
      auto& side = hidden ? back_ : front_;
      auto& other = hidden ? front_ : back_;
      if (!other.empty()) flush();
      side.push_back({camera.project(p), (hidden ? 0.6f : 1.0f) * context.unit, hidden ? ghost(red) : red, {}});
      if (!hidden) placer.avoidPoint(camera.project(p));  // labels keep off the seam as off the paths
      const V3 eye = camera.eye();
      const double facing = (p.x * eye.x + p.y * eye.y + p.z * eye.z) / std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
      // A seam is named at a point of it in sight: not under a ball (a state on the seam covers it there).
      if (!hidden && std::abs(phi) < 1.2 && facing > namedFacing && !placer.onBall(camera.project(p))) {
        namedFacing = facing;
        named = camera.project(p);
      }
    }
    flush();
  }
  if (named)
    drawLabel(fittedForm(context.font, seamLabels(), TextSize::Small, labelBudget(camera)), *named, false, context, placer,
              placed, labels);
}

// The distance colouring's loci and the closed geodesics (frame_state.hpp SphereCurve) riding on the sphere: a locus
// a line of its colour on a thin dark halo, a closed geodesic a faint thin ink line; what the sphere hides dashed and
// faint (the far-side convention), each kind named once where it faces the eye most. A point the scene names (not
// the start, which the path's bar marks) gets an ink ring over the paths (faint behind the sphere) and a label.
void drawLoci(const SphereDecoration& decoration, const PanelContext& context, const SphereCamera& camera,
              LabelPlacer& placer, std::vector<PixelRect>& placed, ShapeBatch& surface, ShapeBatch& back,
              ShapeBatch& labels) {
  const Placement onSurface{true, 0.006};
  const float halfWidth = std::max(1.1f * markUnit(context.unit), 0.0021f * context.rect.height);
  const float ghostHalfWidth = 0.6f * markUnit(context.unit);
  const V3 eye = camera.eye();
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
      const V3 p = onSurface.place(point);
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
    const V3 p = onSurface.place(x);
    if (camera.inFront(p)) {
      const bool behind = behindSphere(camera, p);
      const float radius = std::max(5 * markUnit(context.unit), 0.012f * context.rect.height);
      (behind ? back : labels).ring(camera.project(p), radius, (behind ? 0.6f : 1.2f) * markUnit(context.unit),
                                    behind ? ghost(palette::ink) : palette::ink);  // over the paths
      drawLabel("distance measured from here", camera.project(p), behind, context, placer, placed, labels);
    }
  }
  for (const auto& [kind, name] : names)
    if (name.at) drawLabel(curveName(kind), *name.at, false, context, placer, placed, labels);
}

// A vector carried round a geodesic polygon (view.sphere.holonomy), every side at once at the frame's fraction of
// the animation (SphereTransport): behind each carried vector the arrows it left at every other sample, ink on a
// light halo (faint where the sphere hides it); the carried vectors heavier; the starting vector at the first corner,
// whose corner is ringed, and at the end the returning vector beside it in its own colour. The arrows left behind fade
// as the paths do (view.path_fade_seconds). An arrow spans
// kTransportArrowLength of the sphere whatever the frame's size; its width follows the frame's unit, as the paths' do.
constexpr double kTransportArrowLength = 0.2;
void drawTransport(const SphereTransport& transport, const PanelContext& context, const SphereCamera& camera,
                   LabelPlacer& placer, ShapeBatch& back, ShapeBatch& front) {
  const Placement onSurface{true, 0.012};
  const float mark = markUnit(context.unit);
  const Rgba halo{1, 1, 1, 0.75f};  // over the sphere's colours, not the background
  const auto drawArrow = [&](const SphereTransport::Arrow& arrow, Rgba color, float weight) {
    const Vec3 tip{arrow.base.x + kTransportArrowLength * arrow.direction.x,
                   arrow.base.y + kTransportArrowLength * arrow.direction.y,
                   arrow.base.z + kTransportArrowLength * arrow.direction.z};
    const V3 from3 = onSurface.place(arrow.base), to3 = onSurface.place(tip);
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
    const V3 corner = onSurface.place(transport.corners.front());
    if (camera.inFront(corner) && !surfaceBehind(camera, corner))
      front.ring(camera.project(corner), 4.5f * mark, 0.9f * mark, palette::ink);
  }
}

// A family on the sphere explained where no text panel does it: the run, its members and their wavefront, in the
// panel's bottom-left corner (wrapped to at most two lines; the ball view's caption takes that corner there).
void captionFamilies(const PanelContext& context, float width, ShapeBatch& batch) {
  std::size_t members = 0;
  for (const RunFrame& run : context.frame.runs) members = std::max(members, run.members.size());
  if (members == 0) return;
  const float pad = 0.02f * context.rect.height, line = context.font.lineHeight(TextSize::Small);
  // The longest form that wraps into two lines with every word whole; the shortest, cut, where none does.
  const std::vector<std::string> lines =
      wrappedFittedForm(context.font, familyCaptions(members), TextSize::Small, width - 2 * pad, 2);
  float y = context.rect.y + context.rect.height - pad - line * float(lines.size() - 1);
  for (const std::string& caption : lines) {
    context.font.draw(batch, caption, TextSize::Small, context.rect.x + pad, y, palette::softInk);
    y += line;
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
  SphereCamera camera(cameraOfFrame(context.settings.camera, context.frame), context.frame.time, sphereRect);
  const Placement placement{space == ViewSpace::Sphere, kTubeRadius};
  // Captions at the panel's foot: the ball view's, the stiffness ellipses', or (no text panel) a family's.
  const std::vector<PanelSpec> panels = effectivePanels(context.settings);
  const bool textPanel =
      std::any_of(panels.begin(), panels.end(), [](const PanelSpec& p) { return p.kind == PanelKind::Text; });
  // A holonomy's figures go under the sphere unless a text panel says them.
  const bool transportCaption = decoration && decoration->transport && !textPanel;
  const bool captioned = space == ViewSpace::Ball || (decoration && !decoration->ellipses.empty()) || transportCaption;
  const bool families = std::any_of(context.frame.runs.begin(), context.frame.runs.end(),
                                    [](const RunFrame& run) { return !run.members.empty(); });
  // Labels stay in the sphere's part of the panel, clear of the colour bar and of the captions at its foot (room for
  // them only where there are some: a pole near the panel's foot keeps its label beside it).
  const float captionRoom =
      captioned || (families && !textPanel) ? 2.4f * context.font.lineHeight(TextSize::Small) : 0.0f;
  LabelPlacer placer({sphereRect.x, sphereRect.y, sphereRect.width, sphereRect.height - captionRoom});
  std::vector<PixelRect> labels;
  PixelRect colorBarBox{};
  if (space == ViewSpace::Circle) drawEquator(camera, context.unit, batch);
  if (space == ViewSpace::Ball) drawBallGuide(context, camera, batch);
  if (decoration) {
    const float pad = 0.02f * context.rect.height;
    const Placement onSurface{true, 0.004};
    drawEllipses(decoration->ellipses, camera, onSurface, context.rect, context.unit, batch);
    // The captions at the foot, bottom up: the ellipses', then the holonomy's.
    const float width = context.rect.width - 2 * pad - (colored ? colorBarStrip(context.rect) : 0);
    float foot = context.rect.y + context.rect.height - pad;
    if (!decoration->ellipses.empty()) {
      context.font.draw(batch, fittedForm(context.font, ellipseCaptions(), TextSize::Small, width), TextSize::Small,
                        context.rect.x + pad, foot, palette::softInk);
      foot -= context.font.lineHeight(TextSize::Small);
    }
    if (transportCaption)
      context.font.draw(
          batch,
          fittedForm(context.font,
                     transportCaptions(*decoration->transport, context.frame.time, context.frame.duration),
                     TextSize::Small, width),
          TextSize::Small, context.rect.x + pad, foot, palette::ink);
    if (colored) {
      const SphereField& field = *decoration->field;
      // A gap of a text line from the panel's right edge: the bar never butts against a neighbouring plot's axis.
      const float gap = context.font.lineHeight(TextSize::Small);
      const PixelRect bar{context.rect.x + context.rect.width - colorBarStrip(context.rect), context.rect.y + pad,
                          colorBarStrip(context.rect) - pad - gap, 0.8f * context.rect.height};
      const bool fromStart = !decoration->distance || decoration->distance->fromStart;
      const std::string caption =
          fittedForm(context.font, fieldCaptions(field.coloring, fromStart), TextSize::Small, bar.width);
      // The note under the bar wraps onto two lines at most; a narrow strip takes a shorter form, never a cut one.
      const std::vector<std::string> notes =
          field.diverging       ? twoSlopeNotes()
          : decoration->distance ? injectivityNotes(decoration->distance->injectivityRadius, fromStart)
                                 : std::vector<std::string>{};
      const std::string note = fittedWrappedForm(context.font, notes, TextSize::Small, bar.width, 2);
      drawColorBar(scaleOf(field), caption, note, bar, context.font, batch);
      colorBarBox = bar;
    }
  }
  // What the sphere hides goes into `back`, drawn before everything in front of it.
  ShapeBatch back, front;
  const bool throughAntipode = space == ViewSpace::Ball;
  const auto& runs = context.frame.runs;
  std::vector<P2> pathPoints;  // where the paths are drawn in front, for labels to keep off
  for (const RunFrame& run : runs) drawFamily(run, context, camera, placement, throughAntipode, back, front, pathPoints);
  // Several runs: side by side where they coincide (each shifted by its half width times 2k - (n - 1), narrower by
  // 1/sqrt(n), so n coinciding paths make one band of equal stripes), older sections thinner and fainter
  // (unless the scene fades paths out itself).
  const bool several = runs.size() > 1;
  const auto offsetOf = [&](std::size_t k) { return several ? 2.0f * (float(k) - 0.5f * float(runs.size() - 1)) : 0.0f; };
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const float narrower = std::max(0.45f, 1.0f / std::sqrt(float(runs.size())));
    const PathLook look{toRgba(runs[k].color), narrower * kTubeRadius, narrower * 1.8f * context.unit, false,
                        offsetOf(k), several && context.settings.pathFadeSeconds <= 0};
    drawPath(runs[k].path, runs[k].pathTimes, look, context, camera, placement, throughAntipode, back, front,
             &pathPoints);
  }
  if (space != ViewSpace::Ball)  // the ball view's start is its centre, marked by drawBallStart
    for (std::size_t k = 0; k < runs.size(); ++k)
      drawStart(runs[k], offsetOf(k), context.unit, camera, placement, back, front);
  for (const RunFrame& run : runs) drawConjugatePoints(run, context.unit, camera, placement, back, front);
  if (space == ViewSpace::Ball) drawBallStart(context, camera, front);
  std::vector<BallPlace> balls;
  for (const RunFrame& run : runs) balls.push_back(placeBall(run, context.unit, camera, placement));
  spreadCoincidingBalls(runs, balls);
  std::vector<PixelRect> ballBoxes;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    if (const auto arrowhead = drawBall(runs[k], balls[k], context, camera, placement, back, front)) placer.avoid(*arrowhead);
    if (!balls[k].shown) continue;
    const float r = balls[k].radius + 2.5f * context.unit;
    placer.avoidBall(balls[k].at, r);
    ballBoxes.push_back({balls[k].at.x - r, balls[k].at.y - r, 2 * r, 2 * r});
  }
  for (const P2& p : pathPoints) placer.avoidPoint(p);
  if (decoration && decoration->transport) drawTransport(*decoration->transport, context, camera, placer, back, front);
  // Labels over the paths (never struck through), placed clear of the balls, the paths and each other.
  ShapeBatch labelLayer, loci;  // the loci ride on the sphere, under every path
  if (decoration && decoration->seam) drawSeams(context, camera, placer, labels, loci, back, labelLayer);
  if (decoration && !decoration->curves.empty()) drawLoci(*decoration, context, camera, placer, labels, loci, back, labelLayer);
  if (space == ViewSpace::Sphere) labelChartPoles(context, camera, placer, labels, back, labelLayer);
  batch.append(loci);
  batch.append(back);
  batch.append(front);
  batch.append(labelLayer);
  if (!captioned && !textPanel) captionFamilies(context, sphereRect.width, batch);
  const SphereLook look = colored ? SphereLook::Colored : space == ViewSpace::Sphere ? SphereLook::Opaque : SphereLook::Glass;
  return {camera, look, labels, ballBoxes, placer.leaders(), colorBarBox};
}

}  // namespace sl

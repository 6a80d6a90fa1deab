#include "render/sphere_parts.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "render/color_map.hpp"
#include "render/frame_words.hpp"
#include "render/palette.hpp"
#include "render/panel_layout.hpp"

namespace sl::detail {

void drawPath(const SharedSpan<Vec3>& path, const SharedSamples& times, const PathLook& look,
              const PanelContext& context, const SphereCamera& camera, const Placement& placement, bool throughAntipode,
              ShapeBatch& back, ShapeBatch& front, std::vector<P2>* drawn) {
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
    const Vec3 p = placement.place(path[i]);
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

void drawFamily(const RunFrame& run, const PanelContext& context, const SphereCamera& camera,
                const Placement& placement, bool throughAntipode, ShapeBatch& back, ShapeBatch& front,
                std::vector<P2>& drawn) {
  const std::size_t count = run.members.size();
  for (std::size_t m = 0; m < count; ++m) {
    const PathLook look{
        memberColor(run.color, m, count, 0.85f), 0.3 * kTubeRadius, 0.6f * context.unit, true, 0, false};
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
    const Vec3 p = placement.place(at);
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
    const Vec3 p = placement.place(member.current);
    if (!drawable(member.current) || !camera.inFront(p)) continue;
    const float pixelsPerUnit = float(camera.pixelsPerUnitAt(p));
    const float radius = std::max(1.5f * context.unit, 0.35f * float(kBallRadius) * pixelsPerUnit);
    if (placement.onSphere && surfaceBehind(camera, p)) {
      ringBehind(context, camera.project(p), radius, 0.5f * context.unit, ghost(memberColor(run.color, m, count)),
                 back);
      continue;
    }
    drawn.push_back(camera.project(p));  // a member's dot: labels keep off it as off the paths
    if (member.stopped)
      front.disc(camera.project(p), radius + 1.5f * context.unit, palette::stopRed, false, 0, placement.world(p));
    front.disc(camera.project(p), radius, memberColor(run.color, m, count), true, 0.3f, placement.world(p),
               radius / pixelsPerUnit);
  }
}

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
  const Vec3 state = placement.place(run.current);
  if (!camera.inFront(state)) return ball;
  const P2 now = camera.project(state);
  for (std::size_t i = run.path.size(); i-- > 0;) {
    if (!drawable(run.path[i])) break;
    const Vec3 p = placement.place(run.path[i]);
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

std::optional<Box> drawBall(const RunFrame& run, const BallPlace& ball, const PanelContext& context,
                            const SphereCamera& camera, const Placement& placement, ShapeBatch& back,
                            ShapeBatch& front) {
  std::optional<Box> arrowhead;
  if (!ball.shown) return arrowhead;
  const float unit = context.unit;
  const float radius = ball.radius;
  const P2 at = ball.at;
  const float mark = markUnit(unit);
  const Rgba rim = palette::withAlpha(palette::ink, 0.75f);  // the ball's, and its arrowhead's
  // The arrowhead starts just past the ball's rim: measured from the path (markAt) it could fall under the ball,
  // which is lifted off the surface and so shifted outwards on the screen near the limb. A filled arrowhead (a
  // ribbon tapering from its base to a point) reads as a direction at any angle, where two strokes pointing up and to
  // the right read as the digit 7. It is the run's colour with the ball's dark rim, so ball and arrowhead read as one
  // thing pointing the way it moves: a black one on a light halo, apart from the ball, read as a mouse pointer.
  auto drawArrowhead = [&] {
    if (run.stopped || !ball.headingKnown || !ball.marksDirection) return;
    const P2 d = ball.heading, n{-d.y, d.x};
    // In mark units, but never much larger than the ball it belongs to (a small frame's floor made the arrowhead
    // twice the ball's size at 320x180).
    const float size = std::min(mark, std::max(unit, 0.15f * radius));
    const float halfWidth = (ball.behind ? 0.8f : 0.9f) * size;
    const float clear = radius + 1.0f * size;
    const float ox = ball.markAt.x - at.x, oy = ball.markAt.y - at.y, b = ox * d.x + oy * d.y;
    const float exit = -b + std::sqrt(std::max(b * b - (ox * ox + oy * oy - clear * clear), 0.0f));
    const float from = std::max(clear, exit);
    const P2 base = plus(ball.markAt, d, from);
    P2 tip = plus(ball.markAt, d, from + 10 * size), left = plus(base, n, 4.5f * size),
       right = plus(base, n, -4.5f * size);
    if (placement.onSphere) {  // moved within the outline as one piece, so it keeps its shape
      P2 shift{0, 0};
      for (const P2& point : {tip, left, right}) {
        const P2 kept = withinOutline(camera, point, halfWidth);
        if (std::hypot(kept.x - point.x, kept.y - point.y) > std::hypot(shift.x, shift.y))
          shift = {kept.x - point.x, kept.y - point.y};
      }
      for (P2* point : {&tip, &left, &right}) *point = withinOutline(camera, plus(*point, shift), halfWidth);
    }
    const P2 middle{0.5f * (left.x + right.x), 0.5f * (left.y + right.y)};
    const float baseHalf = 0.5f * std::hypot(left.x - right.x, left.y - right.y);
    const auto draw = [&](ShapeBatch& into, float grow, Rgba color) {
      const P2 dir = unitDirection(middle, tip);
      into.polyline({{plus(middle, dir, -grow), baseHalf + grow, color, {}},
                     {plus(tip, dir, grow), 0.35f * size + grow, color, {}}});
    };
    if (ball.behind) {
      draw(back, 0, ghost(palette::ink));
    } else {
      draw(front, 0.5f * size, rim);
      draw(front, 0, toRgba(run.color));
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
  if (run.stopped)
    front.disc(at, radius + 2.5f * unit, palette::stopRed, true, 0.2f, world, (radius + 2.5f * unit) / pixelsPerUnit);
  // A thin dark rim sets the ball off from its own path, which has its colour (small frames lost it in the tube).
  else
    front.disc(at, radius + unit, rim, false, 0, world, (radius + unit) / pixelsPerUnit);
  front.disc(at, radius, toRgba(run.color), true, 0.55f, world, radius / pixelsPerUnit);
  drawArrowhead();  // over the ball: where the outline pushes it back, it is never hidden by its own ball
  return arrowhead;
}

void drawStart(const RunFrame& run, float offset, float unit, const SphereCamera& camera, const Placement& placement,
               ShapeBatch& back, ShapeBatch& front) {
  if (run.path.size() < 2 || !drawable(run.path[0])) return;
  const Vec3 p = placement.place(run.path[0]);
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

void drawConjugatePoints(const RunFrame& run, float unit, const SphereCamera& camera, const Placement& placement,
                         ShapeBatch& back, ShapeBatch& front) {
  Placement markPlacement = placement;
  markPlacement.lift = 1.5 * kTubeRadius;
  for (const Vec3& point : run.conjugatePoints) {
    const Vec3 p = markPlacement.place(point);
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

}  // namespace sl::detail

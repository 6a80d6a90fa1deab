#include "render/shape_batch.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace sl {
namespace {

// Pixels of quad beyond the shape, room for the anti-aliased edge: a pixel's coverage reaches zero where its centre is
// half a pixel past the edge (common.glsl's edgeCoverage and bandCoverage), so half a pixel is all a quad needs.
// Thin quads pay for every pixel of margin: a 1.1 px grid line's ribbon was 3.1 px wide with a whole pixel's.
constexpr float kMargin = 0.5f;

P2 operator+(P2 a, P2 b) { return {a.x + b.x, a.y + b.y}; }
P2 operator-(P2 a, P2 b) { return {a.x - b.x, a.y - b.y}; }
P2 operator*(float s, P2 a) { return {s * a.x, s * a.y}; }
float length(P2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }
P2 normal(P2 from, P2 to) {
  const P2 d = to - from;
  const float len = length(d);
  return len > 1e-6f ? P2{-d.y / len, d.x / len} : P2{0, 1};
}

ShapeVertex vertex(P2 at, P2 local, ShapeKind kind, float size, float extra, Rgba color, bool shaded, float specular,
                   P2 axis, Occludable world) {
  return {at.x,
          at.y,
          local.x,
          local.y,
          static_cast<float>(kind),
          size,
          extra,
          specular,
          color.r,
          color.g,
          color.b,
          color.a,
          axis.x,
          axis.y,
          world.x,
          world.y,
          world.z,
          world.w,
          shaded ? 1.0f : 0.0f};
}

}  // namespace

void ShapeBatch::quad(const ShapeVertex corners[4]) {
  const ShapeVertex& v = corners[0];
  const ShapeProgram program = v.kind == float(ShapeKind::Glyph)                      ? ShapeProgram::Glyph
                               : (v.shaded > 0.5f || v.ww > 0.5f || v.ww < -0.5f) ? ShapeProgram::Lit
                                                                                      : ShapeProgram::Flat;
  if (segments_.empty() || segments_.back().program != program) segments_.push_back({program, vertices_.size(), 0});
  segments_.back().count += 6;
  for (int i : {0, 1, 2, 0, 2, 3}) vertices_.push_back(corners[i]);
}

void ShapeBatch::capsule(P2 a, P2 b, float halfWidth, Rgba color, bool shaded, float specular, Occludable world) {
  const float len = length(b - a);
  const P2 n = normal(a, b);
  const P2 d{n.y, -n.x};
  const float e = halfWidth + kMargin;
  auto make = [&](P2 at, float s, float u) {
    return vertex(at, {s, u}, ShapeKind::Capsule, halfWidth, len, color, shaded, specular, n, world);
  };
  const ShapeVertex corners[4] = {make(a - e * d - e * n, -e, -e), make(b + e * d - e * n, len + e, -e),
                                  make(b + e * d + e * n, len + e, e), make(a - e * d + e * n, -e, e)};
  quad(corners);
}

void ShapeBatch::disc(P2 c, float radius, Rgba color, bool shaded, float specular, Occludable world,
                      float worldRadius) {
  const float e = radius + kMargin;
  auto make = [&](float dx, float dy) {
    return vertex(c + P2{dx, dy}, {dx, dy}, ShapeKind::Disc, radius, worldRadius, color, shaded, specular, {0, 1},
                  world);
  };
  const ShapeVertex corners[4] = {make(-e, -e), make(e, -e), make(e, e), make(-e, e)};
  quad(corners);
}

void ShapeBatch::polyline(const std::vector<PolylinePoint>& input, bool shaded, float specular) {
  // Points closer than half a pixel add vertices but nothing visible; keep the last one regardless.
  std::vector<PolylinePoint> points;
  points.reserve(input.size());
  for (std::size_t i = 0; i < input.size(); ++i) {
    const bool last = i + 1 == input.size();
    if (points.empty() || length(input[i].at - points.back().at) > 0.5f) {
      points.push_back(input[i]);
    } else if (last) {
      points.back() = input[i];
    }
  }
  // A mitre cannot turn sharper than ~60 degrees without folding its quads over a wide area (as a
  // path does where it crosses the sphere's outline in projection): the strip restarts there.
  std::size_t start = 0;
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const P2 a = points[i].at - points[i - 1].at, b = points[i + 1].at - points[i].at;
    if (a.x * b.x + a.y * b.y < 0.5f * length(a) * length(b)) {
      strip(points, start, i + 1, shaded, specular);
      start = i;
    }
  }
  strip(points, start, points.size(), shaded, specular);
}

void ShapeBatch::strip(const std::vector<PolylinePoint>& all, std::size_t begin, std::size_t end, bool shaded,
                       float specular) {
  if (end < begin + 2) return;
  const PolylinePoint* points = all.data() + begin;
  const std::size_t count = end - begin;
  std::vector<P2> miter(count);
  std::vector<float> miterScale(count, 1.0f);
  for (std::size_t i = 0; i < count; ++i) {
    const P2 before = i > 0 ? normal(points[i - 1].at, points[i].at) : normal(points[i].at, points[i + 1].at);
    const P2 after = i + 1 < count ? normal(points[i].at, points[i + 1].at) : before;
    P2 m = before + after;
    const float len = length(m);
    m = len > 1e-3f ? (1.0f / len) * m : before;
    miter[i] = m;
    miterScale[i] = 1.0f / std::max(m.x * before.x + m.y * before.y, 0.5f);
  }
  auto make = [&](std::size_t i, float side) {
    const PolylinePoint& p = points[i];
    const float e = p.halfWidth + kMargin;
    return vertex(p.at + (side * e * miterScale[i]) * miter[i], {0, side * e}, ShapeKind::Capsule, p.halfWidth, -1,
                  p.color, shaded, specular, miter[i], p.world);
  };
  for (std::size_t i = 0; i + 1 < count; ++i) {
    const SphereCover a = points[i].cover, b = points[i + 1].cover;
    if (a == SphereCover::Hidden && b == SphereCover::Hidden) continue;
    ShapeVertex corners[4] = {make(i, -1), make(i + 1, -1), make(i + 1, 1), make(i, 1)};
    // Still lit (lit.frag lights every occludable shape, shaded or not), but not tested against the sphere.
    if (a == SphereCover::Clear && b == SphereCover::Clear && corners[0].ww > 0.5f)
      for (ShapeVertex& corner : corners) corner.ww = -1;
    quad(corners);
  }
}

void mergeStraightRuns(std::vector<PolylinePoint>& points, float tolerance) {
  constexpr std::size_t kLongestRun = 64;  // points dropped between two kept ones at most (bounds the work)
  if (points.size() < 3) return;
  // Whether every point strictly between a and b is drawn as the section a-b would draw it.
  auto straight = [&](std::size_t a, std::size_t b) {
    const PolylinePoint &from = points[a], &to = points[b];
    const P2 d = to.at - from.at;
    const float len = length(d);
    if (len < 1e-6f) return false;
    for (std::size_t i = a + 1; i < b; ++i) {
      const PolylinePoint& p = points[i];
      if (p.cover != from.cover || p.cover != to.cover || p.world.w != from.world.w) return false;
      const P2 r = p.at - from.at;
      if (std::abs(r.x * d.y - r.y * d.x) > tolerance * len) return false;
      const float u = std::clamp((r.x * d.x + r.y * d.y) / (len * len), 0.0f, 1.0f);
      auto off = [u](float x, float y, float z) { return std::abs(x + u * (y - x) - z); };
      if (off(from.halfWidth, to.halfWidth, p.halfWidth) > 0.01f) return false;
      const float level = 0.5f / 255;
      if (off(from.color.r, to.color.r, p.color.r) > level || off(from.color.g, to.color.g, p.color.g) > level ||
          off(from.color.b, to.color.b, p.color.b) > level || off(from.color.a, to.color.a, p.color.a) > level)
        return false;
    }
    return true;
  };
  std::vector<PolylinePoint> kept{points.front()};
  std::size_t anchor = 0;
  for (std::size_t j = 2; j < points.size(); ++j) {
    if (j - anchor <= kLongestRun && straight(anchor, j)) continue;
    anchor = j - 1;
    kept.push_back(points[anchor]);
  }
  kept.push_back(points.back());
  points = std::move(kept);
}

void ShapeBatch::dashedPolyline(const std::vector<PolylinePoint>& points, float dash, float gap) {
  if (points.empty()) return;
  const float period = dash + gap;
  std::vector<PolylinePoint> piece{points[0]};
  float phase = 0;  // where the pattern is at the current point: in a dash below `dash`, in a gap above
  for (std::size_t i = 1; i < points.size(); ++i) {
    const PolylinePoint &a = points[i - 1], &b = points[i];
    const float len = length(b.at - a.at);
    float done = 0;
    for (;;) {
      const bool on = phase < dash;
      const float toNext = (on ? dash : period) - phase;
      if (done + toNext > len) {
        phase += len - done;
        break;
      }
      done += toNext;
      const float u = len > 0 ? done / len : 1;
      PolylinePoint cut = a;
      cut.at = a.at + u * (b.at - a.at);
      cut.halfWidth = a.halfWidth + u * (b.halfWidth - a.halfWidth);
      piece.push_back(cut);
      if (on) {
        polyline(piece);
        piece.clear();
        phase = dash;
      } else {
        phase = 0;
      }
    }
    if (phase < dash) piece.push_back(b);
  }
  polyline(piece);
}

void ShapeBatch::ring(P2 centre, float radius, float halfWidth, Rgba color) {
  constexpr int kSegments = 40;
  std::vector<PolylinePoint> points;
  for (int k = 0; k <= kSegments; ++k) {
    const float a = 6.2831853f * float(k) / kSegments;
    points.push_back({centre + P2{radius * std::cos(a), radius * std::sin(a)}, halfWidth, color, {}});
  }
  polyline(points);
}

void ShapeBatch::append(const ShapeBatch& other) {
  for (const ShapeSegment& segment : other.segments_) {
    const std::size_t first = vertices_.size();
    vertices_.insert(vertices_.end(), other.vertices_.begin() + std::ptrdiff_t(segment.first),
                     other.vertices_.begin() + std::ptrdiff_t(segment.first + segment.count));
    if (!segments_.empty() && segments_.back().program == segment.program &&
        segments_.back().first + segments_.back().count == first)
      segments_.back().count += segment.count;
    else
      segments_.push_back({segment.program, first, segment.count});
  }
}

void ShapeBatch::rect(float x0, float y0, float x1, float y1, Rgba color) {
  auto make = [&](float x, float y) {
    return vertex({x, y}, {0, 0}, ShapeKind::Rect, 0, 0, color, false, 0, {0, 1}, {});
  };
  const ShapeVertex corners[4] = {make(x0, y0), make(x1, y0), make(x1, y1), make(x0, y1)};
  quad(corners);
}

void ShapeBatch::glyph(float x0, float y0, float x1, float y1, float u0, float v0, float u1, float v1, Rgba color) {
  auto make = [&](float x, float y, float u, float v) {
    return vertex({x, y}, {u, v}, ShapeKind::Glyph, 0, 0, color, false, 0, {0, 1}, {});
  };
  const ShapeVertex corners[4] = {make(x0, y0, u0, v0), make(x1, y0, u1, v0), make(x1, y1, u1, v1),
                                  make(x0, y1, u0, v1)};
  quad(corners);
}

}  // namespace sl

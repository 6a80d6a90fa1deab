// The sphere panel: configuration-space paths of every run on (or, for 5+ rods, inside) the sphere.
// The sphere itself is drawn by shaders/sphere.frag; here the paths become shaded tubes that fade with
// age, lifted just above the surface and hidden per pixel where the sphere is in front of them.

#include <algorithm>
#include <cmath>

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

// A path as a tube of `radius` (world units, at least `minHalfWidth` pixels) in `color`, fading with age. Thin
// paths (a family's members, many at once) are flat lines with points closer than a pixel merged: the same
// picture at a fraction of the fill.
void drawPath(const SharedSpan<Vec3>& path, const SharedSamples& times, Rgba color, double radius,
              float minHalfWidth, const PanelContext& context, const SphereCamera& camera, const Placement& placement,
              bool throughAntipode, ShapeBatch& batch, bool thin = false) {
  std::vector<PolylinePoint> points;
  points.reserve(path.size() + 1);
  for (std::size_t i = 0; i < path.size(); ++i) {
    const double age = i < times.size() ? context.frame.time - times[i] : 0.0;
    const float alpha = pathAlpha(context.settings, age);
    const V3 p = placement.place(path[i]);
    const bool hidden = alpha <= 0.0f || !drawable(path[i]) || !camera.inFront(p);
    const bool jump = throughAntipode && i > 0 && distance(path[i - 1], path[i]) > kMaxPathChord;
    if (hidden || jump) {  // a gap: draw what came before, start afresh (with this point, unless hidden)
      batch.polyline(points, !thin, 0.35f);
      points.clear();
    }
    if (hidden) continue;
    const P2 at = camera.project(p);
    const bool last = i + 1 == path.size();
    if (thin && !points.empty() && !last && std::abs(at.x - points.back().at.x) + std::abs(at.y - points.back().at.y) < 1.5f * context.unit)
      continue;
    const float halfWidth = std::max(minHalfWidth, float(radius * camera.pixelsPerUnitAt(p)));
    points.push_back({at, halfWidth, palette::withAlpha(color, color.a * alpha), placement.world(p)});
  }
  batch.polyline(points, !thin, 0.35f);
}

// A run's family: each member's path as a thin line in the run's colour ramp, then the wavefront, the curve
// through the members' current points in member order, as a dark line over them, and a dot per member (a
// stopped member's dot on a red halo, as a stopped run's ball).
void drawFamily(const RunFrame& run, const PanelContext& context, const SphereCamera& camera,
                const Placement& placement, bool throughAntipode, ShapeBatch& batch) {
  const std::size_t count = run.members.size();
  for (std::size_t m = 0; m < count; ++m) {
    drawPath(run.members[m].path, run.members[m].pathTimes, memberColor(run.color, m, count, 0.85f),
             0.3 * kTubeRadius, 0.6f * context.unit, context, camera, placement, throughAntipode, batch, true);
  }
  std::vector<PolylinePoint> front;
  auto flush = [&] {
    batch.polyline(front, true, 0.2f);
    front.clear();
  };
  for (std::size_t m = 0; m < count; ++m) {
    const Vec3& at = run.members[m].current;
    const V3 p = placement.place(at);
    const bool jump = throughAntipode && m > 0 && distance(run.members[m - 1].current, at) > kMaxPathChord;
    if (!drawable(at) || !camera.inFront(p) || jump) flush();
    if (!drawable(at) || !camera.inFront(p)) continue;
    const float halfWidth = std::max(context.unit, float(0.45 * kTubeRadius * camera.pixelsPerUnitAt(p)));
    front.push_back({camera.project(p), halfWidth, palette::withAlpha(palette::ink, 0.9f), placement.world(p)});
  }
  flush();
  for (std::size_t m = 0; m < count; ++m) {
    const MemberFrame& member = run.members[m];
    const V3 p = placement.place(member.current);
    if (!drawable(member.current) || !camera.inFront(p)) continue;
    const float pixelsPerUnit = float(camera.pixelsPerUnitAt(p));
    const float radius = std::max(1.5f * context.unit, 0.35f * float(kBallRadius) * pixelsPerUnit);
    if (member.stopped) batch.disc(camera.project(p), radius + 1.5f * context.unit, palette::stopRed, false, 0, placement.world(p));
    batch.disc(camera.project(p), radius, memberColor(run.color, m, count), true, 0.3f, placement.world(p),
               radius / pixelsPerUnit);
  }
}

// The current state of a run, `style` its runStyleWidth: a later run's ball is smaller, so a run exactly under
// another still shows as a ring around it, as its path does.
void drawBall(const RunFrame& run, float style, float unit, const SphereCamera& camera, const Placement& placement,
              ShapeBatch& batch) {
  Placement ballPlacement = placement;
  ballPlacement.lift = kBallRadius;
  const V3 centre = ballPlacement.place(run.current);
  if (!drawable(run.current)) return;
  const float pixelsPerUnit = float(camera.pixelsPerUnitAt(centre));
  const float radius = std::max(3.5f * markUnit(unit), float(kBallRadius) * pixelsPerUnit) * (0.45f + 0.55f * style);
  const P2 at = camera.project(centre);
  // First a ghost that nothing hides: where the sphere is in front of the ball (behind it, or past its outline)
  // the state is still seen through it; where the ball shows, the ball covers its ghost.
  batch.disc(at, radius, palette::withAlpha(palette::ink, 0.45f));  // a dark rim: readable over any colour map
  batch.disc(at, std::max(unit, radius - std::max(unit, 0.15f * radius)), toRgba(run.color, 0.6f));
  if (run.stopped) batch.disc(at, 0.45f * radius, palette::withAlpha(palette::stopRed, 0.5f));
  if (!camera.inFront(centre)) return;
  const Occludable world = ballPlacement.world(centre);
  // A stopped run's ball sits on a red halo (a larger ball behind it, hidden with it by the sphere).
  if (run.stopped) batch.disc(at, radius + 2.5f * unit, palette::stopRed, true, 0.2f, world, (radius + 2.5f * unit) / pixelsPerUnit);
  // A thin dark rim sets the ball off from its own path, which has its colour (small frames lost it in the tube).
  else batch.disc(at, radius + unit, palette::withAlpha(palette::ink, 0.75f), false, 0, world, (radius + unit) / pixelsPerUnit);
  batch.disc(at, radius, toRgba(run.color), true, 0.55f, world, radius / pixelsPerUnit);
}

// Conjugate points on the path (runs with Jacobi fields): an ink ring around a dot of the run's colour, where
// the geodesics leaving the start together meet again.
void drawConjugatePoints(const RunFrame& run, float unit, const SphereCamera& camera, const Placement& placement,
                         ShapeBatch& batch) {
  Placement markPlacement = placement;
  markPlacement.lift = 1.5 * kTubeRadius;
  for (const Vec3& point : run.conjugatePoints) {
    const V3 p = markPlacement.place(point);
    if (!drawable(point) || !camera.inFront(p)) continue;
    const float pixelsPerUnit = float(camera.pixelsPerUnitAt(p));
    const float radius = std::max(3.0f * markUnit(unit), 0.7f * float(kBallRadius) * pixelsPerUnit);
    const Occludable world = markPlacement.world(p);
    batch.disc(camera.project(p), radius, palette::ink, false, 0, world, radius / pixelsPerUnit);
    batch.disc(camera.project(p), 0.6f * radius, toRgba(run.color), true, 0.3f, world, 0.6f * radius / pixelsPerUnit);
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

// Stiffness ellipses as light rings riding on the sphere (over the dark end of a colour map as over its light end:
// a white stroke on a dark halo), hidden where the sphere is in front of them.
void drawEllipses(const std::vector<SphereEllipse>& ellipses, const SphereCamera& camera, const Placement& placement,
                  const PixelRect& rect, float unit, ShapeBatch& batch) {
  constexpr int kSegments = 40;
  const float halfWidth = std::max(0.6f * unit, 0.0011f * rect.height);
  const V3 eye = camera.eye();
  const double eyeDistance = std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
  for (const SphereEllipse& e : ellipses) {
    // Seen edge-on near the outline an ellipse is a meaningless dash: fade it out there.
    const double facing = (e.centre.x * eye.x + e.centre.y * eye.y + e.centre.z * eye.z) / eyeDistance;
    const float alpha = float(0.85 * std::clamp((facing - 0.2) / 0.25, 0.0, 1.0));
    if (alpha <= 0) continue;
    const Rgba color{1, 1, 1, alpha};
    const Rgba halo = palette::withAlpha(palette::ink, 0.35f * alpha);
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
      fill.push_back({camera.project(placed), half, Rgba{1, 1, 1, 0.3f * alpha}, placement.world(placed)});
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

// 4 rods: the chart's poles (phi = +-pi/2, where t is undefined and the published single-chart methods fail) are
// marked by the sphere shader; a small label names whichever pole faces the eye.
void labelChartPoles(const PanelContext& context, const SphereCamera& camera, ShapeBatch& batch) {
  const float ascent = context.font.ascent(TextSize::Small);
  for (const double z : {1.0, -1.0}) {
    const V3 pole{0, 0, z};
    const V3 eye = camera.eye();
    if (!(eye.x * pole.x + eye.y * pole.y + eye.z * pole.z > 1.0)) continue;  // behind the sphere
    const P2 at = camera.project(pole);
    const std::string text = "chart pole";
    const float width = context.font.width(text, TextSize::Small);
    if (width > context.rect.width || ascent > context.rect.height) return;  // no room for the label
    const float x = std::clamp(at.x + 0.9f * ascent, context.rect.x, context.rect.x + context.rect.width - width);
    const float y = std::clamp(at.y - 0.6f * ascent, context.rect.y + ascent, context.rect.y + context.rect.height);
    const ColorRGB& b = context.settings.background;
    batch.rect(x - 0.2f * ascent, y - 1.1f * ascent, x + width + 0.2f * ascent, y + 0.35f * ascent,
               {b.r, b.g, b.b, 0.6f});
    context.font.draw(batch, text, TextSize::Small, x, y, palette::softInk);
  }
}

// A family on the sphere explained where no text panel does it: the run, its members and their wavefront, in the
// panel's bottom-left corner (wrapped to at most two lines; the ball view's caption takes that corner there).
void captionFamilies(const PanelContext& context, float width, ShapeBatch& batch) {
  std::size_t members = 0;
  for (const RunFrame& run : context.frame.runs) members = std::max(members, run.members.size());
  if (members == 0) return;
  const std::string text = "large ball: the run; thin paths and small dots: its " + std::to_string(members) +
                           " members; dark curve: their wavefront";
  const float pad = 0.02f * context.rect.height, line = context.font.lineHeight(TextSize::Small);
  const std::vector<std::string> lines = context.font.wrapped(text, TextSize::Small, width - 2 * pad, 2);
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
  SphereCamera camera(context.settings.camera, context.frame.time, sphereRect);
  const Placement placement{space == ViewSpace::Sphere, kTubeRadius};
  if (space == ViewSpace::Circle) drawEquator(camera, context.unit, batch);
  if (space == ViewSpace::Ball) drawBallGuide(context, camera, batch);
  if (decoration) {
    const float pad = 0.02f * context.rect.height;
    const Placement onSurface{true, 0.004};
    drawEllipses(decoration->ellipses, camera, onSurface, context.rect, context.unit, batch);
    if (!decoration->ellipses.empty()) {
      const float width = context.rect.width - 2 * pad - (colored ? colorBarStrip(context.rect) : 0);
      context.font.draw(batch, fittedForm(context.font, ellipseCaptions(), TextSize::Small, width), TextSize::Small,
                        context.rect.x + pad, context.rect.y + context.rect.height - pad, palette::softInk);
    }
    if (colored) {
      const SphereField& field = *decoration->field;
      // A gap of a text line from the panel's right edge: the bar never butts against a neighbouring plot's axis.
      const float gap = context.font.lineHeight(TextSize::Small);
      const PixelRect bar{context.rect.x + context.rect.width - colorBarStrip(context.rect), context.rect.y + pad,
                          colorBarStrip(context.rect) - pad - gap, 0.8f * context.rect.height};
      const std::string caption = fittedForm(context.font, fieldCaptions(field.coloring), TextSize::Small, bar.width);
      drawColorBar(scaleOf(field), caption, field.diverging ? "each sign on its own scale" : "", bar, context.font, batch);
    }
  }
  const bool throughAntipode = space == ViewSpace::Ball;
  const auto& runs = context.frame.runs;
  for (const RunFrame& run : runs) drawFamily(run, context, camera, placement, throughAntipode, batch);
  // Each later run's tube is narrower (runStyleWidth), so a run exactly under another still shows around it.
  for (std::size_t k = 0; k < runs.size(); ++k)
    drawPath(runs[k].path, runs[k].pathTimes, toRgba(runs[k].color), kTubeRadius * runStyleWidth(k, runs.size()),
             1.8f * context.unit * runStyleWidth(k, runs.size()), context, camera, placement, throughAntipode, batch);
  for (const RunFrame& run : context.frame.runs) drawConjugatePoints(run, context.unit, camera, placement, batch);
  if (space == ViewSpace::Ball) drawBallStart(context, camera, batch);
  for (std::size_t k = 0; k < runs.size(); ++k) drawBall(runs[k], runStyleWidth(k, runs.size()), context.unit, camera, placement, batch);
  if (space == ViewSpace::Sphere) labelChartPoles(context, camera, batch);  // over the paths: never struck through
  const bool captioned = space == ViewSpace::Ball || (decoration && !decoration->ellipses.empty());
  const std::vector<PanelSpec> panels = effectivePanels(context.settings);
  const bool textPanel =
      std::any_of(panels.begin(), panels.end(), [](const PanelSpec& p) { return p.kind == PanelKind::Text; });
  if (!captioned && !textPanel) captionFamilies(context, sphereRect.width, batch);
  const SphereLook look = colored ? SphereLook::Colored : space == ViewSpace::Sphere ? SphereLook::Opaque : SphereLook::Glass;
  return {camera, look};
}

}  // namespace sl

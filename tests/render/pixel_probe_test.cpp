// Pixel probes that catch a broken pipeline: background, sphere, pin and path colours where the
// geometry says they must be, and a path on the far side of the sphere hidden by it.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "fixtures/synthetic_frame.hpp"
#include "reference_frames.hpp"
#include "render/color_map.hpp"
#include "render/frame_composer.hpp"
#include "render/panel_layout.hpp"
#include "render/panels.hpp"
#include "render/plane_view.hpp"
#include "render/renderer.hpp"
#include "render/sphere_camera.hpp"
#include "render/sphere_parts.hpp"

namespace sl {
namespace {

using testing::pixel;
using testing::Rgb8;

const double kDeg = std::acos(-1.0) / 180;

Vec3 onSphere(double phi, double t) {
  return {std::cos(phi) * std::cos(t), std::cos(phi) * std::sin(t), std::sin(phi)};
}

// A camera looking at the middle of a grid cell (phi = t = 7.5 deg), so the panel centre shows bare sphere.
ViewSettings probeSettings() {
  ViewSettings s = testing::smallSettings();
  const Vec3 view = onSphere(7.5 * kDeg, 7.5 * kDeg);
  s.camera.viewDirection = view;
  return s;
}

PixelRect panelRect(const ViewSettings& s, PanelKind kind, ImageSize size = {testing::kWidth, testing::kHeight}) {
  const auto rects = layoutPanels(s.panels, size.width, size.height);
  for (std::size_t i = 0; i < s.panels.size(); ++i)
    if (s.panels[i].kind == kind) return rects[i];
  return {};
}

// One run whose path runs from the visible side to the far side of the sphere.
FrameState probeFrame() {
  FrameState frame = syntheticFrame(3.0, 180);
  frame.runs.resize(1);
  RunFrame& run = frame.runs[0];
  run.path.clear();
  run.pathTimes.clear();
  for (int k = 0; k <= 180; ++k) {  // along the equator of the view: t from 7.5 to 187.5 deg at phi = 7.5
    run.path.push_back(onSphere(7.5 * kDeg, (7.5 + k) * kDeg));
    run.pathTimes.push_back(3.0);
  }
  run.current = run.path.back();
  return frame;
}

bool isBackground(Rgb8 c) { return std::abs(c.r - 245) <= 1 && std::abs(c.g - 242) <= 1 && std::abs(c.b - 235) <= 1; }
bool isCream(Rgb8 c) { return c.r > 150 && c.r >= c.g && c.g > c.b && c.r - c.b > 25 && !isBackground(c); }
bool isRunRed(Rgb8 c) { return c.r > c.g + 40 && c.r > c.b + 25; }  // the first run's burgundy, lit

class PixelProbe : public ::testing::Test {
 protected:
  ViewSettings settings = probeSettings();
  Renderer renderer{settings, testing::kSmallSize};
  FrameState frame = probeFrame();
  Image image = renderer.render(frame);
  SphereCamera camera{settings.camera, frame.time, panelRect(settings, PanelKind::Sphere)};
};

TEST_F(PixelProbe, BackgroundInTheCorner) {
  ASSERT_EQ(image.rgb.size(), std::size_t(testing::kWidth * testing::kHeight * 3));
  EXPECT_TRUE(isBackground(pixel(image, testing::kWidth - 1, testing::kHeight - 1)));
  EXPECT_TRUE(isBackground(pixel(image, 0, testing::kHeight / 2)));
}

TEST_F(PixelProbe, SphereColourAtItsCentre) {
  const P2 centre = camera.project({0, 0, 0});
  const Rgb8 c = pixel(image, int(centre.x), int(centre.y) - 6);  // above the path, mid-cell
  EXPECT_TRUE(isCream(c)) << c.r << " " << c.g << " " << c.b;
}

TEST_F(PixelProbe, PathColourAtAProjectedPathPoint) {
  const Vec3 p = onSphere(7.5 * kDeg, 30 * kDeg);  // visible: 22.5 deg from the view direction
  const P2 at = camera.project({p.x * 1.014, p.y * 1.014, p.z * 1.014});
  const Rgb8 c = pixel(image, int(at.x), int(at.y));
  EXPECT_TRUE(isRunRed(c)) << c.r << " " << c.g << " " << c.b;
}

TEST_F(PixelProbe, PathBehindTheSphereIsNotDrawnAsInFront) {
  const Vec3 p = onSphere(7.5 * kDeg, 150 * kDeg);  // 142.5 deg from the view direction: far side
  const P2 at = camera.project({p.x * 1.014, p.y * 1.014, p.z * 1.014});
  const Rgb8 c = pixel(image, int(at.x), int(at.y));
  EXPECT_FALSE(isRunRed(c)) << c.r << " " << c.g << " " << c.b;
}

bool isRunBlue(Rgb8 c) { return c.b > c.r + 40 && c.b > c.g + 10; }

// Two runs on exactly the same path both show, side by side: across the path, a band of each colour of about the
// same width (neither nested inside the other, which would read as a ranking).
TEST_F(PixelProbe, CoincidingRunsLieSideBySide) {
  FrameState two = frame;
  two.runs.push_back(two.runs[0]);
  two.runs[1].name = "same path";
  two.runs[1].color = {0.0f, 0.45f, 0.70f};
  const Image picture = renderer.render(two);
  const Vec3 p = onSphere(7.5 * kDeg, 30 * kDeg);
  const P2 at = camera.project({p.x * 1.014, p.y * 1.014, p.z * 1.014});
  int red = 0, blue = 0;
  for (int dy = -8; dy <= 8; ++dy) {  // the path runs roughly across the panel here: step across it
    const Rgb8 c = pixel(picture, int(at.x), int(at.y) + dy);
    red += isRunRed(c);
    blue += isRunBlue(c);
  }
  EXPECT_GE(red, 1) << "the first run is hidden under the second";
  EXPECT_GE(blue, 1);
  EXPECT_LE(std::abs(red - blue), 1) << red << " red and " << blue << " blue pixels across: nested, not side by side";
}

// The far side's convention: the current state behind the sphere is a hollow ring drawn over the sphere. Its
// centre shows the sphere (no filled disc that would read as a spot on the front); its rim shows the run.
TEST_F(PixelProbe, CurrentStateBehindTheSphereIsAHollowRing) {
  FrameState behind = frame;
  behind.runs[0].path.clear();  // the state alone: no path or heading drawn through it
  behind.runs[0].pathTimes.clear();
  const Vec3 state = behind.runs[0].current;  // on the far side
  const Vec3 centre{state.x * 1.055, state.y * 1.055, state.z * 1.055};
  const P2 at = camera.project(centre);
  const Image picture = renderer.render(behind);
  FrameState without = behind;
  without.runs[0].current = {NAN, NAN, NAN};  // no state drawn at all
  const Image bare = renderer.render(without);
  const Rgb8 middle = pixel(picture, int(std::lround(at.x)), int(std::lround(at.y)));
  const Rgb8 sphere = pixel(bare, int(std::lround(at.x)), int(std::lround(at.y)));
  EXPECT_TRUE(isCream(sphere)) << sphere.r << " " << sphere.g << " " << sphere.b;
  EXPECT_LE(std::abs(middle.r - sphere.r) + std::abs(middle.g - sphere.g) + std::abs(middle.b - sphere.b), 6)
      << "the hidden ball is filled: " << middle.r << " " << middle.g << " " << middle.b;
  // On the rim (0.8 of the ball's radius): the run's colour, faint.
  const float radius = std::max(3.5f, float(0.055 * camera.pixelsPerUnitAt(centre)));
  int tinted = 0;
  for (int k = 0; k < 16; ++k) {
    const double a = 2 * std::acos(-1.0) * k / 16;
    const int x = int(std::lround(at.x + 0.8f * radius * float(std::cos(a))));
    const int y = int(std::lround(at.y + 0.8f * radius * float(std::sin(a))));
    const Rgb8 c = pixel(picture, x, y), b = pixel(bare, x, y);
    tinted += int(b.g) - int(c.g) > 15;  // burgundy over cream: green drops
  }
  EXPECT_GE(tinted, 8) << "no ring around the hidden state";
}

// Over a dark-ended colour map the far side's dashes lie on a light halo. The halo belongs to a line, not a mark: it
// thins with the frame (a mark's floor of one 720p pixel made the dashes at 320x180, halo and all, wider than the
// path in front on a ball four times smaller).
TEST_F(PixelProbe, FarSideHalosThinWithTheFrame) {
  auto decoration = std::make_shared<SphereDecoration>();
  SphereField field{SphereColoring::Bending, false, 32, 64, {}, 0.0, 1.0};
  field.values.assign(std::size_t(field.phiCount * field.tCount), 0.0f);
  decoration->field = field;
  FrameState dark = frame;
  dark.sphereDecoration = decoration;
  dark.runs[0].current = dark.runs[0].path.front();  // the ball in front: no hidden ring on a halo
  // Every faint line's halo is the same white: the dashes' are told from the hidden poles' rings by where they are.
  const Rgba halo = detail::farSideHalo(detail::ghost(toRgba(dark.runs[0].color)));
  auto widestHalo = [&](ImageSize size) {
    PixelRect rect = panelRect(settings, PanelKind::Sphere, size);
    rect.width -= detail::colorBarStrip(rect);  // framed left of the colour bar
    const SphereCamera view(settings.camera, dark.time, rect);
    const float unit = frameUnit(size);
    float widest = 0;
    for (const PanelDrawing& panel : FrameComposer(settings, size).compose(dark).panels)
      for (const ShapeVertex& v : panel.shapes.vertices()) {
        bool byPole = false;
        for (const double z : {-1.0, 1.0}) {
          const P2 pole = view.project({0, 0, z});
          byPole = byPole || std::hypot(v.x - pole.x, v.y - pole.y) < 12 * std::max(unit, 1.0f);
        }
        if (!byPole && v.r == halo.r && v.g == halo.g && v.b == halo.b && v.a == halo.a)
          widest = std::max(widest, v.size);
      }
    return widest;
  };
  const float large = widestHalo({1280, 720}), small = widestHalo({320, 180});
  ASSERT_GT(large, 0) << "no far-side halo at 1280x720";
  ASSERT_GT(small, 0) << "no far-side halo at 320x180";
  EXPECT_LE(small, 0.5f * large);  // 0.82 with a mark's floor
}

// A path's section behind the sphere is drawn faint and dashed over it: along it some pixels are tinted (dashes)
// and some are the bare sphere (gaps), and no pixel is the run's full colour.
TEST_F(PixelProbe, PathBehindTheSphereIsDashedAndFaint) {
  FrameState without = frame;
  without.runs.clear();
  const Image bare = renderer.render(without);
  int dashes = 0, gaps = 0, full = 0;
  for (int k = 0; k <= 40; ++k) {
    const Vec3 p = onSphere(7.5 * kDeg, (130 + 0.5 * k) * kDeg);  // far side, away from the state
    const P2 at = camera.project({p.x * 1.014, p.y * 1.014, p.z * 1.014});
    const Rgb8 c = pixel(image, int(std::lround(at.x)), int(std::lround(at.y)));
    const Rgb8 b = pixel(bare, int(std::lround(at.x)), int(std::lround(at.y)));
    const int drop = int(b.g) - int(c.g);
    dashes += drop > 12;
    gaps += drop <= 3;
    full += drop > 150;  // the run's full colour over cream: green drops by about 200 levels; faint: about 100
  }
  EXPECT_GT(dashes, 0) << "the hidden section is not drawn";
  EXPECT_GT(gaps, 0) << "the hidden section is not dashed";
  EXPECT_EQ(full, 0) << "the hidden section is drawn as if in front";
}

// Nothing drawn on the sphere hangs past its outline: where the probe's path crosses the limb (lifted off the
// surface, a tube, and shifted sideways as one of two coinciding runs), the band just outside the outline is bare
// background. Before, a path just beyond the limb was still in sight past the sphere and drawn as in front. So too
// where a path starts at the limb running along it: its start bar, across the path, points out of the sphere.
TEST_F(PixelProbe, NothingOnTheSphereHangsPastItsOutline) {
  FrameState two = frame;
  two.runs.push_back(two.runs[0]);  // coinciding: drawn side by side, each shifted a half width
  two.runs[1].color = {0.0f, 0.45f, 0.70f};
  const ImageSize size{1280, 720};
  Renderer large(settings, size);
  const PixelRect panel = panelRect(settings, PanelKind::Sphere, size);
  const SphereCamera view(settings.camera, two.time, panel);
  const P2 c = view.centre();
  const double outline = view.outlineRadius();
  ASSERT_GT(outline, 100);
  // Pixels drawn on in the band 2 to 14 px outside the outline, within 0.2 rad of the screen direction of `at`.
  auto drawnOutside = [&](const Image& picture, P2 at, int& probed) {
    const double towards = std::atan2(at.y - c.y, at.x - c.x);
    int drawn = 0;
    for (double a = towards - 0.2; a <= towards + 0.2; a += 0.005)
      for (double r = outline + 2; r <= outline + 14; r += 1) {
        const Rgb8 p = pixel(picture, int(std::lround(c.x + r * std::cos(a))), int(std::lround(c.y + r * std::sin(a))));
        ++probed;
        drawn += !isBackground(p);
      }
    return drawn;
  };
  // The direction on the screen where the path meets the limb (t = 97.5 deg at phi = 7.5 deg is 90 deg from the eye).
  const Vec3 meet = onSphere(7.5 * kDeg, 97.5 * kDeg);
  int probed = 0;
  const int drawn = drawnOutside(large.render(two), view.project({meet.x, meet.y, meet.z}), probed);
  EXPECT_GT(probed, 500);
  EXPECT_EQ(drawn, 0) << drawn << " of " << probed << " pixels just outside the outline are drawn on";

  // A path starting 2 deg in front of the limb (the circle where sight lines graze the sphere) and running along it.
  const Vec3 eye = view.eye();
  const double eyeDistance = std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
  const Vec3 w{eye.x / eyeDistance, eye.y / eyeDistance, eye.z / eyeDistance};
  const double ez = std::sqrt(w.x * w.x + w.y * w.y);  // a unit vector across w, then the third of the frame
  ASSERT_GT(ez, 0.1);
  const Vec3 u{-w.y / ez, w.x / ez, 0}, v{w.y * u.z - w.z * u.y, w.z * u.x - w.x * u.z, w.x * u.y - w.y * u.x};
  const double polar = std::acos(1.0 / eyeDistance) - 2 * kDeg;
  FrameState start = frame;
  RunFrame& run = start.runs[0];
  run.path.clear();
  run.pathTimes.clear();
  for (int k = 0; k <= 40; ++k) {
    const double a = -20 * kDeg + k * kDeg;  // starts 20 deg before the top of the circle, ends past it
    const double s = std::sin(polar), z = std::cos(polar);
    run.path.push_back({z * w.x + s * (std::cos(a) * v.x + std::sin(a) * u.x),
                        z * w.y + s * (std::cos(a) * v.y + std::sin(a) * u.y),
                        z * w.z + s * (std::cos(a) * v.z + std::sin(a) * u.z)});
    run.pathTimes.push_back(3.0);
  }
  run.current = run.path.back();  // 40 deg on: far from the start's direction
  const Vec3 first = run.path.front();
  int probedStart = 0;
  const int drawnStart = drawnOutside(large.render(start), view.project({first.x, first.y, first.z}), probedStart);
  EXPECT_GT(probedStart, 500);
  EXPECT_EQ(drawnStart, 0) << drawnStart << " of " << probedStart
                           << " pixels just outside the outline by the path's start are drawn on";

  // A stiffness ellipse centred 2 deg in front of the limb (half axes 0.08): edge-on there, it is not drawn, so none
  // of it hangs past the outline (faded from facing 0.2, which in perspective is behind the limb, it was).
  // Where the path above starts (its probe found nothing drawn outside), on the same frame.
  FrameState glyph = start;
  auto decoration = std::make_shared<SphereDecoration>();
  const double s = std::sin(polar), z = std::cos(polar), a = -20 * kDeg;
  const Vec3 out{std::cos(a) * v.x + std::sin(a) * u.x, std::cos(a) * v.y + std::sin(a) * u.y,
                 std::cos(a) * v.z + std::sin(a) * u.z};
  const Vec3 side{-std::sin(a) * v.x + std::cos(a) * u.x, -std::sin(a) * v.y + std::cos(a) * u.y,
                  -std::sin(a) * v.z + std::cos(a) * u.z};
  const Vec3 centre{z * w.x + s * out.x, z * w.y + s * out.y, z * w.z + s * out.z};
  const Vec3 along{0.08 * side.x, 0.08 * side.y, 0.08 * side.z};
  const Vec3 across{0.08 * (-s * w.x + z * out.x), 0.08 * (-s * w.y + z * out.y), 0.08 * (-s * w.z + z * out.z)};
  decoration->ellipses.push_back({centre, along, across});
  glyph.sphereDecoration = decoration;
  int probedGlyph = 0;
  const int drawnGlyph = drawnOutside(large.render(glyph), view.project({centre.x, centre.y, centre.z}), probedGlyph);
  EXPECT_GT(probedGlyph, 500);
  EXPECT_EQ(drawnGlyph, 0) << drawnGlyph << " of " << probedGlyph << " pixels just outside the outline by an ellipse";
}

// The opaque sphere's grid tints the lit ball (shaders/sphere_grid.frag, multiplied into it): on the equator the ball
// is darker by the grid colour's share, hue kept (red still above green above blue), and beside the line it is the
// bare ball. A ribbon that lit itself wrongly, or drew white, or missed the ball would fail here.
TEST_F(PixelProbe, TheGridDarkensTheBallAlongItsLines) {
  const ImageSize size{1280, 720};
  Renderer large(settings, size);
  const Image picture = large.render(frame);
  const SphereCamera view(settings.camera, frame.time, panelRect(settings, PanelKind::Sphere, size));
  auto at = [&](double phi, double t) {
    const Vec3 p = onSphere(phi * kDeg, t * kDeg);
    const P2 q = view.project({p.x, p.y, p.z});
    return pixel(picture, int(std::lround(q.x)), int(std::lround(q.y)));
  };
  for (const double t : {5.0, 10.0}) {
    const Rgb8 line = at(0.0, t), bare = at(3.75, t);  // the equator; half way to the next parallel
    ASSERT_TRUE(isCream(bare)) << int(bare.r) << " " << int(bare.g) << " " << int(bare.b);
    const double ratio = double(line.r) / bare.r;
    EXPECT_GT(ratio, 0.55) << "t = " << t;  // not darker than the grid's own colour over the cream
    EXPECT_LT(ratio, 0.85) << "t = " << t;  // but visibly darker: the line is there
    EXPECT_GT(line.r, line.g);
    EXPECT_GT(line.g, line.b);
  }
}

// Time on the sphere: the current state carries a direction mark, an arrowhead in the run's colour just past the ball
// on the side it moves to (not on the side it came from), and at the limb the arrowhead stays within the outline. The
// state here is off the view's centre and moving towards it: the ball, lifted higher than the path, is shifted outwards
// on the screen, and a heading measured from the ball's centre would point outwards instead.
TEST_F(PixelProbe, TheCurrentStateCarriesADirectionMarkWithinTheOutline) {
  const ImageSize size{1280, 720};
  // The mark is in the run's colour, as its path is: the path faded out (drawn 100 s ago, fading over 1 s), so
  // that the run's colour near the ball is the ball's and the mark's alone. The heading still comes from the path.
  ViewSettings faded = settings;
  faded.pathFadeSeconds = 1;
  Renderer large(faded, size);
  const PixelRect panel = panelRect(settings, PanelKind::Sphere, size);
  const SphereCamera view(settings.camera, frame.time, panel);
  auto lifted = [](const Vec3& p, double r) { return Vec3{p.x * r, p.y * r, p.z * r}; };
  // A run along phi = 7.5 deg from t = 70 deg to t = 40 deg (the view's centre is at t = 7.5 deg).
  auto runFrom = [&](double t0, double t1) {
    FrameState moving = frame;
    RunFrame& run = moving.runs[0];
    run.path.clear();
    run.pathTimes.clear();
    for (int k = 0; k <= 60; ++k) {
      run.path.push_back(onSphere(7.5 * kDeg, (t0 + (t1 - t0) * k / 60.0) * kDeg));
      run.pathTimes.push_back(moving.time - 100);
    }
    run.current = run.path.back();
    return moving;
  };
  // Pixels of the run's colour within 3 px of `at`.
  auto inkNear = [&](const Image& picture, P2 at) {
    int ink = 0;
    for (int dy = -3; dy <= 3; ++dy)
      for (int dx = -3; dx <= 3; ++dx)
        ink += isRunRed(pixel(picture, int(std::lround(at.x)) + dx, int(std::lround(at.y)) + dy));
    return ink;
  };
  const FrameState inwards = runFrom(70, 40);
  const Image picture = large.render(inwards);
  const Vec3 state = inwards.runs[0].current, before = inwards.runs[0].path[55];
  const P2 on = view.project(lifted(state, 1.014)), back = view.project(lifted(before, 1.014));
  const P2 ball = view.project(lifted(state, 1.055));
  const double length = std::hypot(on.x - back.x, on.y - back.y);
  ASSERT_GT(length, 3);
  const P2 heading{float((on.x - back.x) / length), float((on.y - back.y) / length)};
  const float radius = std::max(3.5f, float(0.055 * view.pixelsPerUnitAt(lifted(state, 1.055))));
  const float reach = radius + 6.0f;  // the arrowhead runs from 1 to 11 frame units past the ball's edge
  const P2 ahead{ball.x + reach * heading.x, ball.y + reach * heading.y};
  const P2 behind{ball.x - reach * heading.x, ball.y - reach * heading.y};
  EXPECT_GE(inkNear(picture, ahead), 3) << "no direction mark ahead of the state";
  EXPECT_EQ(inkNear(picture, behind), 0) << "a direction mark on the side the state came from";

  // Out through the limb: a path along phi = 7.5 deg ending just in front of the limb (t = 97.5 deg is 90 deg from
  // the view's centre; the limb, where sight lines graze the sphere, is nearer). Just outside the outline nothing is
  // drawn but the ball, which stands on the surface at the outline: the chevron keeps within it.
  const Vec3 eye = view.eye();
  const double limb = std::acos(1.0 / std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z)) / kDeg;
  const FrameState outwards = runFrom(40, 7.5 + limb - 1.5);
  const Image atLimb = large.render(outwards);
  const P2 c = view.centre();
  const double outline = view.outlineRadius();
  P2 standing = view.project(lifted(outwards.runs[0].current, 1.055));  // the ball's centre, on or inside the outline
  const double out = std::hypot(standing.x - c.x, standing.y - c.y);
  if (out > outline)
    standing = {float(c.x + (standing.x - c.x) * outline / out), float(c.y + (standing.y - c.y) * outline / out)};
  const double towards = std::atan2(standing.y - c.y, standing.x - c.x);
  int probed = 0, drawn = 0;
  for (double a = towards - 0.25; a <= towards + 0.25; a += 0.004)
    for (double r = outline + 2; r <= outline + 20; r += 1) {
      const P2 p{float(c.x + r * std::cos(a)), float(c.y + r * std::sin(a))};
      if (std::hypot(p.x - standing.x, p.y - standing.y) < radius + 3) continue;  // the ball, its rim and a pixel
      ++probed;
      drawn += !isBackground(pixel(atLimb, int(std::lround(p.x)), int(std::lround(p.y))));
    }
  EXPECT_GT(probed, 500);
  EXPECT_EQ(drawn, 0) << drawn << " of " << probed
                      << " pixels just outside the outline by the state at the limb are drawn on";
}

// Runs in the same state (their balls spread side by side) move one way: one direction mark for the group, past its
// centre, not a chevron per ball (two read as a double one, "»"). Dark pixels just past the balls: as many for two
// coinciding runs as for one run alone.
TEST_F(PixelProbe, CoincidingStatesShareOneDirectionMark) {
  const ImageSize size{1280, 720};
  Renderer large(settings, size);
  const SphereCamera view(settings.camera, frame.time, panelRect(settings, PanelKind::Sphere, size));
  auto lifted = [](const Vec3& p, double r) { return Vec3{p.x * r, p.y * r, p.z * r}; };
  FrameState one = frame;  // along phi = 7.5 deg from t = 70 deg to t = 40 deg, towards the view's centre
  RunFrame& run = one.runs[0];
  run.path.clear();
  run.pathTimes.clear();
  for (int k = 0; k <= 60; ++k) {
    run.path.push_back(onSphere(7.5 * kDeg, (70 - 30 * k / 60.0) * kDeg));
    run.pathTimes.push_back(3.0);
  }
  run.current = run.path.back();
  FrameState two = one;
  two.runs.push_back(two.runs[0]);
  two.runs[1].name = "same state";
  two.runs[1].color = {0.0f, 0.45f, 0.70f};
  const P2 on = view.project(lifted(run.current, 1.014)), back = view.project(lifted(run.path[55], 1.014));
  const P2 ball = view.project(lifted(run.current, 1.055));
  const double length = std::hypot(on.x - back.x, on.y - back.y);
  ASSERT_GT(length, 3);
  const P2 heading{float((on.x - back.x) / length), float((on.y - back.y) / length)}, across{-heading.y, heading.x};
  const float radius = std::max(3.5f, float(0.055 * view.pixelsPerUnitAt(lifted(run.current, 1.055))));
  // Pixels of the first run's colour (the group's mark is in the colour of the run that draws it) past the balls'
  // edge (the arrowhead runs from 1 to 11 frame units past it), across the whole group.
  auto inkAhead = [&](const Image& picture) {
    int ink = 0;
    for (float along = radius + 1.5f; along <= radius + 14; along += 1)
      for (float side = -2.5f * radius; side <= 2.5f * radius; side += 1)
        ink += isRunRed(pixel(picture, int(std::lround(ball.x + along * heading.x + side * across.x)),
                              int(std::lround(ball.y + along * heading.y + side * across.y))));
    return ink;
  };
  const int alone = inkAhead(large.render(one)), together = inkAhead(large.render(two));
  EXPECT_GE(alone, 10) << "no direction mark ahead of the state";
  EXPECT_GE(together, alone * 3 / 4) << "the group's direction mark is missing";
  EXPECT_LE(together, alone * 5 / 4) << together << " dark pixels ahead of two coinciding states, " << alone
                                     << " ahead of one: a chevron per ball";
}

// The seam (view.sphere.seam) rides on the sphere under the paths and balls: a state on the seam shows its ball
// whole, not struck through by the seam's red dashes (scenes/seam.json starts there).
TEST_F(PixelProbe, TheSeamRunsUnderAStateOnIt) {
  auto decoration = std::make_shared<SphereDecoration>();
  decoration->seam = true;
  ViewSettings facing = settings;
  // The seam t = 90 deg runs down the front, facing the eye most at the state (phi = 0), where it would be named.
  facing.camera.viewDirection = onSphere(0, 80 * kDeg);
  const ImageSize size{1280, 720};
  Renderer large(facing, size);
  FrameState onSeam = frame;
  onSeam.sphereDecoration = decoration;
  RunFrame& run = onSeam.runs[0];
  run.path.clear();
  run.pathTimes.clear();
  for (int k = 0; k <= 30; ++k) {  // along the equator, ending on the seam
    run.path.push_back(onSphere(0, (60 + k) * kDeg));
    run.pathTimes.push_back(3.0);
  }
  run.current = run.path.back();
  const Image picture = large.render(onSeam);
  const auto rects = layoutPanels(facing.panels, size.width, size.height);
  PixelRect panel;
  for (std::size_t i = 0; i < facing.panels.size(); ++i)
    if (facing.panels[i].kind == PanelKind::Sphere) panel = rects[i];
  const SphereCamera view(facing.camera, onSeam.time, panel);
  const Vec3 state = run.current;
  const P2 ball = view.project({state.x * 1.055, state.y * 1.055, state.z * 1.055});
  const P2 seam = view.project({state.x * 1.003, state.y * 1.003, state.z * 1.003});  // the seam under the ball
  const float radius = float(0.055 * view.pixelsPerUnitAt({state.x * 1.055, state.y * 1.055, state.z * 1.055}));
  auto plain = std::make_shared<SphereDecoration>();
  FrameState noSeam = onSeam;
  noSeam.sphereDecoration = plain;
  const Image without = large.render(noSeam);
  // Along the seam within the ball (a few pixels inside its outline): the ball as it is without the seam.
  int struck = 0, probed = 0;
  for (int dy = -12; dy <= 12; ++dy) {
    const P2 at{seam.x, seam.y + float(dy)};
    if (std::hypot(at.x - ball.x, at.y - ball.y) > radius - 3) continue;
    const int x = int(std::lround(at.x)), y = int(std::lround(at.y));
    const Rgb8 c = pixel(picture, x, y), b = pixel(without, x, y);
    ++probed;
    struck += std::abs(c.r - b.r) + std::abs(c.g - b.g) + std::abs(c.b - b.b) > 6;
  }
  EXPECT_GT(probed, 10);
  EXPECT_EQ(struck, 0) << struck << " of " << probed << " pixels along the seam within the ball show the seam";
  // Nor is the seam's name tied to the ball: no leader line runs over it (the whole ball as it is without the seam).
  int crossed = 0, inBall = 0;
  for (int dy = -int(radius); dy <= int(radius); ++dy)
    for (int dx = -int(radius); dx <= int(radius); ++dx) {
      if (std::hypot(float(dx), float(dy)) > radius - 3) continue;
      const int x = int(std::lround(ball.x)) + dx, y = int(std::lround(ball.y)) + dy;
      const Rgb8 c = pixel(picture, x, y), b = pixel(without, x, y);
      ++inBall;
      crossed += std::abs(c.r - b.r) + std::abs(c.g - b.g) + std::abs(c.b - b.b) > 6;
    }
  EXPECT_GT(inBall, 100);
  EXPECT_EQ(crossed, 0) << crossed << " of " << inBall << " pixels within the ball differ from the ball without the seam";
}

TEST_F(PixelProbe, PinsAreCharcoal) {
  // Side by side (one run): the run's name has its line at the foot of the panel.
  const FrameComposer composer(settings, testing::kSmallSize);
  const auto view = fitFrameView(frame, panelRect(settings, PanelKind::Linkage),
                                         captionHeight(composer.font()));
  for (double x : {0.0, frame.runs[0].baseLength}) {
    const P2 pin = view(x, 0);
    const float rod = std::max(1.5f, float(0.045 * view.scale));
    const Rgb8 c = pixel(image, int(pin.x), int(pin.y - 1.4f * rod));  // on the bolt, off its silver centre
    EXPECT_LT(std::max({c.r, c.g, c.b}), 110) << "pin at x = " << x << ": " << c.r << " " << c.g << " " << c.b;
  }
}

// view.theme dark: a dark page, and what stands on it (the text panel's title and time, the plot's axes and tick
// labels, the pins) in light ink; the sphere and its paths are the same object on either page.
TEST_F(PixelProbe, TheDarkThemeLightensTheInkNotTheSphere) {
  ViewSettings dark = settings;
  dark.theme = Theme::Dark;
  dark.background = themeBackground(Theme::Dark);
  const Image night = Renderer(dark, testing::kSmallSize).render(frame);
  const Rgb8 corner = pixel(night, testing::kWidth - 1, testing::kHeight - 1);
  EXPECT_LT(std::max({corner.r, corner.g, corner.b}), 45);
  // Grey pixels (no run's colour) in a panel: dark ink on the light page, light ink on the dark one. Ink left dark
  // on the dark page would leave no light grey pixel at all.
  const auto greyInk = [](const Image& picture, const PixelRect& r, bool light) {
    int count = 0;
    for (int y = int(r.y); y < int(r.y + r.height); ++y)
      for (int x = int(r.x); x < int(r.x + r.width); ++x) {
        const Rgb8 c = pixel(picture, x, y);
        const bool grey = std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}) < 16;
        count += grey && (light ? c.g > 120 : c.g < 100);
      }
    return count;
  };
  for (const PanelKind kind : {PanelKind::Text, PanelKind::Plot}) {
    const PixelRect r = panelRect(settings, kind);
    EXPECT_GT(greyInk(image, r, false), 40) << int(kind);
    EXPECT_GT(greyInk(night, r, true), 40) << int(kind);
  }
  const FrameComposer composer(settings, testing::kSmallSize);
  const auto view = fitFrameView(frame, panelRect(settings, PanelKind::Linkage), captionHeight(composer.font()));
  const P2 pin = view(0.0, 0);
  const float rod = std::max(1.5f, float(0.045 * view.scale));
  const Rgb8 bolt = pixel(night, int(pin.x), int(pin.y - 1.4f * rod));
  EXPECT_GT(int(bolt.g) - int(corner.g), 60) << "a charcoal pin vanishes on the dark page";
  const P2 centre = camera.project({0, 0, 0});
  for (const int dy : {-6, 0, 6}) {  // bare sphere, the path, bare sphere
    const Rgb8 a = pixel(image, int(centre.x), int(centre.y) + dy), b = pixel(night, int(centre.x), int(centre.y) + dy);
    EXPECT_TRUE(a.r == b.r && a.g == b.g && a.b == b.b) << dy;
  }
}

// A massless hinge between thick (massive) rods is a dark rivet where the rods meet: without it the chain read as
// one bent pipe of silver (masses-curvature.json).
TEST_F(PixelProbe, AMasslessHingeIsARivetBetweenThickRods) {
  FrameState massive = frame;
  RunFrame& run = massive.runs[0];
  run.hingeMasses.assign(run.hinges.size(), 0.0);
  run.rodMasses.assign(run.hinges.size() + 1, 3.0);
  const ImageSize size{1280, 720};  // rods wide enough that a hinge's centre pixel is all rivet (or all rod)
  const Image picture = Renderer(settings, size).render(massive);
  const FrameComposer composer(settings, size);
  const auto view =
      fitFrameView(massive, panelRect(settings, PanelKind::Linkage, size), captionHeight(composer.font()));
  for (std::size_t h = 0; h < run.hinges.size(); ++h) {
    const P2 at = view(run.hinges[h]);
    const Rgb8 c = pixel(picture, int(std::lround(at.x)), int(std::lround(at.y)));
    EXPECT_LT(std::max({c.r, c.g, c.b}), 90) << "hinge " << h + 1 << ": " << c.r << " " << c.g << " " << c.b;
  }
}

TEST_F(PixelProbe, NoAntialiasingStillDrawsTheSameScene) {
  ViewSettings aliased = settings;
  aliased.antialias = false;
  Renderer plain(aliased, testing::kSmallSize);
  const Image hard = plain.render(frame);
  const P2 centre = camera.project({0, 0, 0});
  EXPECT_TRUE(isCream(pixel(hard, int(centre.x), int(centre.y) - 6)));
  EXPECT_NE(hard.rgb, image.rgb);  // edges differ
}

// The ball view (5+ rods): a path through the antipode jumps from one side of the boundary to the other; the
// jump is a gap, not a line across the ball. The same line sampled densely is drawn (so the probe can see it).
// The start of a 5+ rod path (the ball's centre) is marked over the path, not hidden under it.
TEST_F(PixelProbe, BallViewMarksTheStartOverThePath) {
  FrameState ball = probeFrame();
  ball.viewSpace = ViewSpace::Ball;
  RunFrame& run = ball.runs[0];
  run.path.clear();
  run.pathTimes.clear();
  for (int k = 0; k <= 200; ++k) {  // straight through the centre
    run.path.push_back({-0.9 + 0.009 * k, 0.0, 0.0});
    run.pathTimes.push_back(ball.time);
  }
  run.current = run.path.back();
  const P2 centre = camera.project({0, 0, 0});
  const Rgb8 mark = pixel(renderer.render(ball), int(centre.x), int(centre.y));
  EXPECT_FALSE(isRunRed(mark)) << "the path hides the start: " << mark.r << " " << mark.g << " " << mark.b;
  EXPECT_LT(mark.r + mark.g + mark.b, 3 * 90) << "expected the dark start mark";
}

TEST_F(PixelProbe, BallViewLeavesAGapWhereThePathJumpsThroughTheAntipode) {
  auto ballFrame = [&](bool jump) {
    FrameState ball = probeFrame();
    ball.viewSpace = ViewSpace::Ball;
    RunFrame& run = ball.runs[0];
    run.path.clear();
    run.pathTimes.clear();
    for (int k = 0; k <= 200; ++k) {
      const double x = jump ? (k <= 100 ? 0.8 + 0.0019 * k : -0.99 + 0.0019 * (k - 101)) : -0.9 + 0.009 * k;
      run.path.push_back({x, 0.0, 0.0});
      run.pathTimes.push_back(ball.time);
    }
    run.current = run.path.back();
    return ball;
  };
  // Probed beside the centre, where the start's cross is drawn over the path.
  const P2 probe = camera.project({0.4, 0, 0});
  const Rgb8 drawn = pixel(renderer.render(ballFrame(false)), int(probe.x), int(probe.y));
  EXPECT_TRUE(isRunRed(drawn)) << drawn.r << " " << drawn.g << " " << drawn.b;
  const Rgb8 gap = pixel(renderer.render(ballFrame(true)), int(probe.x), int(probe.y));
  EXPECT_FALSE(isRunRed(gap)) << "a line crosses the ball: " << gap.r << " " << gap.g << " " << gap.b;
}

// view.sphere.color_by: the sphere carries the field's colours where the field says. A field that is positive on
// the northern hemisphere and negative on the southern one, seen from the equator: red above, blue below.
TEST_F(PixelProbe, ColouredSphereShowsTheFieldWhereItIs) {
  auto decoration = std::make_shared<SphereDecoration>();
  SphereField field{SphereColoring::Curvature, true, 32, 64, {}, -1.0, 2.0};
  for (int i = 0; i < field.phiCount; ++i)
    for (int j = 0; j < field.tCount; ++j) field.values.push_back(i < field.phiCount / 2 ? -1.0f : 2.0f);
  decoration->field = field;
  FrameState colored = probeFrame();
  colored.runs.clear();
  colored.sphereDecoration = decoration;
  ViewSettings side = settings;
  side.camera.viewDirection = {1, 0, 0};
  Renderer sideRenderer(side, testing::kSmallSize);
  const Image picture = sideRenderer.render(colored);
  PixelRect rect = panelRect(side, PanelKind::Sphere);
  // The sphere is framed left of the colour bar: find its centre through the same camera the panel uses.
  rect.width -= detail::colorBarStrip(rect);
  const SphereCamera sideCamera(side.camera, colored.time, rect);
  // At 25 degrees from the equator: clear of the poles' labels (both poles lie on the outline here).
  const P2 north = sideCamera.project({std::cos(25 * kDeg), 0, std::sin(25 * kDeg)});
  const P2 south = sideCamera.project({std::cos(25 * kDeg), 0, -std::sin(25 * kDeg)});
  const Rgb8 up = pixel(picture, int(north.x) + 2, int(north.y) + 2);
  const Rgb8 down = pixel(picture, int(south.x) + 2, int(south.y) - 2);
  EXPECT_GT(up.r, up.b + 60) << up.r << " " << up.g << " " << up.b;
  EXPECT_GT(down.b, down.r + 40) << down.r << " " << down.g << " " << down.b;
  // The same frame without the decoration is the cream sphere.
  colored.sphereDecoration = nullptr;
  const Rgb8 plain = pixel(sideRenderer.render(colored), int(north.x) + 2, int(north.y) + 2);
  EXPECT_TRUE(isCream(plain)) << plain.r << " " << plain.g << " " << plain.b;
}

// The camera of a 640 x 360 frame's sphere panel when the sphere is coloured (framed left of the colour bar).
SphereCamera colouredSphereCamera(const ViewSettings& side, double time) {
  const auto rects = layoutPanels(side.panels, 640, 360);
  PixelRect rect{};
  for (std::size_t i = 0; i < side.panels.size(); ++i)
    if (side.panels[i].kind == PanelKind::Sphere) rect = rects[i];
  rect.width -= detail::colorBarStrip(rect);
  return SphereCamera(side.camera, time, rect);
}

// Faithful colour: the coloured sphere's pixels carry colours of its colour bar (the light darkens them only a
// little and adds no highlight). A field rising smoothly from south to north over the whole map; of the sphere's
// pixels well inside its outline and off the grid lines, at least 95% lie within 24 levels (RGB distance) of some colour of the bar.
// The distance colouring (a sequential map) likewise.
class FaithfulColour : public PixelProbe, public ::testing::WithParamInterface<SphereColoring> {};

TEST_P(FaithfulColour, ColouredSphereKeepsTheColoursOfItsBar) {
  auto decoration = std::make_shared<SphereDecoration>();
  const bool diverging = GetParam() == SphereColoring::Curvature;
  SphereField field{GetParam(), diverging, 32, 64, {}, diverging ? -1.0 : 0.0, 2.0};
  for (int i = 0; i < field.phiCount; ++i)
    for (int j = 0; j < field.tCount; ++j)
      field.values.push_back(float(field.min + (field.max - field.min) * (i + 0.5) / field.phiCount));
  decoration->field = field;
  if (!diverging) decoration->distance = SphereDistance{{0, 0, 1}, true, 1.5};
  FrameState colored = probeFrame();
  colored.runs.clear();
  colored.sphereDecoration = decoration;
  ViewSettings side = settings;
  // Both poles on the outline: their labels (on pads of the background, over the colours on purpose) stay there.
  side.camera.viewDirection = {1.0, 0.3, 0.0};
  Renderer sideRenderer(side, {640, 360});
  const Image picture = sideRenderer.render(colored);
  const SphereCamera sideCamera = colouredSphereCamera(side, colored.time);
  const ColorScale scale{field.min, field.max, diverging};
  std::vector<Rgba> bar;
  for (int k = 0; k <= 512; ++k) bar.push_back(scale.colorAt(k / 512.0));
  int probed = 0, faithful = 0;
  const Vec3 eye = sideCamera.eye();
  for (int k = 0; k < 1600; ++k) {  // points spread over the sphere; those facing the eye well inside the outline
    const double z = 1 - (k + 0.5) * 2 / 1600, r = std::sqrt(1 - z * z), a = k * 2.399963;
    const Vec3 p{r * std::cos(a), r * std::sin(a), z};
    const double facing = (p.x * eye.x + p.y * eye.y + p.z * eye.z) / std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
    if (facing < 0.5 || std::abs(z) > 0.95) continue;
    // Off the chart grid's lines (every 15 degrees in phi and t), which are drawn over the colours on purpose.
    const auto offGrid = [](double angle) {
      const double step = 15 * kDeg;
      return std::abs(angle / step - std::round(angle / step)) * 15 > 2;
    };
    if (!offGrid(std::asin(z)) || !offGrid(std::atan2(p.y, p.x))) continue;
    const P2 at = sideCamera.project(p);
    const Rgb8 c = pixel(picture, int(at.x), int(at.y));
    double nearest = 1e9;
    for (const Rgba& b : bar)
      nearest = std::min(nearest, std::hypot(c.r - 255.0 * b.r, c.g - 255.0 * b.g, c.b - 255.0 * b.b));
    ++probed;
    faithful += nearest <= 24;
  }
  ASSERT_GT(probed, 100);
  EXPECT_GE(faithful, 0.95 * probed) << faithful << " of " << probed << " pixels on the bar's colours";
}

// Colour bars as matplotlib draws them. At 3840x2160 the bar is a smooth ramp in 8-bit output: adjacent rows of its
// inside differ by at most one level in each channel (a bar of 96 bands stepped by 3 to 6 levels every 15 rows), but
// for the mark across it at zero, and a row is one colour across the bar. Beside the bar a gap of at least a text
// line, where nothing is drawn, keeps it off the neighbouring plot's axis.
TEST(ColorBarPixels, SmoothAt4KWithAGapFromTheNeighbouringPanel) {
  auto decoration = std::make_shared<SphereDecoration>();
  SphereField field{SphereColoring::Curvature, true, 32, 64, {}, -0.27, 4.15};
  for (int i = 0; i < field.phiCount; ++i)
    for (int j = 0; j < field.tCount; ++j) field.values.push_back(float(-0.27 + 4.42 * (i + 0.5) / field.phiCount));
  decoration->field = field;
  FrameState frame = syntheticFrame(2.0, 120);
  frame.sphereDecoration = decoration;
  ViewSettings view;
  view.panels = {{PanelKind::Sphere, std::array<double, 4>{0, 0, 0.5, 1}, 0},
                 {PanelKind::Plot, std::array<double, 4>{0.5, 0, 0.5, 1}, 1}};
  const ImageSize size{3840, 2160};
  const FrameComposer composer(view, size);
  const DrawList list = composer.compose(frame);
  ASSERT_TRUE(list.panels[0].sphere);
  const PixelRect area = list.panels[0].sphere->colorBar;
  ASSERT_GT(area.height, 1000);
  Renderer renderer(view, size);
  const Image picture = renderer.render(frame);
  const float barWidth = std::max(6.0f, 0.018f * area.height), right = area.x + area.width;
  const int inner = int(right - 0.5f * barWidth), innerLeft = int(right - 0.8f * barWidth), innerRight = int(right - 0.2f * barWidth);
  const auto dark = [](const Rgb8& c) { return c.r + c.g + c.b < 300; };  // the zero mark's ink
  int rows = 0, worst = 0, distinct = 0;
  for (int y = int(area.y + 0.2f * area.height); y < int(area.y + 0.75f * area.height); ++y) {
    const Rgb8 a = pixel(picture, inner, y), b = pixel(picture, inner, y + 1);
    bool nearMark = false;
    for (int d = -4; d <= 5; ++d) nearMark = nearMark || dark(pixel(picture, inner, y + d));
    if (nearMark) continue;
    ++rows;
    const int step = std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
    worst = std::max(worst, step);
    distinct += step > 0;
    for (const int x : {innerLeft, innerRight}) {
      const Rgb8 c = pixel(picture, x, y);
      EXPECT_LE(std::max({std::abs(a.r - c.r), std::abs(a.g - c.g), std::abs(a.b - c.b)}), 1) << "row " << y;
    }
  }
  ASSERT_GT(rows, 800);
  EXPECT_LE(worst, 1) << "a step of " << worst << " levels between adjacent rows of the bar";
  EXPECT_GT(distinct, 100) << "the bar is not a ramp";
  // The gap: from just right of the bar's frame to the panel's edge, nothing but the background.
  const PixelRect panel = list.panels[0].rect;
  const float line = composer.font().lineHeight(TextSize::Small);
  EXPECT_GE(panel.x + panel.width - right, line);
  const ColorRGB& bg = view.background;
  for (int y = int(area.y); y < int(area.y + area.height); y += 7)
    for (int x = int(right + 0.01f * area.height); x < int(panel.x + panel.width); ++x) {
      const Rgb8 c = pixel(picture, x, y);
      ASSERT_LE(std::abs(c.r - std::lround(255 * bg.r)) + std::abs(c.g - std::lround(255 * bg.g)) +
                    std::abs(c.b - std::lround(255 * bg.b)),
                6)
          << "something drawn in the bar's gap at " << x << ", " << y;
    }
}

INSTANTIATE_TEST_SUITE_P(Colourings, FaithfulColour,
                         ::testing::Values(SphereColoring::Curvature, SphereColoring::Distance));

// The distance colouring's loci are drawn where the decoration puts them: a cut-locus point facing the eye is
// covered by the cut locus's white (no colour of viridis is light in all three channels), a conjugate-locus point by its magenta; a locus point behind the sphere is not
// drawn as in front (at most the far side's faint dashes).
// The far side over a dark colour map (view.sphere.color_by: bending, viridis' purple end, as in
// scenes/stiffness.json): the hidden section's dashes stand out from the sphere under them (a luminance change of at
// least 50 levels somewhere along it: the light halo; faint dark red alone on purple changed it by about 20), and it
// stays dashed (some of it the bare sphere).
TEST_F(PixelProbe, HiddenDashesReadOnADarkColourMap) {
  auto decoration = std::make_shared<SphereDecoration>();
  SphereField field{SphereColoring::Bending, false, 32, 64, {}, 0.0, 1.0};
  field.values.assign(std::size_t(field.phiCount * field.tCount), 0.0f);  // the map's dark end everywhere
  decoration->field = field;
  FrameState dark = frame;
  dark.sphereDecoration = decoration;
  FrameState bare = dark;
  bare.runs.clear();
  const ImageSize size{1280, 720};
  Renderer large(settings, size);
  const Image picture = large.render(dark), sphere = large.render(bare);
  PixelRect rect = panelRect(settings, PanelKind::Sphere, size);
  rect.width -= detail::colorBarStrip(rect);  // framed left of the colour bar
  const SphereCamera view(settings.camera, dark.time, rect);
  auto luminance = [](Rgb8 c) { return 0.30 * c.r + 0.59 * c.g + 0.11 * c.b; };
  int readable = 0, gaps = 0, probed = 0;
  for (int k = 0; k <= 80; ++k) {
    const Vec3 p = onSphere(7.5 * kDeg, (120 + 0.5 * k) * kDeg);  // far side, away from the state
    const P2 at = view.project({p.x * 1.014, p.y * 1.014, p.z * 1.014});
    double change = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = int(std::lround(at.x)) + dx, y = int(std::lround(at.y)) + dy;
        change = std::max(change, std::abs(luminance(pixel(picture, x, y)) - luminance(pixel(sphere, x, y))));
      }
    ++probed;
    readable += change >= 50;
    gaps += change <= 4;
  }
  EXPECT_GE(readable, probed / 4) << "the hidden dashes barely show on the dark map";
  EXPECT_GT(gaps, 0) << "the hidden section is not dashed";
}

TEST_F(PixelProbe, LociAreDrawnWhereTheDistanceMapPutsThem) {
  auto decoration = std::make_shared<SphereDecoration>();
  SphereField field{SphereColoring::Distance, false, 32, 64, {}, 0.0, 3.0};
  for (int i = 0; i < field.phiCount; ++i)
    for (int j = 0; j < field.tCount; ++j) field.values.push_back(float(3.0 * (i + 0.5) / field.phiCount));
  decoration->field = field;
  decoration->distance = SphereDistance{{0, 0, -1}, true, 1.2};
  SphereCurve cut{SphereCurveKind::CutLocus, {}}, conjugate{SphereCurveKind::ConjugateLocus, {}};
  for (int k = -60; k <= 60; ++k) {
    cut.points.push_back(onSphere(k * kDeg, 0));                 // the meridian facing the eye, and on behind
    conjugate.points.push_back(onSphere(20 * kDeg, k * kDeg));  // a parallel above the equator
  }
  for (int k = 0; k <= 60; ++k) cut.points.push_back(onSphere(0, (120 + k) * kDeg));  // the far side
  decoration->curves = {cut, conjugate};
  FrameState colored = probeFrame();
  colored.runs.clear();
  colored.sphereDecoration = decoration;
  ViewSettings side = settings;
  side.camera.viewDirection = {1, 0, 0};
  Renderer sideRenderer(side, {640, 360});
  const Image picture = sideRenderer.render(colored);
  const SphereCamera sideCamera = colouredSphereCamera(side, colored.time);
  auto at = [&](const Vec3& p) {  // the pixel holding the point (the loci ride just above the surface)
    const P2 q = sideCamera.project({1.006 * p.x, 1.006 * p.y, 1.006 * p.z});
    return pixel(picture, int(q.x), int(q.y));
  };
  for (const double phi : {-40.0, -10.0, 35.0}) {
    const Rgb8 c = at(onSphere(phi * kDeg, 0));
    EXPECT_TRUE(c.r > 200 && c.g > 200 && c.b > 200) << "cut locus at phi " << phi << ": " << c.r << " " << c.g << " " << c.b;
  }
  for (const double t : {-40.0, 30.0}) {
    const Rgb8 c = at(onSphere(20 * kDeg, t * kDeg));
    EXPECT_TRUE(c.r > c.g + 80 && c.b > c.g + 40) << "conjugate locus at t " << t << ": " << c.r << " " << c.g << " " << c.b;
  }
  const Rgb8 hidden = at(onSphere(0, 150 * kDeg));
  EXPECT_FALSE(hidden.r > 200 && hidden.g > 200 && hidden.b > 200) << hidden.r << " " << hidden.g << " " << hidden.b;
  // Without the curves, the same pixels are the map's colours.
  decoration->curves.clear();
  const Image bare = sideRenderer.render(colored);
  const P2 q = sideCamera.project({1.006 * std::cos(10 * kDeg), 0, -1.006 * std::sin(10 * kDeg)});
  const Rgb8 c = pixel(bare, int(q.x), int(q.y));
  EXPECT_FALSE(c.r > 200 && c.g > 200 && c.b > 200) << c.r << " " << c.g << " " << c.b;
}

}  // namespace
}  // namespace sl

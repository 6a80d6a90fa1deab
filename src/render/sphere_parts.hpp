#pragma once
// The sphere panel's pieces, shared by the files that draw it (render/sphere_panel.cpp puts them together):
// render/sphere_parts.cpp the far-side conventions and small helpers, render/sphere_paths.cpp the runs (paths,
// families, balls, starts, conjugate points), render/sphere_marks.cpp what the sphere carries (the ball view's guide,
// the equator, stiffness ellipses, seams, loci, chart poles, a transported vector) and the labels.
//
// One convention for the far side: whatever the sphere hides (a path's section, a ball, a member's dot, a mark, a
// pole) is drawn over the sphere faint and hollow (paths dashed and flat, balls and dots as rings), never as a
// filled disc, so front and back are never confused.

#include <optional>
#include <string>
#include <vector>

#include "render/label_placer.hpp"
#include "render/panels.hpp"

namespace sl::detail {

constexpr double kTubeRadius = 0.014;  // world units (sphere radius 1)
constexpr double kBallRadius = 0.055;
// The ball view's jump through the antipode (from one side of the boundary to the other) is drawn as a gap,
// never a line. Consecutive path samples lie a few thousandths apart at the shipped sampling; a jump is a
// chord of nearly 2. Only the ball view can jump: other views never break a path on length.
constexpr double kMaxPathChord = 0.5;
// The far side's look: the colour at a fraction of its opacity, drawn flat over the sphere.
constexpr float kGhostAlpha = 0.55f;
// Dashes and gaps of hidden paths, in frame units.
constexpr float kGhostDash = 5.0f, kGhostGap = 3.5f;
// How far (pixels per frame unit) a thin path's drawn line may stray from its points to save vertices.
constexpr float kThinPathTolerance = 0.05f;
// A transported vector's arrow spans this much of the sphere whatever the frame's size.
constexpr double kTransportArrowLength = 0.2;

// Finite and not absurdly far (the frame state promises the unit ball or sphere; this guards the drawing).
bool drawable(const Vec3& p);
double distance(const Vec3& a, const Vec3& b);
// Hidden by the opaque unit sphere: the sight line from the eye to p passes through the sphere's inside before
// reaching p (p itself lies on or outside the sphere).
bool behindSphere(const SphereCamera& camera, const Vec3& p);
// Whether the surface point under a lifted one is on the far side. Lifted points just beyond the limb are still in
// sight past the sphere, and drawn as in front they would hang outside its outline.
bool surfaceBehind(const SphereCamera& camera, const Vec3& lifted);
// A point drawn on the sphere kept within its outline, `inset` pixels inside it: what is shifted sideways
// (coinciding runs side by side) or lifted off the surface never hangs past the limb.
P2 withinOutline(const SphereCamera& camera, P2 at, float inset);
// How the opaque unit sphere covers every pixel within `reach` pixels of p's image, by shaders/lit.frag's own test
// (hiddenBySphere: the sight line's near hit against the fragment's distance, blended over a pixel) evaluated at
// the nearest and farthest sight lines of that reach, with two pixels to spare: clear where no such pixel can be
// hidden, hidden where all are, else left to the shader.
SphereCover sphereCoverNear(const SphereCamera& camera, const Vec3& p, double reach);
Rgba ghost(Rgba c);
// A hidden line's half width: its own, but never bolder than the line in front would be there (a small frame's floor
// of a mark unit made hidden dashes bolder than the paths in front).
float hiddenHalfWidth(float own, float inFront);
// Over a sequential colour map the far side's faint lines would vanish on its dark end (viridis' purple): there
// they are drawn on a light halo, faint with them. The plain sphere and the diverging map (light in the middle, its
// ends mid-tones) keep them bare: a halo there changed little and doubled the hidden dashes a fan of 64 draws.
bool onDarkEndedMap(const PanelContext& context);
// The strip at a sphere panel's right kept for the colour bar of a coloured sphere (the sphere is framed in the rest).
float colorBarStrip(const PixelRect& rect);
Rgba farSideHalo(Rgba ghostColor);
// A hidden line, dashed and faint (on its halo over a dark-ended map); the halo's dashes are the line's own.
void dashedBehind(const PanelContext& context, const std::vector<PolylinePoint>& points, ShapeBatch& back);
// A hidden ring, faint (on its halo over a dark-ended map).
void ringBehind(const PanelContext& context, P2 at, float radius, float halfWidth, Rgba color, ShapeBatch& back);
P2 plus(P2 a, P2 b, float s = 1);
P2 unitDirection(P2 from, P2 to);
// Each point moved sideways (across the line's direction there) by `offset` times its half width.
void shiftAcross(std::vector<PolylinePoint>& points, float offset);
float pathAlpha(const ViewSettings& settings, double age);

// On the opaque sphere, points ride on a shell just outside it so the tube's front half is never
// inside the sphere; lines elsewhere are not occluded.
struct Placement {
  bool onSphere;
  double lift;
  Vec3 place(const Vec3& p) const {
    if (!onSphere) return p;
    const double r = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    const double s = r > 1e-12 ? (1.0 + lift) / r : 0.0;
    return {p.x * s, p.y * s, p.z * s};
  }
  Occludable world(const Vec3& p) const { return {float(p.x), float(p.y), float(p.z), onSphere ? 1.0f : 0.0f}; }
};

// === The runs (render/sphere_paths.cpp)

// How a path is drawn: a tube of `radius` (world units, at least `minHalfWidth` pixels) in `color`, or for `thin`
// paths (a family's members, many at once) flat lines with points closer than a pixel merged: the same picture at a
// fraction of the fill. `offset`: shifted sideways by that many half widths (coinciding runs side by side).
// `aging`: sections thinner and fainter the older they are (down to 60% of the width and 45% of the opacity at the
// start), so a long path carries its time.
struct PathLook {
  Rgba color;
  double radius;
  float minHalfWidth;
  bool thin = false;
  float offset = 0;
  bool aging = false;
};
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
  Vec3 centre;
  P2 markAt;
  bool marksDirection = true;
};
// The path, fading with age (view.path_fade_seconds); sections the sphere hides go dashed and faint into `back`
// (drawn before everything in front). The points drawn in front are added to `drawn` (for label placement).
void drawPath(const SharedSpan<Vec3>& path, const SharedSamples& times, const PathLook& look,
              const PanelContext& context, const SphereCamera& camera, const Placement& placement, bool throughAntipode,
              ShapeBatch& back, ShapeBatch& front, std::vector<P2>* drawn = nullptr);
// A run's family: each member's path as a thin line in the run's colour ramp, then the wavefront, the curve
// through the members' current points in member order, as a dark line over them, and a dot per member (a
// stopped member's dot on a red halo, as a stopped run's ball). Behind the sphere: dashed lines and rings.
void drawFamily(const RunFrame& run, const PanelContext& context, const SphereCamera& camera,
                const Placement& placement, bool throughAntipode, ShapeBatch& back, ShapeBatch& front,
                std::vector<P2>& drawn);
BallPlace placeBall(const RunFrame& run, float unit, const SphereCamera& camera, const Placement& placement);
// Balls whose places coincide on the screen (runs in the same state) are spread across their heading, side by side
// in run order, as their paths are: each stays visible and none looks larger or ranked. The group's direction mark
// is one arrowhead from the group's centre, drawn by its first moving member (one per ball read as a double mark).
void spreadCoincidingBalls(const std::vector<RunFrame>& runs, std::vector<BallPlace>& balls);
// The current state of a run. In front: a shaded ball on a thin dark rim (a stopped run's on a red halo), hidden
// per pixel where the sphere's outline passes in front of it. Behind the sphere: a hollow ring in its colour (a red
// one around it when stopped), nothing inside, so it never reads as a spot on the front. The direction mark: a
// filled arrowhead just past the ball pointing along the last section of the path (a moving run only; one for a group
// of coinciding balls, past the group's centre), dark on a light halo in front (it reads on a dark path or colour map),
// faint alone behind. The arrowhead and the hidden rings are kept within the sphere's outline (a ball in front,
// standing on the surface, may stand out past it at the limb). Returns the box of an arrowhead drawn in front, for
// labels to keep clear of.
std::optional<Box> drawBall(const RunFrame& run, const BallPlace& ball, const PanelContext& context,
                            const SphereCamera& camera, const Placement& placement, ShapeBatch& back,
                            ShapeBatch& front);
// The start of a run's path: a short dark bar across its first section (faint where the sphere hides it), kept
// within the sphere's outline as the path is (each end a half width inside it, so a bar at the limb is shortened).
void drawStart(const RunFrame& run, float offset, float unit, const SphereCamera& camera, const Placement& placement,
               ShapeBatch& back, ShapeBatch& front);
// Conjugate points on the path (runs with Jacobi fields): an ink ring around a dot of the run's colour, where
// the geodesics leaving the start together meet again; behind the sphere the faint ring alone.
void drawConjugatePoints(const RunFrame& run, float unit, const SphereCamera& camera, const Placement& placement,
                         ShapeBatch& back, ShapeBatch& front);

// === What the sphere carries, and labels (render/sphere_marks.cpp)

// 5+ rods: the ball view explained (frames/configuration_view.hpp): the ring of radius 1/2 (the great sphere at a
// right angle from the start) outlined, and a caption, wrapped to the panel, saying what the start mark, the
// radius, the ring and the rim mean and, for n > 5, which directions are shown.
void drawBallGuide(const PanelContext& context, const SphereCamera& camera, ShapeBatch& batch);
// The start of a 5+ rod path, the ball's centre: a cross drawn over the paths, on a halo of the background so it
// stays visible where a path runs through it.
void drawBallStart(const PanelContext& context, const SphereCamera& camera, ShapeBatch& batch);
// 3 rods: the configuration circle, the equator.
void drawEquator(const SphereCamera& camera, float unit, ShapeBatch& batch);
// Stiffness ellipses as light filled glyphs riding on the sphere (over the dark end of a colour map as over its
// light end: a half-white fill, a white stroke on a faint dark halo), hidden where the sphere is in front of them.
void drawEllipses(const std::vector<SphereEllipse>& ellipses, const SphereCamera& camera, const Placement& placement,
                  const PixelRect& rect, float unit, ShapeBatch& batch);
// A label at `anchor` placed by `placer` where it covers nothing else: on a pad of the background, joined to its
// anchor by a thin leader line when it had to move away. Faint (the far side's look) when `hidden`.
void drawLabel(const std::string& text, P2 anchor, bool hidden, const PanelContext& context, LabelPlacer& placer,
               std::vector<PixelRect>& placed, ShapeBatch& batch);
// The widest a label on the sphere may be: a share of the sphere's radius on the screen, so that a label is as large
// a part of the picture at every frame size. Text has a legibility floor (10 px), so a small frame takes a label's
// shorter form (render/frame_words.hpp: "φ = 90°", then "N"), never a label that crowds the sphere.
float labelBudget(const SphereCamera& camera);
// 4 rods: the chart's poles (phi = +-pi/2, where t is undefined and the published single-chart methods fail) are
// marked by the sphere shader on the front; both are named, a pole behind the sphere as a faint ring and label.
void labelChartPoles(const PanelContext& context, const SphereCamera& camera, LabelPlacer& placer,
                     std::vector<PixelRect>& placed, ShapeBatch& back, ShapeBatch& batch);
// The seams t = +-pi/2 (view.sphere.seam), where the published metric divides by zero: two meridians drawn as dashed
// red lines on the sphere (fainter behind it), one named where it faces the eye. The lines ride on the sphere under
// the paths and balls (`surface`), kept within its outline; the name goes with the labels.
void drawSeams(const PanelContext& context, const SphereCamera& camera, LabelPlacer& placer,
               std::vector<PixelRect>& placed, ShapeBatch& surface, ShapeBatch& back, ShapeBatch& labels);
// The distance colouring's loci and the closed geodesics (frame_state.hpp SphereCurve) riding on the sphere: a locus
// a line of its colour on a thin dark halo, a closed geodesic a faint thin ink line; what the sphere hides dashed and
// faint (the far-side convention), each kind named once where it faces the eye most. A point the scene names (not
// the start, which the path's bar marks) gets an ink ring over the paths (faint behind the sphere) and a label.
void drawLoci(const SphereDecoration& decoration, const PanelContext& context, const SphereCamera& camera,
              LabelPlacer& placer, std::vector<PixelRect>& placed, ShapeBatch& surface, ShapeBatch& back,
              ShapeBatch& labels);
// A vector carried round a geodesic polygon (view.sphere.holonomy), every side at once at the frame's fraction of
// the animation (SphereTransport): behind each carried vector the arrows it left at every other sample, ink on a
// light halo (faint where the sphere hides it); the carried vectors heavier; the starting vector at the first corner,
// whose corner is ringed, and at the end the returning vector beside it in its own colour. The arrows left behind fade
// as the paths do (view.path_fade_seconds). An arrow spans
// kTransportArrowLength of the sphere whatever the frame's size; its width follows the frame's unit, as the paths' do.
void drawTransport(const SphereTransport& transport, const PanelContext& context, const SphereCamera& camera,
                   LabelPlacer& placer, ShapeBatch& back, ShapeBatch& front);

}  // namespace sl::detail

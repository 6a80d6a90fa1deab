// The sphere panel: configuration-space paths of every run on (or, for 5+ rods, inside) the sphere.
// The sphere itself is drawn by shaders/sphere.frag; here the paths become shaded tubes that fade with
// age, lifted just above the surface and hidden per pixel where the sphere is in front of them. The pieces live in
// render/sphere_parts.hpp (the far-side convention, paths and balls, marks and labels); this file puts them
// together in drawing order. Time: a bar across each path's start, an arrowhead at the current state along its last
// section, older sections thinner and fainter where several runs share the sphere. Coinciding runs lie side by side
// (each path and ball shifted across its direction by its place among the runs), never nested by width, which would
// read as a ranking. Labels are placed where they cover nothing (render/label_placer.hpp).

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/color_map.hpp"
#include "render/frame_words.hpp"
#include "render/palette.hpp"
#include "render/panel_layout.hpp"
#include "render/panels.hpp"
#include "render/sphere_parts.hpp"

namespace sl {
namespace {

using namespace detail;

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
    context.font.draw(batch, caption, TextSize::Small, context.rect.x + pad, y, context.page().softInk);
    y += line;
  }
}

}  // namespace

SphereImpostor drawSpherePanel(const PanelContext& context, ShapeBatch& batch) {
  using namespace detail;
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
                        context.rect.x + pad, foot, context.page().softInk);
      foot -= context.font.lineHeight(TextSize::Small);
    }
    if (transportCaption)
      context.font.draw(
          batch,
          fittedForm(context.font,
                     transportCaptions(*decoration->transport, context.frame.time, context.frame.duration),
                     TextSize::Small, width),
          TextSize::Small, context.rect.x + pad, foot, context.page().ink);
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
      drawColorBar(scaleOf(field), caption, note, bar, context.font, context.page(), batch);
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

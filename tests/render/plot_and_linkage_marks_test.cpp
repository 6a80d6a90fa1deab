// What the plot and linkage panels mark beyond the data, read off their draw lists: the plots' "now" line, event
// times, a roundoff-only plot's one line, the stop cross's place; the linkage's masses, a stopped chain, a push.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fixtures/synthetic_frame.hpp"
#include "render/frame_composer.hpp"
#include "render/frame_words.hpp"
#include "render/palette.hpp"
#include "render/panels.hpp"
#include "render/plane_view.hpp"
#include "render/shape_batch.hpp"

namespace sl {
namespace {

bool sameColour(const ShapeVertex& v, const Rgba& c, bool alphaToo = false) {
  return std::abs(v.r - c.r) < 1e-6f && std::abs(v.g - c.g) < 1e-6f && std::abs(v.b - c.b) < 1e-6f &&
         (!alphaToo || std::abs(v.a - c.a) < 1e-6f);
}

// The first panel's vertices, copied: a range-for over a temporary DrawList's member would read freed memory.
std::vector<ShapeVertex> firstPanelVertices(const DrawList& list) { return list.panels[0].shapes.vertices(); }

// One plot panel filling the frame.
ViewSettings onePlot(int plotIndex) {
  ViewSettings view;
  view.panels = {{PanelKind::Plot, std::array<double, 4>{0, 0, 1, 1}, plotIndex}};
  view.titleLine = false;
  return view;
}

// One linkage panel filling the frame, one run drawn.
ViewSettings oneLinkage() {
  ViewSettings view;
  view.panels = {{PanelKind::Linkage, std::array<double, 4>{0, 0, 1, 1}, 0}};
  view.linkageLayout = LinkageLayout::SingleRun;
  view.titleLine = false;
  return view;
}

// The x pixel of time t in plot `plotIndex` of the frame, as the layout places the plot area.
float plotX(const FrameComposer& composer, const ViewSettings& view, const FrameState& frame, ImageSize size,
            int plotIndex, double t) {
  const PanelContext context{frame, view, composer.font(), composer.rects()[0], frameUnit(size)};
  const PlotLayout layout = layoutPlot(context, frame.plots[std::size_t(plotIndex)]);
  const PlotFrame& plot = frame.plots[std::size_t(plotIndex)];
  return float(layout.areaX0 + (t - plot.timeMin) / (plot.timeMax - plot.timeMin) * (layout.areaX1 - layout.areaX0));
}

// The "now" line stands at the frame's time, and moves with it, at every frame size.
TEST(PlotMarks, TheNowLineIsAtTheFramesTime) {
  const ViewSettings view = onePlot(1);
  for (const ImageSize size : {ImageSize{320, 180}, ImageSize{1280, 720}, ImageSize{3840, 2160}}) {
    const FrameComposer composer(view, size);
    for (const double t : {2.5, 7.0}) {
      SCOPED_TRACE(std::to_string(size.width) + " t = " + std::to_string(t));
      const FrameState frame = syntheticFrame(t, int(30 * t));
      std::vector<float> xs;
      for (const ShapeVertex& v : firstPanelVertices(composer.compose(frame)))
        if (sameColour(v, palette::nowCursor, true)) xs.push_back(v.x);
      ASSERT_FALSE(xs.empty()) << "no now line";
      const auto [lo, hi] = std::minmax_element(xs.begin(), xs.end());
      EXPECT_NEAR(0.5f * (*lo + *hi), plotX(composer, view, frame, size, 1, t), 0.5f);
      EXPECT_LT(*hi - *lo, 4 * markUnit(frameUnit(size))) << "a line, not a band";
    }
  }
}

// Every y axis is named (what and unit) above its top tick label.
TEST(PlotMarks, TheValueAxisIsNamed) {
  FrameState frame = syntheticFrame(7.0, 210);
  const ViewSettings view = onePlot(1);
  const FrameComposer composer(view, {1280, 720});
  const PanelContext context{frame, view, composer.font(), composer.rects()[0], 1};
  const PlotLayout named = layoutPlot(context, frame.plots[1]);
  ASSERT_TRUE(named.valueLabelShown);
  EXPECT_LT(named.valueLabelBaseline, named.areaY0) << "the name sits above the plot area";
  EXPECT_GT(named.valueLabelBaseline - composer.font().ascent(TextSize::Small), named.legendBottom);
  EXPECT_EQ(valueAxisWords(frame.plots[1].kind), "|E − E₀| / E₀ (no unit)");
  frame.plots[1].roundoff = PlotFrame::RoundoffOnly{3.2e-15, false, 1};
  EXPECT_FALSE(layoutPlot(context, frame.plots[1]).valueLabelShown) << "a roundoff-only plot has no axis to name";
}

// A legend of one series named as the plot's title begins (the holonomy plot's) is left out; one naming a run stays.
TEST(PlotMarks, ALegendThatRepeatsTheTitleIsLeftOut) {
  FrameState frame = syntheticFrame(7.0, 210);
  const ViewSettings view = onePlot(1);
  const FrameComposer composer(view, {1280, 720});
  const PanelContext context{frame, view, composer.font(), composer.rects()[0], 1};
  PlotFrame& plot = frame.plots[1];
  plot.series.resize(1);
  const PlotLayout named = layoutPlot(context, plot, {"relative energy error"});
  EXPECT_TRUE(named.legendShown) << "one run's series keeps its name";
  plot.series[0].label = "relative energy";
  const PlotLayout repeated = layoutPlot(context, plot, {"relative energy error"});
  EXPECT_FALSE(repeated.legendShown);
  EXPECT_LE(repeated.areaY0, named.areaY0);
}

// A plot whose every value is roundoff says so in one line, and draws no axis, tick, line or now line.
TEST(PlotMarks, ARoundoffOnlyPlotSaysSoInOneLineWithoutAnAxis) {
  FrameState frame = syntheticFrame(7.0, 210);
  const ViewSettings view = onePlot(1);
  const FrameComposer composer(view, {1280, 720});
  const ShapeBatch plotted = composer.compose(frame).panels[0].shapes;
  frame.plots[1].roundoff = PlotFrame::RoundoffOnly{3.2e-15, false, 1};
  ASSERT_EQ(frame.plots[1].kind, PlotKind::EnergyError);
  EXPECT_EQ(roundoffNotes(frame.plots[1]).front(), "energy conserved to 3×10⁻¹⁵ over the run");
  // Shorter forms for small frames, the level kept (at 320x180 the tolerance's note ended "integrator's…").
  PlotFrame byTolerance = frame.plots[1];
  byTolerance.roundoff = PlotFrame::RoundoffOnly{2e-9, true, 1};
  EXPECT_EQ(roundoffNotes(byTolerance).front(), "energy conserved to 2×10⁻⁹ over the run, as its integrator's tolerance allows");
  EXPECT_EQ(roundoffNotes(byTolerance).back(), "energy conserved to 2×10⁻⁹");
  EXPECT_EQ(typesetPowerOfTen(1e-14), "10⁻¹⁴");
  EXPECT_EQ(typesetPowerOfTen(9.7e-15), "10⁻¹⁴");
  const ShapeBatch noted = composer.compose(frame).panels[0].shapes;
  std::size_t axisInk = 0, grid = 0, capsules = 0;
  for (const ShapeVertex& v : noted.vertices()) {
    axisInk += v.kind == 0 && sameColour(v, palette::softInk) ? 1 : 0;
    grid += sameColour(v, palette::gridLight) ? 1 : 0;
    capsules += v.kind == 0 ? 1 : 0;
  }
  EXPECT_EQ(axisInk, 0u) << "an axis line";
  EXPECT_EQ(grid, 0u) << "grid lines";
  std::size_t plottedCapsules = 0;
  for (const ShapeVertex& v : plotted.vertices()) plottedCapsules += v.kind == 0 ? 1 : 0;
  EXPECT_LT(capsules, plottedCapsules / 4) << "lines beyond the legend's swatches";
  // The note's glyphs lie around the middle of the panel, on one line.
  const PixelRect rect = composer.rects()[0];
  float lo = 1e9f, hi = -1e9f;
  for (const ShapeVertex& v : noted.vertices())
    if (v.kind == 3 && v.y > rect.y + 0.3f * rect.height) lo = std::min(lo, v.y), hi = std::max(hi, v.y);
  ASSERT_LT(lo, hi) << "no note in the middle of the panel";
  EXPECT_LT(hi - lo, 2.2f * composer.font().lineHeight(TextSize::Small)) << "more than one line";
}

// The stop cross sits on the line's last value before the stop; a line without any drawable value before its stop
// gets no cross at all (never one at the axis floor, a value the run never had).
TEST(PlotMarks, TheStopCrossSitsOnTheLastValue) {
  SyntheticOptions stopping;
  stopping.stopSecondRun = true;
  const ViewSettings view = onePlot(1);
  const ImageSize size{1280, 720};
  const FrameComposer composer(view, size);
  FrameState frame = syntheticFrame(7.0, 210, stopping);
  const PlotSeries& series = frame.plots[1].series[1];
  ASSERT_TRUE(std::isfinite(series.stopTime));
  // The series' last value before its stop, on screen.
  const PanelContext context{frame, view, composer.font(), composer.rects()[0], 1};
  const PlotLayout layout = layoutPlot(context, frame.plots[1]);
  std::size_t last = 0;
  for (std::size_t i = 0; i < series.times.size(); ++i)
    if (series.times[i] <= series.stopTime) last = i;
  std::vector<float> xs, ys;
  for (const ShapeVertex& v : firstPanelVertices(composer.compose(frame)))
    if (sameColour(v, palette::stopRed) && v.kind == 0) xs.push_back(v.x), ys.push_back(v.y);
  ASSERT_FALSE(xs.empty());
  const auto [x0, x1] = std::minmax_element(xs.begin(), xs.end());
  const auto [y0, y1] = std::minmax_element(ys.begin(), ys.end());
  EXPECT_NEAR(0.5f * (*x0 + *x1), plotX(composer, view, frame, size, 1, series.times[last]), 1.5f);
  // Its height on a log axis between the area's ends: well above the floor, the value's own place.
  const float middle = 0.5f * (*y0 + *y1);
  EXPECT_LT(middle, layout.areaY1 - 10) << "the cross sits on the axis floor";
  EXPECT_GT(middle, layout.areaY0);

  // The same series with no drawable value (zeros on a log axis): no cross.
  PlotSeries& zeros = frame.plots[1].series[1];
  for (std::size_t i = 0; i < zeros.values.size(); ++i) zeros.values[i] = 0;
  for (const ShapeVertex& v : firstPanelVertices(composer.compose(frame)))
    EXPECT_FALSE(sameColour(v, palette::stopRed) && v.kind == 0) << "a cross at a value the run never had";
}

// The stop's time is written by its cross, never on the left at the cross's height, where the line comes in (it lay
// over the line there: comparison.json frame 593).
TEST(PlotMarks, TheStopTimeIsWrittenClearOfTheIncomingLine) {
  SyntheticOptions stopping;
  stopping.stopSecondRun = true;
  const ViewSettings view = onePlot(1);
  const FrameComposer composer(view, {1280, 720});
  FrameState frame = syntheticFrame(7.0, 210, stopping);
  // The stop at the time axis' right end, where the label cannot go on the right.
  frame.plots[1].timeMax = frame.plots[1].series[1].stopTime * 1.005;
  float crossX0 = INFINITY, crossX1 = -INFINITY, crossY0 = INFINITY, crossY1 = -INFINITY;
  std::vector<ShapeVertex> glyphs;
  for (const ShapeVertex& v : firstPanelVertices(composer.compose(frame))) {
    if (!sameColour(v, palette::stopRed)) continue;
    if (v.kind == 0) crossX0 = std::min(crossX0, v.x), crossX1 = std::max(crossX1, v.x), crossY0 = std::min(crossY0, v.y), crossY1 = std::max(crossY1, v.y);
    if (v.kind == 3) glyphs.push_back(v);
  }
  ASSERT_LT(crossX0, crossX1);
  ASSERT_FALSE(glyphs.empty()) << "the stop's time is not written";
  // The line's last section ends at the cross's centre from the left: a point of it just left of the cross.
  const float cx = 0.5f * (crossX0 + crossX1), cy = 0.5f * (crossY0 + crossY1), incoming = cx - (crossX1 - crossX0);
  float x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const ShapeVertex& v : glyphs) x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
  EXPECT_FALSE(x0 < incoming && x1 > incoming && y0 < cy && y1 > cy) << "the stop time lies on the line coming in";
}

// A marked time (a conjugate point) is written beside its mark: more glyphs with the mark than without.
TEST(PlotMarks, MarkedTimesAreWritten) {
  FrameState frame = syntheticFrame(7.0, 210);
  const ViewSettings view = onePlot(1);
  const FrameComposer composer(view, {1280, 720});
  auto glyphsIn = [&](const FrameState& f, float xLo, float xHi) {
    std::size_t count = 0;
    for (const ShapeVertex& v : firstPanelVertices(composer.compose(f)))
      count += v.kind == 3 && v.x >= xLo && v.x <= xHi ? 1 : 0;
    return count;
  };
  const float at = plotX(composer, view, frame, {1280, 720}, 1, 3.14159);
  const std::size_t before = glyphsIn(frame, at, at + 80);
  frame.plots[1].series[0].markTimes = {3.14159};
  EXPECT_GE(glyphsIn(frame, at, at + 80), before + 4 * 4) << "no \"3.14\" beside the mark";
}

// The disc radii drawn at each interior hinge in the run's colour (the ball's coloured core), by hinge.
std::vector<float> hingeCores(const FrameState& frame, const ViewSettings& view, ImageSize size) {
  const FrameComposer composer(view, size);
  const DrawList list = composer.compose(frame);
  const PlaneView plane = fitFrameView(frame, composer.rects()[0]);
  const RunFrame& run = frame.runs[0];
  std::vector<float> radii(run.hinges.size(), 0.0f);
  for (const ShapeVertex& v : list.panels[0].shapes.vertices()) {
    if (v.kind != 1 || !sameColour(v, toRgba(run.color))) continue;
    const P2 centre{v.x - v.localX, v.y - v.localY};
    for (std::size_t k = 0; k < run.hinges.size(); ++k) {
      const P2 hinge = plane(run.hinges[k]);
      if (std::hypot(centre.x - hinge.x, centre.y - hinge.y) < 0.5f) radii[k] = std::max(radii[k], v.size);
    }
  }
  return radii;
}

// A hinge's ball shows its mass: none for a massless hinge, larger for a heavier one.
TEST(LinkageMarks, HingeBallsShowTheHingeMasses) {
  FrameState frame = syntheticFrame(3.0, 90);
  frame.runs.resize(1);
  const std::vector<float> unit = hingeCores(frame, oneLinkage(), {1280, 720});
  ASSERT_EQ(unit.size(), 3u);
  for (const float r : unit) EXPECT_GT(r, 0) << "a unit mass without its ball";
  frame.runs[0].hingeMasses = {0, 1, 8};
  const std::vector<float> weighed = hingeCores(frame, oneLinkage(), {1280, 720});
  EXPECT_EQ(weighed[0], 0) << "a massless hinge with a ball";
  EXPECT_NEAR(weighed[1], unit[1], 1e-4f);
  EXPECT_NEAR(weighed[2], 2 * unit[2], 1e-3f) << "a ball of 8 unit masses has twice the radius";
}

// A rod's thickness shows its mass.
TEST(LinkageMarks, HeavierRodsAreThicker) {
  FrameState frame = syntheticFrame(3.0, 90);
  frame.runs.resize(1);
  auto widest = [&](const FrameState& f) {
    float width = 0;
    for (const ShapeVertex& v : firstPanelVertices(FrameComposer(oneLinkage(), {1280, 720}).compose(f)))
      if (v.kind == 0 && sameColour(v, palette::silver)) width = std::max(width, v.size);
    return width;
  };
  const float massless = widest(frame);
  frame.runs[0].rodMasses = {0, 3, 0, 0};
  EXPECT_NEAR(widest(frame), 2 * massless, 1e-3f) << "a rod of mass 3 has twice a massless rod's half width";
}

// A stopped chain is grey (no silver rod, no run colour left) and crossed out in red; a running one is neither.
TEST(LinkageMarks, AStoppedChainIsGreyAndCrossed) {
  SyntheticOptions stopping;
  stopping.stopSecondRun = true;
  FrameState frame = syntheticFrame(7.0, 210, stopping);
  ViewSettings view = oneLinkage();
  auto count = [&](const FrameState& f, const Rgba& c) {
    std::size_t n = 0;
    for (const ShapeVertex& v : firstPanelVertices(FrameComposer(view, {1280, 720}).compose(f)))
      n += sameColour(v, c) ? 1 : 0;
    return n;
  };
  view.linkageRun = 1;  // the stopped one
  ASSERT_TRUE(frame.runs[1].stopped);
  EXPECT_GT(count(frame, palette::stoppedGrey), 0u);
  EXPECT_GT(count(frame, palette::stopRed), 0u);
  EXPECT_EQ(count(frame, palette::silver), 12u) << "silver beyond the two pins' cores";
  EXPECT_EQ(count(frame, toRgba(frame.runs[1].color)), 0u);
  view.linkageRun = 0;  // the running one
  EXPECT_EQ(count(frame, palette::stoppedGrey), 0u);
  EXPECT_EQ(count(frame, palette::stopRed), 0u);
}

// A push start is an arrow at the pushed hinge, along the push, in the first frames only.
TEST(LinkageMarks, APushIsAnArrowAlongIt) {
  FrameState frame = syntheticFrame(0.0, 0);
  frame.runs.resize(1);
  frame.runs[0].push = {{2, {0.0, 1.0}}};  // hinge 2 pushed straight up
  frame.runs[0].pushShown = 1;
  const FrameComposer composer(oneLinkage(), {1280, 720});
  const PlaneView plane = fitFrameView(frame, composer.rects()[0]);
  const P2 hinge = plane(frame.runs[0].hinges[1]);
  float top = 1e9f;
  std::size_t arrow = 0;
  for (const ShapeVertex& v : firstPanelVertices(composer.compose(frame))) {
    if (!sameColour(v, palette::ink) || v.kind != 0) continue;
    ++arrow;
    top = std::min(top, v.y);
    EXPECT_NEAR(v.x, hinge.x, 12) << "the arrow leaves the hinge sideways";
  }
  ASSERT_GT(arrow, 0u) << "no arrow";
  EXPECT_LT(top, hinge.y - 40) << "the arrow does not point up";
  frame.runs[0].pushShown = 0;
  for (const ShapeVertex& v : firstPanelVertices(composer.compose(frame)))
    EXPECT_FALSE(sameColour(v, palette::ink) && v.kind == 0) << "an arrow after the push has faded";
}

}  // namespace
}  // namespace sl

// The CPU part of the renderer, without any GL context: what each panel puts into the draw list.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "fixtures/synthetic_frame.hpp"
#include "render/frame_composer.hpp"
#include "render/frame_words.hpp"
#include "render/palette.hpp"
#include "render/panels.hpp"
#include "render/plane_view.hpp"
#include "render/shape_batch.hpp"

namespace sl {
namespace {

ViewSettings fourPanels() {
  ViewSettings view;
  view.panels = {{PanelKind::Text, std::array<double, 4>{0, 0, 1, 0.15}, 0},
                 {PanelKind::Sphere, std::array<double, 4>{0, 0.15, 0.5, 0.85}, 0},
                 {PanelKind::Linkage, std::array<double, 4>{0.5, 0.15, 0.5, 0.4}, 0},
                 {PanelKind::Plot, std::array<double, 4>{0.5, 0.55, 0.5, 0.45}, 1}};
  view.linkageLayout = LinkageLayout::SideBySide;
  return view;
}

bool hasProgram(const ShapeBatch& shapes, ShapeProgram program) {
  for (const ShapeSegment& segment : shapes.segments())
    if (segment.program == program && segment.count > 0) return true;
  return false;
}

TEST(DrawList, OnePanelDrawingPerPanelInLayoutOrder) {
  const FrameComposer composer(fourPanels(), {640, 360});
  const DrawList list = composer.compose(syntheticFrame(2.0, 120));
  ASSERT_EQ(list.panels.size(), 4u);
  EXPECT_EQ(list.size.width, 640);
  EXPECT_TRUE(list.sphereIsStatic);
  // Only the sphere panel carries an impostor sphere; the text panel is text, the sphere panel lit tubes.
  EXPECT_FALSE(list.panels[0].sphere);
  ASSERT_TRUE(list.panels[1].sphere);
  EXPECT_EQ(list.panels[1].sphere->look, SphereLook::Opaque);
  EXPECT_TRUE(hasProgram(list.panels[0].shapes, ShapeProgram::Glyph));
  EXPECT_TRUE(hasProgram(list.panels[1].shapes, ShapeProgram::Lit));
  EXPECT_FALSE(list.panels[3].shapes.vertices().empty());
}

// Without a text panel, the title and the time go across the top of the frame, glyphs in its top
// line only; a text panel, or view.title_line false, leaves them out.
// The renderer draws batches as indexed quads (render/gl/renderer.cpp, upload): every six vertices are the corners
// 0 1 2 0 2 3 of one quad, in every panel's batch, segments included.
TEST(DrawList, EveryShapeIsQuadsOfSixVerticesInCornerOrder) {
  auto same = [](const ShapeVertex& a, const ShapeVertex& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  const DrawList list = FrameComposer(fourPanels(), {640, 360}).compose(syntheticFrame(2.0, 120));
  for (const PanelDrawing& panel : list.panels) {
    const auto& v = panel.shapes.vertices();
    ASSERT_EQ(v.size() % 6, 0u);
    for (std::size_t q = 0; q < v.size(); q += 6)
      ASSERT_TRUE(same(v[q + 3], v[q]) && same(v[q + 4], v[q + 2])) << "quad " << q / 6;
    for (const ShapeSegment& segment : panel.shapes.segments())
      EXPECT_TRUE(segment.first % 6 == 0 && segment.count % 6 == 0);
  }
}

TEST(DrawList, ATitleLineWhenThereIsNoTextPanel) {
  ViewSettings noText = fourPanels();
  noText.panels.erase(noText.panels.begin());
  const DrawList withLine = FrameComposer(noText, {640, 360}).compose(syntheticFrame(2.0, 120));
  ASSERT_EQ(withLine.panels.size(), 4u);  // three panels and the title line
  const ShapeBatch& line = withLine.panels.back().shapes;
  EXPECT_TRUE(hasProgram(line, ShapeProgram::Glyph));
  for (const ShapeVertex& v : line.vertices()) EXPECT_LT(v.y, 0.1f * 360) << "a glyph below the top line";
  noText.titleLine = false;
  EXPECT_EQ(FrameComposer(noText, {640, 360}).compose(syntheticFrame(2.0, 120)).panels.size(), 3u);
  EXPECT_EQ(FrameComposer(fourPanels(), {640, 360}).compose(syntheticFrame(2.0, 120)).panels.size(), 4u);
}

bool isStopRed(const ShapeVertex& v) {
  return std::abs(v.r - palette::stopRed.r) < 1e-6f && std::abs(v.g - palette::stopRed.g) < 1e-6f &&
         std::abs(v.b - palette::stopRed.b) < 1e-6f;
}

// A run's stop is shown where it happened in its plots: red shapes (the cross) inside the plot area at
// the stop time's x, and none while every run still moves.
TEST(DrawList, AStoppedRunIsCrossedOutInItsPlotWhereItStopped) {
  ViewSettings view = fourPanels();
  const FrameComposer composer(view, {640, 360});
  SyntheticOptions stopping;
  stopping.stopSecondRun = true;
  const FrameState frame = syntheticFrame(7.0, 420, stopping);  // the second run stopped at t = 5 of 10
  ASSERT_TRUE(std::isfinite(frame.plots[1].series[1].stopTime));
  const DrawList list = composer.compose(frame);
  const PanelDrawing& plot = list.panels[3];
  std::vector<float> xs;
  for (const ShapeVertex& v : plot.shapes.vertices())
    if (isStopRed(v) && v.kind == float(ShapeKind::Capsule)) xs.push_back(v.x);  // the cross, not its time's text
  ASSERT_FALSE(xs.empty()) << "no stop cross in the plot";
  const auto [lo, hi] = std::minmax_element(xs.begin(), xs.end());
  // The plot's time axis spans 0..10 across most of the panel: t = 5 lies near its middle.
  const float middle = plot.rect.x + 0.5f * plot.rect.width;
  EXPECT_NEAR(0.5f * (*lo + *hi), middle, 0.12f * plot.rect.width);
  EXPECT_LT(*hi - *lo, 0.1f * plot.rect.width) << "the cross is a mark, not a line";

  const DrawList running = composer.compose(syntheticFrame(7.0, 420));
  for (const ShapeVertex& v : running.panels[3].shapes.vertices()) EXPECT_FALSE(isStopRed(v));
}

// The automatic layout keeps the title line's band free, so the title and the time never sit on a panel
// (default-like scenes without a text panel), at every frame size.
TEST(DrawList, TheTitleLineHasABandOfItsOwn) {
  ViewSettings view;
  view.panels = {{PanelKind::Sphere, std::nullopt, 0}, {PanelKind::Linkage, std::nullopt, 0}};
  for (const ImageSize size : {ImageSize{320, 180}, ImageSize{640, 360}, ImageSize{1920, 1080}, ImageSize{1080, 1920}}) {
    const FrameComposer composer(view, size);
    const DrawList list = composer.compose(syntheticFrame(2.0, 120));
    ASSERT_EQ(list.panels.size(), 3u);
    float panelsTop = float(size.height);
    for (std::size_t i = 0; i < 2; ++i) panelsTop = std::min(panelsTop, list.panels[i].rect.y);
    EXPECT_GT(panelsTop, 0) << size.width << "x" << size.height;
    for (const ShapeVertex& v : list.panels.back().shapes.vertices())
      ASSERT_LE(v.y, panelsTop + 0.5f) << "title line over a panel at " << size.width << "x" << size.height;
  }
}

// A plot's parts never overlap and stay inside its panel at every frame size: title, then legend, then
// the plot area (which the legend never covers), with room for the y labels, the last x label and "t"; plots of the
// comparison layout (two plots beside the sphere) keep a plot area even at 320x180.
TEST(PlotLayoutTest, TitleLegendAndAreaNeverOverlapAtAnySize) {
  ViewSettings view;
  view.panels = {{PanelKind::Text, std::nullopt, 0},   {PanelKind::Sphere, std::nullopt, 0},
                 {PanelKind::Linkage, std::nullopt, 0}, {PanelKind::Plot, std::nullopt, 0},
                 {PanelKind::Plot, std::nullopt, 1}};
  const FrameState frame = syntheticFrame(7.0, 420);
  for (const ImageSize size : {ImageSize{320, 180}, ImageSize{640, 360}, ImageSize{1280, 720}, ImageSize{1920, 1080},
                               ImageSize{3840, 2160}, ImageSize{1080, 1920}}) {
    const FrameComposer composer(view, size);
    for (const int p : {3, 4}) {
      SCOPED_TRACE(std::to_string(size.width) + "x" + std::to_string(size.height) + " plot " + std::to_string(p));
      const PixelRect rect = composer.rects()[std::size_t(p)];
      const PanelContext context{frame, view, composer.font(), rect, frameUnit(size)};
      const PlotLayout layout = layoutPlot(context, frame.plots[std::size_t(p - 3)]);
      ASSERT_TRUE(layout.areaShown);
      EXPECT_GT(layout.areaX1 - layout.areaX0, 0.4f * rect.width);
      EXPECT_GT(layout.areaY1 - layout.areaY0, 0.2f * rect.height);
      EXPECT_GE(layout.titleBaseline - composer.font().ascent(layout.titleSize), rect.y);
      EXPECT_LE(composer.font().width(layout.title, layout.titleSize), rect.width);
      EXPECT_GE(layout.areaX0, rect.x);
      EXPECT_LE(layout.areaX1 + composer.font().width("t", TextSize::Small), rect.x + rect.width);
      EXPECT_LE(layout.areaY1 + composer.font().lineHeight(TextSize::Small), rect.y + rect.height);
      if (size.width >= 640) {
        EXPECT_TRUE(layout.legendShown);
      }
      if (layout.legendShown) {
        EXPECT_LT(layout.legendBottom + 0.25f * composer.font().lineHeight(TextSize::Small), layout.areaY0)
            << "the legend reaches into the plot area";
      }
    }
  }
}

// A plot draws what its width can show: a series of a million samples costs about what one of ten thousand does
// (every stride-th sample and the last), and a short series is drawn whole.
TEST(PlotLayoutTest, LongSeriesAreThinnedToThePlotsWidth) {
  const auto plotVertices = [](std::size_t samples) {
    FrameState frame = syntheticFrame(7.0, 420);
    std::vector<double> times(samples), values(samples);
    for (std::size_t i = 0; i < samples; ++i) {
      times[i] = 10.0 * double(i) / double(samples);
      values[i] = 1e-10 * (2 + std::sin(0.01 * double(i)));
    }
    for (PlotSeries& series : frame.plots[1].series) series.times = times, series.values = values;
    return FrameComposer(fourPanels(), {640, 360}).compose(frame).panels[3].shapes.vertices().size();
  };
  const std::size_t few = plotVertices(200), some = plotVertices(10'000), many = plotVertices(1'000'000);
  EXPECT_LT(few, some);                          // 200 samples: all drawn
  EXPECT_LT(double(many), 2.0 * double(some));  // without thinning: about 100 times as many
}

// A plot's lines nest like the runs' paths: each later series is narrower, so a line exactly under
// another still shows along both its edges.
TEST(PlotLayoutTest, CoincidingSeriesBothShow) {
  ViewSettings view = fourPanels();
  FrameState frame = syntheticFrame(7.0, 420);
  frame.plots[1].series[1].values = frame.plots[1].series[0].values;  // run 2's energy error = the reference's
  frame.plots[1].series[1].times = frame.plots[1].series[0].times;
  const DrawList list = FrameComposer(view, {640, 360}).compose(frame);
  float widthFirst = 0, widthSecond = 0;
  const ColorRGB first = frame.plots[1].series[0].color, second = frame.plots[1].series[1].color;
  for (const ShapeVertex& v : list.panels[3].shapes.vertices()) {
    if (v.kind != float(ShapeKind::Capsule)) continue;
    if (v.r == first.r && v.g == first.g && v.b == first.b) widthFirst = std::max(widthFirst, v.size);
    if (v.r == second.r && v.g == second.g && v.b == second.b) widthSecond = std::max(widthSecond, v.size);
  }
  ASSERT_GT(widthSecond, 0);
  EXPECT_GT(widthFirst, widthSecond + 0.5f) << "the first line would hide under the second";
}

// Side by side, each run's caption sits just under the lowest place its chain can reach, not at the
// foot of a tall panel (it floated about 100 px below its linkage).
TEST(DrawList, SideBySideCaptionsSitUnderTheirLinkages) {
  ViewSettings view = fourPanels();
  view.panels[2].rect = std::array<double, 4>{0.5, 0.15, 0.5, 0.6};  // a tall linkage panel
  const FrameComposer composer(view, {1280, 720});
  const FrameState frame = syntheticFrame(3.0, 180);
  const DrawList list = composer.compose(frame);
  const PixelRect panel = list.panels[2].rect;
  const PixelRect column{panel.x, panel.y, panel.width / 2, panel.height};
  const float boxBottom = fitFrameView(frame, column, captionHeight(composer.font())).boxBottom;
  const float line = composer.font().lineHeight(TextSize::Small);
  float lowest = 0;
  std::size_t glyphs = 0;
  for (const ShapeVertex& v : list.panels[2].shapes.vertices())
    if (v.kind == float(ShapeKind::Glyph)) lowest = std::max(lowest, v.y), ++glyphs;
  ASSERT_GT(glyphs, 0u);
  EXPECT_GT(lowest, boxBottom);
  EXPECT_LT(lowest, boxBottom + 1.6f * line) << "the caption floats below its linkage";
  EXPECT_LT(boxBottom + 2 * line, panel.y + panel.height) << "the test's panel is not tall enough to tell";
}

// A stopped run's reason is explained in the text panel where there is room (a line of its own, in the
// stop colour: its meaning among it), and left out where there is not.
TEST(DrawList, AStopIsExplainedWhereThereIsRoom) {
  SyntheticOptions stopping;
  stopping.stopSecondRun = true;
  const FrameState frame = syntheticFrame(7.0, 420, stopping);
  const std::string meaning = stopMeaningWords(frame.runs[1].stopReason);
  for (const ImageSize size : {ImageSize{1280, 720}, ImageSize{320, 180}}) {
    const FrameComposer composer(fourPanels(), size);
    const DrawList list = composer.compose(frame);  // kept: a range-for over a temporary's member would dangle
    std::size_t red = 0;
    for (const ShapeVertex& v : list.panels[0].shapes.vertices())
      red += v.kind == float(ShapeKind::Glyph) && isStopRed(v);
    ShapeBatch alone;
    composer.font().draw(alone, meaning, TextSize::Small, 0, 20, palette::stopRed);
    ASSERT_GT(red, 0u);
    if (size.width >= 1280) {
      EXPECT_GT(red, alone.vertices().size()) << "no explanation at " << size.width;
    } else {
      EXPECT_LT(red, alone.vertices().size()) << "an explanation squeezed into a small frame";
    }
  }
}

// One stop line per run: explained, the stop is said on a line of its own (time, reason, reading, meaning) and not
// again on the run's row: the stop colour's glyphs are exactly that line's, its words made from the typed stop.
TEST(DrawList, AStopIsSaidOnceInTheTextPanel) {
  SyntheticOptions stopping;
  stopping.stopSecondRun = true;
  FrameState frame = syntheticFrame(7.0, 420, stopping);
  frame.runs[1].stopReason = StopReason::EnergyBlowUp;
  frame.runs[1].stopMeasured = 2.1253;
  frame.runs[1].stopLimit = 1;
  const FrameComposer composer(fourPanels(), {1280, 720});
  const DrawList list = composer.compose(frame);  // kept: a range-for over a temporary's member would dangle
  std::size_t red = 0;
  for (const ShapeVertex& v : list.panels[0].shapes.vertices())
    red += v.kind == float(ShapeKind::Glyph) && isStopRed(v);
  char time[32];
  std::snprintf(time, sizeof time, "%.3g", frame.runs[1].stopTime);
  // Written out here, independently of render/frame_words.cpp.
  const std::string line = frame.runs[1].name + " stopped at t = " + time +
                           ": energy-blow-up (energy drift 2.13 > limit 1) \u2014 "
                           "the relative energy drift passed the watchdog's limit";
  ShapeBatch alone;
  composer.font().draw(alone, line, TextSize::Small, 0, 20, palette::stopRed);
  EXPECT_EQ(red, alone.vertices().size());
}

// A run's row names its method only where the runs differ by method: with one method for all, the method words
// are noise and the text panel draws exactly their glyphs fewer.
TEST(DrawList, MethodsAreNamedOnlyWhereRunsDifferByThem) {
  FrameState frame = syntheticFrame(2.0, 120);
  ASSERT_EQ(frame.runs.size(), 2u);
  const FrameComposer composer(fourPanels(), {1280, 720});
  const auto glyphs = [&](const FrameState& f) {
    const DrawList list = composer.compose(f);  // kept: a range-for over a temporary's member would dangle
    std::size_t count = 0;
    for (const ShapeVertex& v : list.panels[0].shapes.vertices()) count += v.kind == float(ShapeKind::Glyph);
    return count;
  };
  frame.runs[0].method = Method::Ambient;
  frame.runs[1].method = Method::Christoffel;
  const std::size_t differing = glyphs(frame);
  frame.runs[0].method = Method::Christoffel;
  const std::size_t same = glyphs(frame);
  ShapeBatch words;
  composer.font().draw(words, "  (ambient)  (christoffel)", TextSize::Normal, 0, 20, palette::ink);  // spaces are quads too
  EXPECT_EQ(differing - same, words.vertices().size()) << "the method words of two runs that differ by method";
  EXPECT_GT(differing, same);
}

// Both chart poles are named in the sphere panel, the one behind the sphere too (faintly); a 3-rod circle has none.
TEST(DrawList, BothChartPolesAreLabelled) {
  ViewSettings view = fourPanels();
  const FrameState frame = syntheticFrame(2.0, 120);
  for (const Vec3 direction : {Vec3{0.5, 0.6, 0.62}, Vec3{1, 0, 0}, Vec3{0.3, -0.2, -0.9}}) {
    view.camera.viewDirection = direction;
    const DrawList list = FrameComposer(view, {640, 360}).compose(frame);
    ASSERT_TRUE(list.panels[1].sphere);
    EXPECT_EQ(list.panels[1].sphere->labels.size(), 2u) << direction.x << " " << direction.y << " " << direction.z;
  }
  SyntheticOptions circle;
  circle.viewSpace = ViewSpace::Circle;
  EXPECT_TRUE(FrameComposer(view, {640, 360}).compose(syntheticFrame(2.0, 120, circle)).panels[1].sphere->labels.empty());
}

// view.sphere.seam: the seams are drawn and one is named, beside the two poles; without it, neither.
TEST(DrawList, TheSeamIsDrawnAndNamedWhenAsked) {
  ViewSettings view = fourPanels();
  view.camera.viewDirection = {0.2, 0.9, 0.4};  // facing the seam t = pi/2
  FrameState frame = syntheticFrame(2.0, 120);
  const DrawList plain = FrameComposer(view, {640, 360}).compose(frame);
  auto seams = std::make_shared<SphereDecoration>();
  seams->seam = true;
  frame.sphereDecoration = seams;
  const DrawList seamed = FrameComposer(view, {640, 360}).compose(frame);
  EXPECT_EQ(plain.panels[1].sphere->labels.size(), 2u);
  EXPECT_EQ(seamed.panels[1].sphere->labels.size(), 3u);
  EXPECT_GT(seamed.panels[1].shapes.vertices().size(), plain.panels[1].shapes.vertices().size() + 6 * 20);
}

bool intersects(const PixelRect& a, const PixelRect& b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}
bool inside(const PixelRect& inner, const PixelRect& outer) {
  return inner.x >= outer.x && inner.y >= outer.y && inner.x + inner.width <= outer.x + outer.width &&
         inner.y + inner.height <= outer.y + outer.height;
}

// Labels on the sphere never overlap each other or a ball, and stay inside the sphere panel (so never in the title
// band or a neighbouring panel): every camera, size, run count and time tried.
TEST(DrawList, SphereLabelsCoverNoLabelBallOrBand) {
  ViewSettings view;  // sphere + linkage with the title line
  view.panels = {{PanelKind::Sphere, std::nullopt, 0}, {PanelKind::Linkage, std::nullopt, 0}};
  int checked = 0;
  for (const ImageSize size : {ImageSize{320, 180}, ImageSize{640, 360}, ImageSize{1280, 720}}) {
    for (const Vec3 direction : {Vec3{0.5, 0.6, 0.62}, Vec3{0.2, 0.1, 0.97}, Vec3{1, 0, 0}, Vec3{-0.3, 0.4, -0.86}}) {
      view.camera.viewDirection = direction;
      for (const int runs : {1, 3}) {
        for (const double time : {0.5, 2.0, 4.0}) {
          SyntheticOptions options;
          options.runs = runs;
          const DrawList list = FrameComposer(view, size).compose(syntheticFrame(time, 120, options));
          for (const PanelDrawing& panel : list.panels) {
            if (!panel.sphere) continue;
            const auto& labels = panel.sphere->labels;
            for (std::size_t i = 0; i < labels.size(); ++i) {
              ++checked;
              EXPECT_TRUE(inside(labels[i], panel.rect)) << size.width << " label " << i;
              for (std::size_t j = i + 1; j < labels.size(); ++j)
                EXPECT_FALSE(intersects(labels[i], labels[j])) << size.width << " labels " << i << ", " << j;
              for (const PixelRect& ball : panel.sphere->balls)
                EXPECT_FALSE(intersects(labels[i], ball)) << size.width << " label " << i << " on a ball";
            }
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 50);
}

// A family on the sphere is explained in the sphere panel when no text panel does it (fan.json).
TEST(DrawList, AFamilyIsCaptionedWithoutATextPanel) {
  ViewSettings view;
  view.panels = {{PanelKind::Sphere, std::nullopt, 0}, {PanelKind::Linkage, std::nullopt, 0}};
  view.camera.viewDirection = {1, 0, 0};  // beside the poles' labels, the panel's glyphs are the caption's alone
  FrameState frame = syntheticFrame(2.0, 120);
  const auto glyphs = [](const DrawList& list) {
    std::size_t count = 0;
    for (const ShapeVertex& v : list.panels[0].shapes.vertices()) count += v.kind == float(ShapeKind::Glyph);
    return count;
  };
  const FrameComposer composer(view, {1280, 720});
  const std::size_t poles = glyphs(composer.compose(frame));
  frame.runs[0].members.resize(3);
  for (MemberFrame& member : frame.runs[0].members) member.current = frame.runs[0].current;
  EXPECT_GT(glyphs(composer.compose(frame)), poles + 6u * 40);  // "large ball: the run; ..." in glyph quads
  view.panels.push_back({PanelKind::Text, std::nullopt, 0});
  EXPECT_LE(glyphs(FrameComposer(view, {1280, 720}).compose(frame)), poles) << "the text panel explains the runs";
}

// A polyline's sections between points the sphere hides wholly are left out; those between points clear of it are
// lit without the per-pixel test (w = -1); the others keep it (w = 1).
TEST(ShapeBatchTest, SectionsKnownHiddenAreLeftOutAndThoseKnownClearSkipTheSphereTest) {
  const auto line = [](std::vector<SphereCover> covers) {
    std::vector<PolylinePoint> points;
    for (std::size_t i = 0; i < covers.size(); ++i)
      points.push_back({{10.0f * float(i), 0}, 0.6f, {0, 0, 1, 1}, {0, 0, 1.014f, 1}, covers[i]});
    ShapeBatch batch;
    batch.polyline(points);
    return batch;
  };
  using C = SphereCover;
  EXPECT_TRUE(line({C::Hidden, C::Hidden, C::Hidden}).vertices().empty());
  const ShapeBatch mixed = line({C::Hidden, C::Hidden, C::PerPixel, C::Clear, C::Clear});
  ASSERT_EQ(mixed.vertices().size(), 3u * 6);  // hidden-hidden left out; hidden-tested, tested-clear, clear-clear
  for (std::size_t v = 0; v < 12; ++v) EXPECT_EQ(mixed.vertices()[v].ww, 1.0f) << v;
  for (std::size_t v = 12; v < 18; ++v) EXPECT_EQ(mixed.vertices()[v].ww, -1.0f) << v;
  ASSERT_EQ(mixed.segments().size(), 1u);
  EXPECT_EQ(mixed.segments()[0].program, ShapeProgram::Lit);  // still lit as every occludable shape
}

// A thin path's points merged where they lie on a straight section: a straight run keeps its ends, an arc keeps
// every dropped point within the tolerance of the section drawn in its place, and a change of colour or of the
// sphere's cover is never merged over.
TEST(ShapeBatchTest, StraightRunsAreMergedWithinTheTolerance) {
  const auto point = [](float x, float y) { return PolylinePoint{{x, y}, 0.6f, {0.2f, 0.4f, 0.8f, 1}, {}}; };
  std::vector<PolylinePoint> line;
  for (int i = 0; i <= 40; ++i) line.push_back(point(1.5f * float(i), 0.5f * float(i)));
  mergeStraightRuns(line, 0.05f);
  ASSERT_EQ(line.size(), 2u);
  EXPECT_EQ(line.back().at.x, 60.0f);

  std::vector<PolylinePoint> arc;
  for (int i = 0; i <= 200; ++i) {
    const float a = 0.01f * float(i);
    arc.push_back(point(100 * std::cos(a), 100 * std::sin(a)));
  }
  const std::vector<PolylinePoint> all = arc;
  mergeStraightRuns(arc, 0.05f);
  EXPECT_LT(arc.size(), all.size() / 3);
  EXPECT_GT(arc.size(), 10u);  // a 100 px arc of 2 rad bends: sections of ~6 px at 0.05 px
  for (const PolylinePoint& p : all) {  // each original point's distance from the nearest section drawn
    float nearest = 1e9f;
    for (std::size_t k = 0; k + 1 < arc.size(); ++k) {
      const P2 a = arc[k].at, b = arc[k + 1].at;
      const float dx = b.x - a.x, dy = b.y - a.y;
      const float u = std::clamp(((p.at.x - a.x) * dx + (p.at.y - a.y) * dy) / (dx * dx + dy * dy), 0.0f, 1.0f);
      nearest = std::min(nearest, std::hypot(p.at.x - a.x - u * dx, p.at.y - a.y - u * dy));
    }
    EXPECT_LE(nearest, 0.0501f);
  }

  std::vector<PolylinePoint> turning = {point(0, 0), point(1.5f, 0), point(3, 0), point(4.5f, 0), point(6, 0)};
  turning[2].color.g = 0.6f;
  turning[3].cover = SphereCover::Clear;
  mergeStraightRuns(turning, 0.05f);
  EXPECT_EQ(turning.size(), 5u);
}

// shaders/lit.frag's hiddenBySphere, in double: how much the unit sphere hides a fragment at `pixel` whose point is
// `world` (not a ball).
double hiddenBySphereAt(const SphereCamera& camera, P2 pixel, Vec3 world, bool antialias) {
  const Vec3 e = camera.eye(), f = camera.forward(), r = camera.right(), u = camera.up();
  const double focal = camera.focal(), dx = pixel.x - camera.centre().x, dy = pixel.y - camera.centre().y;
  Vec3 ray{f.x * focal + r.x * dx - u.x * dy, f.y * focal + r.y * dx - u.y * dy, f.z * focal + r.z * dx - u.z * dy};
  const double n = std::sqrt(ray.x * ray.x + ray.y * ray.y + ray.z * ray.z);
  ray = {ray.x / n, ray.y / n, ray.z / n};
  const double closest = -(ray.x * e.x + ray.y * e.y + ray.z * e.z);
  const double miss2 = e.x * e.x + e.y * e.y + e.z * e.z - closest * closest;
  const double size = closest / focal;
  const double inside = (1.0 - std::sqrt(std::max(miss2, 0.0))) / size;
  const double cover = antialias ? std::clamp(inside + 0.5, 0.0, 1.0) : (inside >= 0 ? 1.0 : 0.0);
  const double nearHit = closest - std::sqrt(std::max(1.0 - miss2, 0.0));
  const double toPoint = std::sqrt((world.x - e.x) * (world.x - e.x) + (world.y - e.y) * (world.y - e.y) +
                                   (world.z - e.z) * (world.z - e.z));
  const double x = std::clamp((toPoint - nearHit + size) / (2 * size), 0.0, 1.0);
  return cover * x * x * (3 - 2 * x);
}

// Every path section drawn without the per-pixel sphere test (w = -1) is one the test would not have touched:
// checked at each corner of its quads (the farthest its fragments reach) by the shader's own formula, for a family
// whose members circle the sphere, at three sizes and two directions; and some sections still keep the test.
TEST(DrawList, PathSectionsDrawnWithoutTheSphereTestAreClearOfTheSphere) {
  FrameState frame = syntheticFrame(9.0, 540);
  frame.runs[0].members.resize(8);
  for (std::size_t m = 0; m < frame.runs[0].members.size(); ++m) {
    MemberFrame& member = frame.runs[0].members[m];
    member.path = m % 2 ? frame.runs[0].path : frame.runs[1].path;
    member.pathTimes = m % 2 ? frame.runs[0].pathTimes : frame.runs[1].pathTimes;
    member.current = m % 2 ? frame.runs[0].current : frame.runs[1].current;
  }
  std::size_t clear = 0, tested = 0;
  for (const ImageSize size : {ImageSize{320, 180}, ImageSize{1280, 720}, ImageSize{3840, 2160}}) {
    for (const Vec3 direction : {Vec3{1, 0, 0}, Vec3{0.3, -1, 0.4}}) {
      ViewSettings view;
      view.panels = {{PanelKind::Sphere, std::nullopt, 0}};
      view.camera.viewDirection = direction;
      const DrawList list = FrameComposer(view, size).compose(frame);
      ASSERT_TRUE(list.panels[0].sphere);
      const SphereCamera& camera = list.panels[0].sphere->camera;
      for (const ShapeVertex& v : list.panels[0].shapes.vertices()) {
        tested += v.ww > 0.5f;
        if (v.ww > -0.5f) continue;
        ++clear;
        EXPECT_EQ(hiddenBySphereAt(camera, {v.x, v.y}, {v.wx, v.wy, v.wz}, list.antialias), 0.0)
            << size.width << " px at (" << v.x << ", " << v.y << ")";
      }
    }
  }
  EXPECT_GT(clear, 1000u);
  EXPECT_GT(tested, 0u);
}

TEST(DrawList, ShapesStayNearTheirPanel) {
  const FrameComposer composer(fourPanels(), {640, 360});
  const DrawList list = composer.compose(syntheticFrame(5.0, 300));
  for (const PanelDrawing& panel : list.panels) {
    // Anti-aliasing fringes reach a few pixels past a shape; the scissor clips to the panel when drawn.
    const float margin = 8;
    for (const ShapeVertex& v : panel.shapes.vertices()) {
      EXPECT_GE(v.x, panel.rect.x - margin);
      EXPECT_LE(v.x, panel.rect.x + panel.rect.width + margin);
      EXPECT_GE(v.y, panel.rect.y - margin);
      EXPECT_LE(v.y, panel.rect.y + panel.rect.height + margin);
    }
  }
}

TEST(DrawList, GlassSphereForTheBallAndAnOrbitIsNotStatic) {
  ViewSettings view = fourPanels();
  view.camera.orbitDegreesPerSecond = 10;
  const FrameComposer composer(view, {320, 180});
  SyntheticOptions ball;
  ball.viewSpace = ViewSpace::Ball;
  const DrawList list = composer.compose(syntheticFrame(4.0, 240, ball));
  EXPECT_FALSE(list.sphereIsStatic);
  EXPECT_EQ(list.viewSpace, ViewSpace::Ball);
  ASSERT_TRUE(list.panels[1].sphere);
  EXPECT_EQ(list.panels[1].sphere->look, SphereLook::Glass);
}

// A frame's draw list depends on that frame alone, never on the frames composed before it: a shard composes a
// frame after other frames than a whole render does (or after none), and must draw the same bytes.
TEST(DrawList, AFramesDrawListDoesNotDependOnTheFramesBeforeIt) {
  const FrameComposer composer(fourPanels(), {320, 180});
  const DrawList a = composer.compose(syntheticFrame(3.0, 180));
  composer.compose(syntheticFrame(5.0, 300));
  const DrawList b = composer.compose(syntheticFrame(3.0, 180));
  ASSERT_EQ(a.panels.size(), b.panels.size());
  for (std::size_t i = 0; i < a.panels.size(); ++i) {
    const auto& va = a.panels[i].shapes.vertices();
    const auto& vb = b.panels[i].shapes.vertices();
    ASSERT_EQ(va.size(), vb.size());
    for (std::size_t k = 0; k < va.size(); ++k) {
      EXPECT_EQ(va[k].x, vb[k].x);
      EXPECT_EQ(va[k].y, vb[k].y);
    }
  }
}

TEST(DrawList, SizeOutsideTheLimitsIsRefusedBeforeAnyGl) {
  EXPECT_THROW(FrameComposer(fourPanels(), {8, 100}), std::invalid_argument);
  EXPECT_THROW(FrameComposer(fourPanels(), {100, 100000}), std::invalid_argument);
}

}  // namespace
}  // namespace sl

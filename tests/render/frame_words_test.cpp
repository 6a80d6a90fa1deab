// The words a frame shows (render/frame_words.hpp): made from the FrameState's kinds and numbers, symbols
// typeset, and a small frame given a shorter form rather than a word cut in the middle.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "fixtures/synthetic_frame.hpp"
#include "render/font_atlas.hpp"
#include "render/frame_composer.hpp"
#include "render/frame_words.hpp"
#include "render/panels.hpp"

namespace sl {
namespace {

const std::string kEllipsis = "\u2026";

std::vector<PlotFrame> everyPlotKind() {
  std::vector<PlotFrame> plots;
  for (const auto& [kind, name] : kPlotKinds) {
    PlotFrame plot;
    plot.kind = kind;
    plot.referenceRun = "reference";
    plots.push_back(plot);
  }
  return plots;
}

// No ASCII stand-ins where the font has the symbol: |J⊥|, E₀, √, π, the minus sign.
TEST(FrameWords, SymbolsAreTypesetNotSpelledInAscii) {
  std::vector<std::string> texts = ellipseCaptions();
  for (const PlotFrame& plot : everyPlotKind())
    for (const std::string& title : plotTitles(plot)) texts.push_back(title);
  for (const SphereColoring coloring : {SphereColoring::Curvature, SphereColoring::Bending})
    for (const std::string& caption : fieldCaptions(coloring)) texts.push_back(caption);
  for (const auto& reason : kStopReasons) texts.push_back(stopMeaningWords(reason.kind));
  for (const std::string& text : texts) {
    for (const char* ascii : {"J_perp", "sqrt", "pi", "phi", "S^", "E0", " - ", "+-"})
      EXPECT_EQ(text.find(ascii), std::string::npos) << "\"" << ascii << "\" in: " << text;
  }
  PlotFrame jacobi;
  jacobi.kind = PlotKind::Jacobi;
  EXPECT_NE(plotTitles(jacobi).front().find("|J\u22a5|"), std::string::npos);
  EXPECT_NE(stopMeaningWords(StopReason::FieldBlowUp).find("t = \u00b1\u03c0/2"), std::string::npos);
}

// Numbers carry a true minus sign, in the value and in its exponent; hyphens inside words stay.
TEST(FrameWords, NumbersCarryATrueMinusSign) {
  EXPECT_EQ(typesetNumber("%g", -0.5), "\u22120.5");
  EXPECT_EQ(typesetNumber("%g", 2.5e-14), "2.5e\u221214");
  EXPECT_EQ(typesetNumber("%g", 3.0), "3");
  RunFrame run;
  run.stopReason = StopReason::RodLength;
  run.stopMeasured = 2e-6;
  run.stopLimit = 1e-6;
  EXPECT_EQ(stopReadingWords(run), "rod-length error 2e\u221206 > limit 1e\u221206");
  run.stopReason = StopReason::PoleFoldBack;
  EXPECT_EQ(stopReadingWords(run), "");
}

// The first form that fits, else the shortest shortened at a word: never a word cut in the middle.
TEST(FrameWords, AFormThatFitsIsChosenBeforeAnyCut) {
  const FrameComposer composer(ViewSettings{}, {320, 180});
  const FontAtlas& font = composer.font();
  const std::vector<std::string> forms = fieldCaptions(SphereColoring::Curvature);
  ASSERT_GE(forms.size(), 2u);
  EXPECT_EQ(fittedForm(font, forms, TextSize::Small, 1e6f), forms.front());
  const float shortest = font.width(forms.back(), TextSize::Small);
  EXPECT_EQ(fittedForm(font, forms, TextSize::Small, shortest), forms.back());
  EXPECT_EQ(fittedForm(font, forms, TextSize::Small, font.width(forms[1], TextSize::Small)), forms[1]);
  EXPECT_LE(font.width(fittedForm(font, forms, TextSize::Small, 0.5f * shortest), TextSize::Small), 0.5f * shortest);
}

// A family's key comes in forms, longest first; a 320x180 frame's sphere panel (about 150 px for the caption) shows a
// whole shorter form on two lines, where the longest was cut at "its 32…" and lost the wavefront's key.
TEST(FrameWords, AFamilyKeyFitsASmallPanelWhole) {
  const FrameComposer composer(ViewSettings{}, {320, 180});
  const FontAtlas& font = composer.font();
  const std::vector<std::string> forms = familyCaptions(32);
  ASSERT_GE(forms.size(), 2u);
  for (const std::string& form : forms) {
    EXPECT_NE(form.find("32 members"), std::string::npos) << form;
    EXPECT_NE(form.find("wavefront"), std::string::npos) << form;
  }
  EXPECT_EQ(fittedWrappedForm(font, forms, TextSize::Small, 1e6f, 1), forms.front());
  const std::string shown = fittedWrappedForm(font, forms, TextSize::Small, 150, 2);
  EXPECT_FALSE(shown.empty());
  EXPECT_NE(shown, forms.front());
}

// A note under a colour bar wraps onto two lines: the longest form that does so with every word whole, then shorter
// ones (the distance's note at 320x180 is "inj. 2.09", not "from / the…"); nothing when none fits.
TEST(FrameWords, AWrappedNoteIsAWholeForm) {
  const FrameComposer composer(ViewSettings{}, {320, 180});
  const FontAtlas& font = composer.font();
  const std::vector<std::string> forms = injectivityNotes(2.0854, true);
  ASSERT_EQ(forms.front(), "from the start; injectivity radius 2.0854");  // as the title gives it
  ASSERT_EQ(forms[1], "from the start; injectivity radius 2.09");
  EXPECT_EQ(fittedWrappedForm(font, forms, TextSize::Small, 1e6f, 1), forms.front());
  const float longest = font.width(forms.front(), TextSize::Small);
  EXPECT_EQ(fittedWrappedForm(font, forms, TextSize::Small, 0.7f * longest, 2), forms.front());  // on two lines
  EXPECT_NE(fittedWrappedForm(font, forms, TextSize::Small, 0.7f * longest, 1), forms.front());
  const float shortest = font.width(forms.back(), TextSize::Small);
  EXPECT_EQ(fittedWrappedForm(font, forms, TextSize::Small, shortest, 2), forms.back());
  EXPECT_EQ(fittedWrappedForm(font, forms, TextSize::Small, 0.5f * shortest, 2), "");
  // "inj." and "2.09" each fit a line, so the shortest form is also found on two narrower lines.
  EXPECT_EQ(fittedWrappedForm(font, forms, TextSize::Small, 0.8f * shortest, 2), forms.back());
}

// The scene's title where it fits, else its short title (scene key short_title), else the shorter of them cut at a word;
// with no short title, the title cut at a word.
TEST(FrameWords, AShortTitleStandsInForATitleThatDoesNotFit) {
  const FrameComposer composer(ViewSettings{}, {320, 180});
  const FontAtlas& font = composer.font();
  FrameState frame;
  frame.title = "Through a pole of the chart: the published method stops, chart switching and chart-free carry on";
  frame.shortTitle = "At a chart pole, the published stops";
  const float whole = font.width(frame.title, TextSize::Normal), brief = font.width(frame.shortTitle, TextSize::Normal);
  EXPECT_EQ(shownTitle(font, frame, TextSize::Normal, whole), frame.title);
  EXPECT_EQ(shownTitle(font, frame, TextSize::Normal, 0.9f * whole), frame.shortTitle);
  EXPECT_EQ(shownTitle(font, frame, TextSize::Normal, brief), frame.shortTitle);
  const std::string cut = shownTitle(font, frame, TextSize::Normal, 0.7f * brief);
  EXPECT_EQ(cut.rfind("At a chart", 0), 0u) << cut;
  EXPECT_NE(cut.find(kEllipsis), std::string::npos) << cut;
  frame.shortTitle.clear();
  const std::string alone = shownTitle(font, frame, TextSize::Normal, 0.9f * whole);
  EXPECT_EQ(alone.rfind("Through a pole", 0), 0u) << alone;
  EXPECT_NE(alone.find(kEllipsis), std::string::npos) << alone;
}

// Every plot kind's title is one of its forms, whole, in a plot panel at every frame size (at 320x180 the full
// titles do not fit: a shorter form is shown, never "relative energy err…").
TEST(FrameWords, PlotTitlesAreWholeFormsAtEverySize) {
  ViewSettings view;
  view.panels = {{PanelKind::Plot, std::array<double, 4>{0.5, 0.55, 0.5, 0.45}, 0}};
  bool shortened = false;
  for (const ImageSize size : {ImageSize{320, 180}, ImageSize{1280, 720}, ImageSize{3840, 2160}}) {
    const FrameComposer composer(view, size);
    const PixelRect rect{0.5f * size.width, 0.55f * size.height, 0.5f * size.width, 0.45f * size.height};
    for (const PlotFrame& plot : everyPlotKind()) {
      FrameState frame;
      frame.plots = {plot};
      const PanelContext context{frame, view, composer.font(), rect, frameUnit(size)};
      const PlotLayout layout = layoutPlot(context, plot);
      const std::vector<std::string> forms = plotTitles(plot);
      EXPECT_NE(std::find(forms.begin(), forms.end(), layout.title), forms.end())
          << layout.title << " at " << size.width << "x" << size.height;
      EXPECT_EQ(layout.title.find(kEllipsis), std::string::npos) << layout.title;
      shortened = shortened || layout.title != forms.front();
    }
  }
  EXPECT_TRUE(shortened) << "no title needed a shorter form: the test cannot tell";
}

// A damaged font file (cut short, zeroed, its glyph index pointing past its glyphs) is refused with the reason, where
// stb_truetype read past the end of the file and crashed the renderer.
TEST(FontAtlas, DamagedFontFilesAreRefusedNotRead) {
  std::ifstream in(kFramesFontPath, std::ios::binary);
  ASSERT_TRUE(in) << kFramesFontPath;
  const std::string font((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::array<float, 3> heights{12, 16, 24};
  EXPECT_NO_THROW(FontAtlas(kFramesFontPath, heights));
  const auto damaged = [&](const std::string& bytes) {
    const std::string path = (std::filesystem::temp_directory_path() / "sl-damaged-font.ttf").string();
    std::ofstream(path, std::ios::binary) << bytes;
    std::string message;
    try {
      FontAtlas atlas(path, heights);
    } catch (const std::runtime_error& error) {
      message = error.what();
    }
    std::filesystem::remove(path);
    return message;
  };
  EXPECT_NE(damaged(font.substr(0, font.size() / 2)).find("is damaged"), std::string::npos);   // cut short
  EXPECT_NE(damaged(std::string(font.size(), '\0')).find("is damaged"), std::string::npos);  // zeroed
  EXPECT_NE(damaged(font.substr(0, 7)).find("is damaged"), std::string::npos);                // a header's start
  EXPECT_NE(damaged("").find("is damaged"), std::string::npos);
}

// A holonomy's caption: Gauss-Bonnet's three figures in the longest forms, the turning in every form, true minus
// signs, each form shorter than the one before.
TEST(FrameWords, HolonomyCaptionsGiveTheThreeFiguresAndShortenInOrder) {
  SphereTransport t;
  t.corners.resize(3);
  t.holonomy = -0.32985;
  t.angleExcess = -0.32985;
  t.enclosedCurvature = -0.32985;
  const std::vector<std::string> forms = transportCaptions(t, 6.0, 6.0);  // at the end: the vector is back
  ASSERT_GE(forms.size(), 3u);
  EXPECT_NE(forms[0].find("angle sum \u2212 \u03c0 = \u22120.330 = \u222bK dA = \u22120.330 = holonomy \u22120.330 rad (\u221218.9\u00b0)"),
            std::string::npos) << forms[0];
  EXPECT_NE(forms[0].find("triangle"), std::string::npos);
  for (std::size_t i = 1; i < forms.size(); ++i) {
    EXPECT_LT(forms[i].size(), forms[i - 1].size()) << forms[i];
    EXPECT_NE(forms[i].find("18.9\u00b0"), std::string::npos) << forms[i];
  }
  t.corners.resize(5);
  EXPECT_NE(transportCaptions(t, 6.0, 6.0)[0].find("5-gon comes back turned: angle sum \u2212 3\u03c0"),
            std::string::npos);
}

// On the way round, the caption says what the sides have swept so far (the holonomy plot's value), not the end.
TEST(FrameWords, HolonomyCaptionOnTheWaySaysTheCurvatureSweptSoFar) {
  SphereTransport t;
  t.samplesPerSide = 2;
  for (std::size_t side = 0; side < 3; ++side) {
    t.corners.push_back({1, 0, 0});
    for (int k = 0; k <= 2; ++k) t.arrows.push_back({{1, 0, 0}, {0, 1, 0}, side, k / 2.0, -0.1 * k});
  }
  t.holonomy = t.angleExcess = t.enclosedCurvature = -0.6;
  const std::vector<std::string> half = transportCaptions(t, 3.0, 6.0);  // each side halfway: 3 x -0.1
  EXPECT_NE(half[0].find("swept so far = \u22120.300 rad"), std::string::npos) << half[0];
  EXPECT_EQ(half[0].find("holonomy"), std::string::npos) << half[0];
  EXPECT_NE(transportCaptions(t, 6.0, 6.0)[0].find("holonomy \u22120.600"), std::string::npos);
}

}  // namespace
}  // namespace sl

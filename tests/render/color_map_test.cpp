// Colour scales and colour bars (render/color_map.hpp), and the sphere panel's decoration, without GL.
#include <gtest/gtest.h>

#include <cmath>

#include "fixtures/synthetic_frame.hpp"
#include "render/color_map.hpp"
#include "render/frame_composer.hpp"
#include "render/frame_words.hpp"
#include "render/palette.hpp"

namespace sl {
namespace {

float lightness(Rgba c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

TEST(ColorScale, DivergingIsCentredAtZeroWithEachSignOnItsOwnRange) {
  const ColorScale scale{-0.25, 4.0, true};
  EXPECT_DOUBLE_EQ(scale.position(0.0), 0.5);
  EXPECT_DOUBLE_EQ(scale.position(-0.25), 0.0);
  EXPECT_DOUBLE_EQ(scale.position(4.0), 1.0);
  EXPECT_DOUBLE_EQ(scale.position(-0.125), 0.25);  // half the negative range: a quarter of the map
  EXPECT_DOUBLE_EQ(scale.position(2.0), 0.75);
  for (double v : {-0.25, -0.1, 0.0, 0.3, 4.0}) EXPECT_NEAR(scale.valueAt(scale.position(v)), v, 1e-12) << v;
  // White in the middle, blue below, red above.
  const Rgba zero = scale.colorAt(0.5), low = scale.colorAt(0.0), high = scale.colorAt(1.0);
  EXPECT_GT(std::min({zero.r, zero.g, zero.b}), 0.95f);
  EXPECT_GT(low.b, low.r + 0.3f);
  EXPECT_GT(high.r, high.b + 0.3f);
  // Positive-only data: the map's lower half is never used.
  const ColorScale positive{0.5, 4.0, true};
  EXPECT_GT(positive.lowest(), 0.5);
  EXPECT_DOUBLE_EQ(positive.highest(), 1.0);
}

TEST(ColorScale, SequentialIsMonotoneInLightness) {
  const ColorScale scale{0.7, 18.4, false};
  EXPECT_DOUBLE_EQ(scale.position(0.7), 0.0);
  EXPECT_DOUBLE_EQ(scale.position(18.4), 1.0);
  EXPECT_DOUBLE_EQ(scale.position(100.0), 1.0);  // clamped
  float previous = -1;
  for (int k = 0; k <= 64; ++k) {
    const float l = lightness(scale.colorAt(k / 64.0));
    EXPECT_GT(l, previous) << k;
    previous = l;
  }
  EXPECT_DOUBLE_EQ(ColorScale({1, 1, false}).position(1), 0.5);  // a constant field: no division by zero
}

TEST(ColorScale, FieldTexelsFollowTheScale) {
  SphereField field;
  field.diverging = true;
  field.phiCount = 2;
  field.tCount = 3;
  field.values = {-1, 0, 2, 2, 0, -1};
  field.min = -1;
  field.max = 2;
  const std::vector<std::uint8_t> texels = fieldTexels(field);
  ASSERT_EQ(texels.size(), 6u * 4);
  EXPECT_GT(texels[2], texels[0]);      // the first value is blue
  EXPECT_GT(texels[8], texels[10]);     // the third is red
  EXPECT_EQ(texels[12], texels[8]);     // equal values, equal colours
  for (int i = 0; i < 6; ++i) EXPECT_EQ(texels[4 * i + 3], 255);
}

// Every shape of a colour bar lies inside its area, and the label and ticks are drawn (glyphs exist).
// Ticks as matplotlib's MaxNLocator picks them (values checked by hand against matplotlib 3.6:
// MaxNLocator(nbins, steps=[1, 2, 2.5, 5, 10]) on the same ranges), labelled with a true minus sign.
TEST(ColorBar, TicksAreRoundValuesWithATrueMinus) {
  EXPECT_EQ(niceTicks(0, 4.15, 4), (std::vector<double>{0, 2, 4}));
  EXPECT_EQ(niceTicks(0, 4.15, 5), (std::vector<double>{0, 1, 2, 3, 4}));
  EXPECT_EQ(niceTicks(-0.27, 0, 3), (std::vector<double>{-0.2, -0.1, 0}));
  EXPECT_EQ(niceTicks(0.013, 0.087, 4).size(), 4u);  // 0.02 0.04 0.06 0.08
  EXPECT_NEAR(niceTicks(0.013, 0.087, 4)[0], 0.02, 1e-12);
  EXPECT_TRUE(niceTicks(1, 1, 4).empty());
  for (int maxTicks = 1; maxTicks <= 8; ++maxTicks) {
    const std::vector<double> ticks = niceTicks(-3.7, 12.9, maxTicks);
    EXPECT_LE(int(ticks.size()), maxTicks);
    EXPECT_GE(ticks.size(), 1u);
    for (double t : ticks) EXPECT_TRUE(t >= -3.7 && t <= 12.9);
  }
  EXPECT_EQ(tickLabel(-0.25, 0.25), "\u22120.25");
  EXPECT_EQ(tickLabel(-0.2, 0.1), "\u22120.2");
  EXPECT_EQ(tickLabel(20, 10), "20");
  EXPECT_EQ(tickLabel(2.5, 2.5), "2.5");
  EXPECT_EQ(tickLabel(-1e-17, 0.1), "0.0");  // roundoff about zero is not negative
  EXPECT_EQ(tickLabel(0, 1), "0");
}

// The bar is a smooth ramp at every size: one band per pixel row, no steps of several rows.
TEST(ColorBar, HasNoBanding) {
  const FrameComposer composer(ViewSettings{}, {3840, 2160});
  const PixelRect area{100, 100, 300, 1600};
  ShapeBatch batch;
  drawColorBar({0, 1, false}, "bending", "", area, composer.font(), palette::kLightPage, batch);
  std::size_t bands = 0;
  for (const ShapeVertex& v : batch.vertices()) bands += v.kind == float(ShapeKind::Rect);
  EXPECT_GT(bands / 6, 1200u);  // two triangles (6 vertices) a rect: at least one per row of the bar's ~1400
}

TEST(ColorBar, StaysInsideItsArea) {
  const FrameComposer composer(ViewSettings{}, {640, 360});
  ShapeBatch batch;
  const PixelRect area{500, 20, 120, 300};
  drawColorBar({-0.27, 4.15, true}, "Gaussian curvature K", "each sign on its own scale", area, composer.font(),
               palette::kLightPage, batch);
  ASSERT_GT(batch.vertices().size(), 96u * 6);
  for (const ShapeVertex& v : batch.vertices()) {
    EXPECT_GE(v.x, area.x - 1);
    EXPECT_LE(v.x, area.x + area.width + 2);
    EXPECT_GE(v.y, area.y - 1);
    EXPECT_LE(v.y, area.y + area.height + 1);
  }
  // In a strip narrower than its label and note (small frames), both are shortened, never cut by the panel.
  ShapeBatch narrow;
  const PixelRect strip{580, 20, 50, 300};
  drawColorBar({-0.27, 4.15, true}, "K, Gaussian curvature", "each sign on its own scale", strip, composer.font(),
               palette::kLightPage, narrow);
  ASSERT_GT(narrow.vertices().size(), 96u * 6);
  for (const ShapeVertex& v : narrow.vertices()) {
    EXPECT_GE(v.x, strip.x - 1);
    EXPECT_LE(v.x, strip.x + strip.width + 2);
  }
  // Too small to read: nothing rather than an illegible bar.
  ShapeBatch tiny;
  drawColorBar({-1, 1, true}, "K", "", {0, 0, 40, 30}, composer.font(), palette::kLightPage, tiny);
  EXPECT_TRUE(tiny.vertices().empty());
}

// A two-slope scale says where its slope changes, at the break: the zero tick's label reads "scale changes at 0"
// (soft ink before the number) where the strip has room, and the note under the bar is left out then; a narrow strip
// keeps "0" and the note. A one-slope scale has neither.
TEST(ColorBar, ATwoSlopeScaleIsNotedAtItsBreak) {
  const FrameComposer composer(ViewSettings{}, {1280, 720});
  const FontAtlas& font = composer.font();
  const auto softGlyphs = [](const ShapeBatch& batch) {
    std::size_t count = 0;
    for (const ShapeVertex& v : batch.vertices())
      count += v.kind == float(ShapeKind::Glyph) && v.r == palette::softInk.r && v.g == palette::softInk.g;
    return count;
  };
  const auto glyphsOf = [&](const std::string& text) {
    ShapeBatch alone;
    font.draw(alone, text, TextSize::Small, 0, 20, palette::softInk);
    return alone.vertices().size();
  };
  const std::string note = "each sign on its own scale";
  ShapeBatch wide;
  drawColorBar({-0.27, 4.15, true}, "K", note, {900, 40, 200, 560}, font, palette::kLightPage, wide);
  EXPECT_EQ(softGlyphs(wide), glyphsOf(scaleBreakWords().front() + " "));
  ShapeBatch narrow;
  drawColorBar({-0.27, 4.15, true}, "K", note, {900, 40, 60, 560}, font, palette::kLightPage, narrow);
  EXPECT_GT(softGlyphs(narrow), 0u) << "the note under the bar";
  ShapeBatch narrowWithoutNote;
  drawColorBar({-0.27, 4.15, true}, "K", "", {900, 40, 60, 560}, font, palette::kLightPage, narrowWithoutNote);
  EXPECT_EQ(softGlyphs(narrowWithoutNote), 0u) << "break words squeezed into a narrow strip";
  ShapeBatch oneSlope;
  drawColorBar({0, 4.15, false}, "K", "", {900, 40, 200, 560}, font, palette::kLightPage, oneSlope);
  EXPECT_EQ(softGlyphs(oneSlope), 0u);
}

// A decorated frame: the sphere is coloured, framed left of the colour bar, and ellipses are drawn.
TEST(SpherePanel, DecorationColoursTheSphereAndMakesRoomForTheBar) {
  ViewSettings settings;
  settings.panels = {{PanelKind::Sphere, std::nullopt, 0}};
  const FrameComposer composer(settings, {640, 360});
  FrameState frame = syntheticFrame(1.0, 30);
  const DrawList plain = composer.compose(frame);
  ASSERT_TRUE(plain.panels[0].sphere);
  EXPECT_EQ(plain.panels[0].sphere->look, SphereLook::Opaque);

  auto decoration = std::make_shared<SphereDecoration>();
  decoration->field = SphereField{SphereColoring::Curvature, true, 2, 4, std::vector<float>(8, 1.0f), -1.0, 1.0};
  decoration->ellipses.push_back({{0.6, 0.4, 0.7}, {0.0, 0.05, 0.0}, {0.02, 0.0, 0.0}});
  frame.sphereDecoration = decoration;
  const DrawList colored = composer.compose(frame);
  ASSERT_TRUE(colored.panels[0].sphere);
  EXPECT_EQ(colored.panels[0].sphere->look, SphereLook::Colored);
  EXPECT_EQ(colored.sphereDecoration.get(), decoration.get());
  EXPECT_LT(colored.panels[0].sphere->camera.centre().x, plain.panels[0].sphere->camera.centre().x);
  EXPECT_GT(colored.panels[0].shapes.vertices().size(), plain.panels[0].shapes.vertices().size() + 96 * 6);

  // 5+ rods: a decoration is never drawn into the ball view.
  frame.viewSpace = ViewSpace::Ball;
  EXPECT_EQ(composer.compose(frame).panels[0].sphere->look, SphereLook::Glass);
}

}  // namespace
}  // namespace sl

namespace sl {
namespace {

// Titles and captions give way rather than overflow: cut after a whole word (at a code point in a single word),
// with an ellipsis, within the width.
TEST(FontAtlas, FittedTextStaysWithinItsWidth) {
  const FrameComposer composer(ViewSettings{}, {640, 360});
  const FontAtlas& font = composer.font();
  const std::string title = "divergence from christoffel (published): max hinge distance";
  EXPECT_EQ(font.fitted(title, TextSize::Normal, 1e6), title);
  const float whole = font.width(title, TextSize::Normal);
  for (float width : {0.8f * whole, 0.4f * whole, 40.0f}) {
    const std::string cut = font.fitted(title, TextSize::Normal, width);
    EXPECT_LE(font.width(cut, TextSize::Normal), width);
    EXPECT_EQ(cut.substr(cut.size() - 3), "\u2026");
    EXPECT_EQ(cut.rfind(title.substr(0, cut.size() - 3), 0), 0u) << cut;
    // Whole words: the kept text ends where a word of the title ends (a single word is cut at a code point).
    const std::size_t kept = cut.size() - 3;
    if (cut.find(' ') != std::string::npos) {
      EXPECT_TRUE(kept < title.size() && (title[kept] == ' ' || title[kept] == ')')) << cut;
    }
  }
  EXPECT_EQ(font.fitted("K, Gaussian curvature", TextSize::Normal, font.width("K, Gau\u2026", TextSize::Normal)),
            "K\u2026");
  EXPECT_EQ(font.fitted("\u03c6 = \u03c0/2 and more", TextSize::Normal, 1.0f), "");
  const std::string greek = font.fitted("\u03c6\u03c6\u03c6\u03c6\u03c6\u03c6\u03c6\u03c6", TextSize::Normal, 40.0f);
  EXPECT_EQ(decodeUtf8(greek).back(), 0x2026u);  // never half a code point
  for (std::uint32_t cp : decodeUtf8(greek)) EXPECT_NE(cp, 0xFFFDu);
}

// The symbols the labels use are in the atlas, not drawn as the replacement character: S³, π, φ, |J⊥|, √, −.
TEST(FontAtlas, BakesTheLabelSymbols) {
  const FrameComposer composer(ViewSettings{}, {1280, 720});
  const FontAtlas& font = composer.font();
  const auto quad = [&](const std::string& text) {
    ShapeBatch batch;
    font.draw(batch, text, TextSize::Normal, 10, 40, {0, 0, 0, 1});
    std::vector<float> texture;
    for (const ShapeVertex& v : batch.vertices()) texture.insert(texture.end(), {v.localX, v.localY});
    return texture;
  };
  const std::vector<float> replacement = quad("\ufffd");
  ASSERT_FALSE(replacement.empty());
  for (const char* symbol : {"\u00b3", "\u03c0", "\u03c6", "\u22a5", "\u221a", "\u2212", "\u2080", "\u00b1"}) {
    const std::vector<float> drawn = quad(symbol);
    EXPECT_FALSE(drawn.empty()) << symbol;
    EXPECT_NE(drawn, replacement) << symbol;
  }
}

// Notes wrap by words into the lines allowed, each within the width; what does not fit ends in an ellipsis.
TEST(FontAtlas, WrappedTextKeepsItsWordsWithinTheWidth) {
  const FrameComposer composer(ViewSettings{}, {640, 360});
  const FontAtlas& font = composer.font();
  const std::string note = "nothing to plot: \"published\" stopped at t = 0 (field-blow-up)";
  const float width = 0.45f * font.width(note, TextSize::Small);
  const std::vector<std::string> three = font.wrapped(note, TextSize::Small, width, 3);
  ASSERT_EQ(three.size(), 3u);
  std::string joined;
  for (const std::string& line : three) {
    EXPECT_LE(font.width(line, TextSize::Small), width) << line;
    joined += (joined.empty() ? "" : " ") + line;
  }
  EXPECT_EQ(joined, note);  // every word, in order, none cut
  const std::vector<std::string> two = font.wrapped(note, TextSize::Small, width, 2);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[1].substr(two[1].size() - 3), "\u2026");
  EXPECT_EQ(font.wrapped(note, TextSize::Small, 1e6, 2), std::vector<std::string>{note});
  EXPECT_TRUE(font.wrapped("", TextSize::Small, width, 2).empty());
}

}  // namespace
}  // namespace sl

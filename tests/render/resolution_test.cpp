// The same picture at every size: a 3840x2160 frame box-downscaled (3x3 pixels to one) to 1280x720 matches the
// 1280x720 frame. Line widths, markers, glyphs and gaps are defined per 720 px of the frame's shorter side
// (frameUnit), and panel edges and text baselines lie on whole pixels of 720p's scale (3 pixels at 4K), so only
// anti-aliasing and glyph rasterisation may differ.
//
// Measure: among the pixels drawn in either frame (not the background colour), the fraction whose largest channel
// difference exceeds 48 levels. Thresholds: 0.2% for the synthetic 4-rod frames (sphere, ball, linkage, plots, text),
// 1% for a 200-rod rope whose hairline chain is almost all edge. Measured: 0.00% and 0.43%; with panel edges and
// baselines on the 4K frame's own pixels: 0.6-0.8% and 7.1%; before sizes were in frame units: 0.85-1.35% and 70.6%
// (the rope a chain of beads at 4K). Every shipped scene: tests/cli/shipped_frames_test.cpp.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "fixtures/image_compare.hpp"
#include "fixtures/synthetic_frame.hpp"
#include "reference_frames.hpp"
#include "render/draw_list.hpp"
#include "render/frame_composer.hpp"
#include "render/sphere_grid.hpp"
#include "render/renderer.hpp"

namespace sl {
namespace {

constexpr int kLevels = 48;
constexpr double kMaxDifferingFraction = 0.002, kMaxDifferingFractionHairline = 0.01;

struct Case {
  const char* name;
  FrameState frame;
  ViewSettings settings;
  double maxDiffering = kMaxDifferingFraction;
};

// A rope: 200 rods hanging in a V between pins 150 apart, in the linkage panel alone (shipped rope.json's look).
Case rope() {
  FrameState frame = syntheticFrame(2.0, 120);
  frame.rods = 200;
  frame.runs.resize(1);
  RunFrame& run = frame.runs[0];
  run.baseLength = 150;
  run.hinges.clear();
  run.trails.clear();
  const double down = std::sqrt(1 - 0.75 * 0.75);
  for (int k = 1; k < 200; ++k) {
    const int along = k <= 100 ? k : 200 - k;
    run.hinges.push_back({0.75 * k, -down * along});
  }
  ViewSettings settings;
  settings.panels = {{PanelKind::Linkage, std::nullopt, 0}};
  return {"rope_linkage", frame, settings, kMaxDifferingFractionHairline};
}

std::vector<Case> cases() {
  SyntheticOptions stopping;
  stopping.stopSecondRun = true;
  SyntheticOptions ball;
  ball.viewSpace = ViewSpace::Ball;
  ViewSettings automatic;  // the default layout: sphere, linkage, text band
  ViewSettings overlay = testing::smallSettings();
  overlay.linkageLayout = LinkageLayout::Overlay;
  // Three runs seen from below: hidden sections (dashes), hidden states (rings), start bars, arrowheads, both poles'
  // labels and the seams with their label.
  SyntheticOptions three;
  three.runs = 3;
  FrameState farSide = syntheticFrame(5.0, 300, three);
  auto seams = std::make_shared<SphereDecoration>();
  seams->seam = true;
  farSide.sphereDecoration = seams;
  ViewSettings below = testing::smallSettings();
  below.camera.viewDirection = {-0.5, 0.5, -0.7};
  return {{"panels_sphere", syntheticFrame(2.0, 120), testing::smallSettings()},
          {"far_side_marks_labels", farSide, below},
          {"default_layout_stopped", syntheticFrame(7.0, 420, stopping), automatic},
          {"ball_overlay", syntheticFrame(4.0, 240, ball), overlay},
          rope()};
}

TEST(ResolutionIndependence, FourKDownscaledMatches720p) {
  for (const Case& c : cases()) {
    Renderer small(c.settings, {1280, 720});
    const Image reference = small.render(c.frame);
    Image big;
    {
      Renderer large(c.settings, {3840, 2160});
      big = large.render(c.frame);
    }
    const double fraction = testing::differingFraction(testing::boxDownscale3(big), reference, c.settings.background, kLevels);
    std::printf("%s: %.2f%% of drawn pixels differ by more than %d levels\n", c.name, 100 * fraction, kLevels);
    EXPECT_LT(fraction, c.maxDiffering) << c.name;
  }
}

// The sphere's chart grid at every size: the same share of the ball, neither a net at 320x180 nor vanishing at 4K.
// Measure: the mean colour (sum of channels) of the ball's central disc (half its radius; the pole labels and the
// limb lie outside it), seen along the equator with no runs drawn, so the disc shows the lit ball and its grid only.
// A box downscale keeps a region's mean, so this is the downscaled frames' measure too. Measured when the test was
// written: 562.0, 562.4 and 562.4 at 320x180, 1280x720 and 3840x2160; without the grid 567.6 at every size (the grid
// darkens the disc by 5.3 levels in the sum); with lines one pixel wide at every size (as before line widths were in
// frame units) 548.2, 562.9 and 566.0, so a net at 320x180 and a fading grid at 4K each fail. Threshold: 1.5 levels
// in the sum of the three channels.
double centralDiscMean(const Image& image, double centreX, double centreY, double radius) {
  double sum = 0;
  std::size_t count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double dx = x + 0.5 - centreX, dy = y + 0.5 - centreY;
      if (dx * dx + dy * dy > radius * radius) continue;
      const std::size_t i = (std::size_t(y) * image.width + x) * 3;
      sum += image.rgb[i] + image.rgb[i + 1] + image.rgb[i + 2];
      ++count;
    }
  return count ? sum / double(count) : 0;
}

TEST(ResolutionIndependence, SphereGridCoversTheSameShareOfTheBallAtEverySize) {
  SyntheticOptions none;
  none.runs = 0;
  const FrameState frame = syntheticFrame(2.0, 120, none);
  ViewSettings settings;
  settings.panels = {{PanelKind::Sphere, std::nullopt, 0}};
  settings.camera.viewDirection = {1, 0.3, 0};  // along the equator: the poles at the top and bottom limbs
  double means[3] = {0, 0, 0};
  double darkest[3] = {0, 0, 0};  // the disc's largest drop below its neighbour 2 frame units away, levels
  const ImageSize sizes[3] = {{320, 180}, {1280, 720}, {3840, 2160}};
  for (int k = 0; k < 3; ++k) {
    Renderer renderer(settings, sizes[k]);
    const Image image = renderer.render(frame);
    // Where the ball is: its camera's centre and outline (the title band takes more of a small frame).
    const DrawList list = FrameComposer(settings, sizes[k]).compose(frame);
    ASSERT_TRUE(list.panels.at(0).sphere.has_value());
    const SphereCamera& camera = list.panels[0].sphere->camera;
    const double cx = camera.centre().x, cy = camera.centre().y, radius = sphereOutlinePixels(camera);
    means[k] = centralDiscMean(image, cx, cy, 0.5 * radius);
    const int step = std::max(1, int(std::lround(2 * frameUnit(sizes[k]))));
    for (int y = int(cy - 0.5 * radius); y < int(cy + 0.5 * radius); ++y)
      for (int x = int(cx - 0.5 * radius); x + step < int(cx + 0.5 * radius); ++x) {
        const std::size_t i = (std::size_t(y) * image.width + x) * 3, j = i + std::size_t(step) * 3;
        darkest[k] = std::max(darkest[k], double(image.rgb[j + 1]) - double(image.rgb[i + 1]));
      }
    std::printf("%dx%d: central disc mean %.2f (sum of channels), deepest grid line %.0f levels\n", sizes[k].width,
                sizes[k].height, means[k], darkest[k]);
  }
  EXPECT_NEAR(means[0], means[1], 1.5) << "320x180 against 1280x720";
  EXPECT_NEAR(means[2], means[1], 1.5) << "3840x2160 against 1280x720";
  // The lines are there at every size: sub-pixel and faint at 320x180, but visible.
  for (int k = 0; k < 3; ++k) EXPECT_GT(darkest[k], 8.0) << sizes[k].width << "x" << sizes[k].height;
}

}  // namespace
}  // namespace sl

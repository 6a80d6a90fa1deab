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

}  // namespace
}  // namespace sl

// The same FrameState gives the same bytes, whatever was rendered before, with a fixed camera (cached
// sphere layer) and an orbiting one (sphere redrawn every frame).

#include <gtest/gtest.h>

#include "fixtures/synthetic_frame.hpp"
#include "reference_frames.hpp"

namespace sl {
namespace {

TEST(Determinism, SameFrameTwiceGivesSameBytes) {
  Renderer renderer(testing::smallSettings(), testing::kSmallSize);
  const FrameState frame = syntheticFrame(2.5, 150);
  const Image first = renderer.render(frame);
  const Image second = renderer.render(frame);
  EXPECT_EQ(first.rgb, second.rgb);
}

TEST(Determinism, FrameAloneEqualsFrameInSequence) {
  for (double orbit : {0.0, 20.0}) {
    ViewSettings settings = testing::smallSettings();
    settings.camera.orbitDegreesPerSecond = orbit;
    const FrameState target = syntheticFrame(5.0, 300);
    Renderer sequence(settings, testing::kSmallSize);
    for (double t : {0.5, 1.5, 3.0}) sequence.render(syntheticFrame(t, int(t * 60)));
    SyntheticOptions ball;
    ball.viewSpace = ViewSpace::Ball;  // a different sphere look in between
    sequence.render(syntheticFrame(4.0, 240, ball));
    const Image inSequence = sequence.render(target);
    Renderer alone(settings, testing::kSmallSize);
    EXPECT_EQ(alone.render(target).rgb, inSequence.rgb) << "orbit " << orbit;
  }
}

TEST(Determinism, OrbitingCameraMovesTheSphere) {
  ViewSettings settings = testing::smallSettings();
  settings.camera.orbitDegreesPerSecond = 30;
  Renderer renderer(settings, testing::kSmallSize);
  FrameState frame = syntheticFrame(2.0, 120);
  const Image before = renderer.render(frame);
  frame.time = 3.0;  // same paths, camera 30 degrees further round
  EXPECT_NE(renderer.render(frame).rgb, before.rgb);
}

}  // namespace
}  // namespace sl

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
  // One frame, two cameras that differ only in their orbit: the time (and so every label) is the same, so
  // the pixels can differ only through the camera. The orbit turns the sphere by 30 * 3 = 90 degrees.
  const FrameState frame = syntheticFrame(3.0, 180);
  ViewSettings fixed = testing::smallSettings();
  fixed.camera.orbitDegreesPerSecond = 0;
  ViewSettings orbiting = fixed;
  orbiting.camera.orbitDegreesPerSecond = 30;
  const Image still = Renderer(fixed, testing::kSmallSize).render(frame);
  EXPECT_EQ(Renderer(fixed, testing::kSmallSize).render(frame).rgb, still.rgb);  // the comparison can hold
  EXPECT_NE(Renderer(orbiting, testing::kSmallSize).render(frame).rgb, still.rgb);
}

}  // namespace
}  // namespace sl

// The same FrameState gives the same bytes, whatever was rendered before, with a fixed camera (cached
// sphere layer), an orbiting one (sphere redrawn every frame) and a directed one (redrawn when it turns).

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

// The render loop draws into buffers the sinks gave back (ImageRecycler): every byte of the stale frame is
// overwritten, whatever size the buffer had.
TEST(Determinism, RenderingIntoAStaleBufferEqualsAFreshRender) {
  Renderer renderer(testing::smallSettings(), testing::kSmallSize);
  const FrameState frame = syntheticFrame(2.5, 150);
  const Image fresh = renderer.render(frame);
  Image stale = renderer.render(syntheticFrame(4.0, 240));
  ASSERT_NE(stale.rgb, fresh.rgb);  // the comparison can fail
  renderer.render(frame, stale);
  EXPECT_EQ(stale.rgb, fresh.rgb);
  Image wrongSize{7, 3, std::vector<std::uint8_t>(63, 200)};
  renderer.render(frame, wrongSize);
  EXPECT_EQ(wrongSize.width, fresh.width);
  EXPECT_EQ(wrongSize.height, fresh.height);
  EXPECT_EQ(wrongSize.rgb, fresh.rgb);
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

// Each sphere look has its own program: with a moving camera (the sphere shaded every frame), a frame of each look
// rendered after the other looks equals the same frame rendered fresh, bit for bit.
TEST(Determinism, EveryLookAfterTheOthersEqualsAFreshRender) {
  ViewSettings settings = testing::smallSettings();
  settings.camera.orbitDegreesPerSecond = 20;
  SphereField field{SphereColoring::Curvature, true, 16, 32, {}, -1.0, 2.0};
  for (int i = 0; i < field.phiCount * field.tCount; ++i) field.values.push_back(float(-1.0 + 3.0 * (i % 7) / 6.0));
  auto decoration = std::make_shared<SphereDecoration>();
  decoration->field = field;
  auto frameOf = [&](ViewSpace space, bool colored, double t) {
    SyntheticOptions options;
    options.viewSpace = space;
    FrameState frame = syntheticFrame(t, int(t * 60), options);
    if (colored) frame.sphereDecoration = decoration;
    return frame;
  };
  const FrameState opaque = frameOf(ViewSpace::Sphere, false, 2.0), glass = frameOf(ViewSpace::Ball, false, 2.0),
                   colored = frameOf(ViewSpace::Sphere, true, 2.0);
  Renderer sequence(settings, testing::kSmallSize);
  for (double t : {0.5, 1.0, 1.5}) {
    sequence.render(frameOf(ViewSpace::Sphere, true, t));
    sequence.render(frameOf(ViewSpace::Ball, false, t));
    sequence.render(frameOf(ViewSpace::Sphere, false, t));
  }
  std::vector<Image> inSequence;
  for (const FrameState* frame : {&colored, &glass, &opaque}) inSequence.push_back(sequence.render(*frame));
  // A renderer's context is current on its thread only while it is the newest: render fresh ones one at a time.
  std::vector<Image> fresh;
  for (const FrameState* frame : {&colored, &glass, &opaque})
    fresh.push_back(Renderer(settings, testing::kSmallSize).render(*frame));
  for (std::size_t k = 0; k < fresh.size(); ++k) EXPECT_EQ(fresh[k].rgb, inSequence[k].rgb) << "look " << k;
  // The comparison can fail: the looks are different pictures.
  EXPECT_NE(fresh[0].rgb, fresh[2].rgb);
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

// A directed camera (FrameState::cameraDirection): the renderer draws the sphere straight into a frame whose
// direction differs from its last frame's, caches it in a layer once the direction stays and keeps that layer only
// while the direction stays, so a frame gives the same bytes whichever directions came before it and whichever way
// it was drawn, and the direction does move the sphere (the frame's direction wins over the scene's, orbit included).
TEST(Determinism, DirectedCameraRedrawsTheCachedSphereWhenItTurns) {
  ViewSettings settings = testing::smallSettings();
  settings.camera.orbitDegreesPerSecond = 30;  // ignored: the frame carries its camera
  FrameState target = syntheticFrame(3.0, 180);
  target.cameraDirection = Vec3{0.2, -0.9, 0.4};
  Renderer sequence(settings, testing::kSmallSize);
  for (const Vec3& direction : {Vec3{1, 0, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0.3}}) {
    FrameState other = target;
    other.cameraDirection = direction;
    sequence.render(other);
  }
  const Image inSequence = sequence.render(target);        // straight into the frame: the camera turned
  EXPECT_EQ(sequence.render(target).rgb, inSequence.rgb);  // at rest: drawn into the layer, then copied
  EXPECT_EQ(sequence.render(target).rgb, inSequence.rgb);  // the cached layer copied
  EXPECT_EQ(Renderer(settings, testing::kSmallSize).render(target).rgb, inSequence.rgb);
  FrameState turned = target;
  turned.cameraDirection = Vec3{-0.2, 0.9, 0.4};
  EXPECT_NE(Renderer(settings, testing::kSmallSize).render(turned).rgb, inSequence.rgb);
  ViewSettings fixed = settings;
  fixed.camera.orbitDegreesPerSecond = 0;
  EXPECT_EQ(Renderer(fixed, testing::kSmallSize).render(target).rgb, inSequence.rgb);
}

// A frame whose first panel is the sphere gets its background from the sphere's layer copied whole, not from a
// clear (renderer.cpp, copyLayer): the same bytes as the same panels drawn after another panel cleared the frame,
// for a turning camera (the ball's layer, the grid over it), one at rest (the cached sphere) and the glass ball.
TEST(Determinism, ASpherePanelDrawnFirstGivesTheBytesOfTheClearedFrame) {
  for (double orbit : {0.0, 20.0}) {
    for (ViewSpace space : {ViewSpace::Sphere, ViewSpace::Ball}) {
      ViewSettings textFirst = testing::smallSettings();
      textFirst.camera.orbitDegreesPerSecond = orbit;
      ViewSettings sphereFirst = textFirst;
      ASSERT_EQ(sphereFirst.panels[1].kind, PanelKind::Sphere);
      std::swap(sphereFirst.panels[0], sphereFirst.panels[1]);
      SyntheticOptions options;
      options.viewSpace = space;
      // Turning (a renderer's first frame), at rest, and a later frame. A renderer's context is current on its
      // thread only while it is the newest: one renderer after the other.
      const auto frames = [&](const ViewSettings& settings) {
        Renderer renderer(settings, testing::kSmallSize);
        std::vector<Image> images;
        for (double t : {2.0, 2.0, 3.0}) images.push_back(renderer.render(syntheticFrame(t, int(t * 60), options)));
        return images;
      };
      const std::vector<Image> layered = frames(sphereFirst), cleared = frames(textFirst);
      for (std::size_t k = 0; k < cleared.size(); ++k)
        EXPECT_EQ(layered[k].rgb, cleared[k].rgb) << "orbit " << orbit << ", frame " << k;
    }
  }
}

}  // namespace
}  // namespace sl

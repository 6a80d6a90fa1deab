// Several renderers side by side (RendererPool): frames come back in the order given, each byte for byte what one
// renderer alone draws, whichever of the pool's renderers drew it; a renderer that cannot be made is an error of
// the pool's constructor; the pool never holds more frames than its capacity.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "fixtures/synthetic_frame.hpp"
#include "reference_frames.hpp"
#include "render/renderer_pool.hpp"

namespace sl {
namespace {

// Frames that differ from each other, with a turning camera (the sphere shaded anew in every frame) and a fixed one
// (its layer cached by whichever renderer draws first).
std::vector<FrameState> distinctFrames() {
  std::vector<FrameState> frames;
  for (int k = 0; k < 7; ++k) frames.push_back(syntheticFrame(0.4 + 0.7 * k, 30 + 40 * k));
  return frames;
}

TEST(RendererPool, FramesComeBackInTheOrderGivenEqualToOneRenderersFrames) {
  for (double orbit : {0.0, 20.0}) {
    ViewSettings settings = testing::smallSettings();
    settings.camera.orbitDegreesPerSecond = orbit;
    const std::vector<FrameState> frames = distinctFrames();
    std::vector<Image> alone;
    {
      Renderer renderer(settings, testing::kSmallSize);
      for (const FrameState& frame : frames) alone.push_back(renderer.render(frame));
    }
    ASSERT_NE(alone[0].rgb, alone[1].rgb);  // the comparison below can fail
    RendererPool pool(settings, testing::kSmallSize, "", 3);
    ASSERT_EQ(pool.renderers(), 3);
    EXPECT_FALSE(pool.glRenderer().empty());
    std::vector<Image> pooled;
    for (const FrameState& frame : frames) {
      if (pool.inFlight() == pool.capacity()) pooled.push_back(pool.takeOldest());
      pool.submit(frame, pooled.empty() ? Image{} : Image{5, 5, std::vector<std::uint8_t>(75, 9)});
    }
    while (pool.inFlight() > 0) pooled.push_back(pool.takeOldest());
    ASSERT_EQ(pooled.size(), alone.size());
    for (std::size_t k = 0; k < frames.size(); ++k)
      EXPECT_EQ(pooled[k].rgb, alone[k].rgb) << "frame " << k << ", orbit " << orbit;
  }
}

TEST(RendererPool, ARendererThatCannotBeMadeIsTheConstructorsError) {
  try {
    RendererPool pool(testing::smallSettings(), testing::kSmallSize, "/nonexistent/shaders", 2);
    FAIL() << "a pool without shaders was made";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/shaders/"), std::string::npos) << e.what();
  }
  EXPECT_THROW(RendererPool(testing::smallSettings(), {0, 100}, "", 2), std::invalid_argument);
}

TEST(RendererPool, HoldsNoMoreFramesThanItsCapacity) {
  RendererPool pool(testing::smallSettings(), testing::kSmallSize, "", 1);
  EXPECT_THROW(pool.takeOldest(), std::logic_error);
  EXPECT_EQ(pool.capacity(), 2);
  const FrameState frame = syntheticFrame(2.5, 150);
  pool.submit(frame);
  pool.submit(frame);
  EXPECT_THROW(pool.submit(frame), std::logic_error);
  EXPECT_EQ(pool.takeOldest().rgb, pool.takeOldest().rgb);
  EXPECT_EQ(pool.inFlight(), 0);
}

// Frames come back in the order they were submitted, whichever renderer drew them (a pool of two against one
// drawing them one by one), and frames left in flight when a pool ends (an interrupted render) are dropped without
// waiting for anyone: a hang here is the test's time limit.
TEST(RendererPool, ReturnsFramesInOrderAndEndsWithFramesStillInFlight) {
  const FrameState early = syntheticFrame(1.0, 60), late = syntheticFrame(2.0, 120);
  RendererPool single(testing::smallSettings(), testing::kSmallSize, "", 1);
  single.submit(early);
  const std::vector<std::uint8_t> earlyPixels = single.takeOldest().rgb;
  single.submit(late);
  const std::vector<std::uint8_t> latePixels = single.takeOldest().rgb;
  ASSERT_NE(earlyPixels, latePixels);
  RendererPool pool(testing::smallSettings(), testing::kSmallSize, "", 2);
  pool.submit(early);
  pool.submit(late);
  EXPECT_EQ(pool.takeOldest().rgb, earlyPixels);
  pool.submit(early);  // two left in flight as the pool ends
}

}  // namespace
}  // namespace sl

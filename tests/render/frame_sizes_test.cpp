// Every frame size the scene format allows renders, landscape, portrait and extreme: text and the glyph atlas
// scale with the frame (the atlas grows past 1024 px for frames taller than about 1250 px).

#include <gtest/gtest.h>

#include <set>

#include "fixtures/synthetic_frame.hpp"
#include "reference_frames.hpp"
#include "render/renderer.hpp"

namespace sl {
namespace {

// Distinct colours in a frame: a blank or black frame has one or two.
std::size_t colourCount(const Image& image) {
  std::set<int> colours;
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3 * 97)
    colours.insert(image.rgb[i] << 16 | image.rgb[i + 1] << 8 | image.rgb[i + 2]);
  return colours.size();
}

class FrameSizes : public ::testing::TestWithParam<ImageSize> {};

TEST_P(FrameSizes, RenderWithTextAndPanels) {
  const ImageSize size = GetParam();
  Renderer renderer(testing::smallSettings(), size);
  const Image image = renderer.render(syntheticFrame(2.0, 120));
  ASSERT_EQ(image.width, size.width);
  ASSERT_EQ(image.height, size.height);
  ASSERT_EQ(image.rgb.size(), static_cast<std::size_t>(size.width) * size.height * 3);
  EXPECT_GT(colourCount(image), 10u);  // not a blank frame: sphere, paths, chain and text (64 px wide: few, small)
}

INSTANTIATE_TEST_SUITE_P(LandscapePortraitExtreme, FrameSizes,
                         ::testing::Values(ImageSize{3840, 2160}, ImageSize{1080, 1920}, ImageSize{2560, 1440},
                                           ImageSize{4096, 64}, ImageSize{64, 4096}),
                         [](const auto& info) {
                           return std::to_string(info.param.width) + "x" + std::to_string(info.param.height);
                         });

}  // namespace
}  // namespace sl

// The read-back frame's RGBA to RGB packing: the SIMD path and the portable one give the same bytes, at every
// pixel count (the SIMD loop leaves a tail of up to eight pixels to the portable one); and the read-back itself,
// band by band, puts every row where it belongs.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "render/gl/drop_alpha.hpp"
#include "render/gl/gl.hpp"
#include "render/gl/gl_context.hpp"

namespace sl {
namespace {

TEST(DropAlpha, BothPathsKeepEveryColourByteAndDropEveryAlpha) {
  for (std::size_t pixels : {std::size_t(1), std::size_t(3), std::size_t(4), std::size_t(7), std::size_t(8),
                             std::size_t(9), std::size_t(33), std::size_t(1280 * 3 + 5)}) {
    std::vector<std::uint8_t> rgba(pixels * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = std::uint8_t(i * 37 + 11);
    std::vector<std::uint8_t> expected;
    for (std::size_t p = 0; p < pixels; ++p)
      expected.insert(expected.end(), {rgba[4 * p], rgba[4 * p + 1], rgba[4 * p + 2]});
    for (DropAlphaPath path : {DropAlphaPath::automatic, DropAlphaPath::portable}) {
      std::vector<std::uint8_t> rgb(pixels * 3 + 16, 0xEE);  // bytes past the end must stay untouched
      dropAlpha(rgba.data(), rgb.data(), pixels, path);
      EXPECT_TRUE(std::equal(expected.begin(), expected.end(), rgb.begin())) << pixels << " pixels";
      for (std::size_t i = pixels * 3; i < rgb.size(); ++i) ASSERT_EQ(rgb[i], 0xEE) << pixels << " pixels, byte " << i;
    }
  }
}

// Rows of a frame several read-back bands tall (and a short last band) painted with colours that name the row and
// the column stripe: the RGB read back holds each where it was drawn.
TEST(ReadBack, EveryRowOfEveryBandLandsInItsPlace) {
  for (const auto& [width, height] : {std::pair{300, 701}, std::pair{1280, 219}, std::pair{7, 3}}) {
    GlContext context(width, height);
    context.bindFramebuffer();
    glEnable(GL_SCISSOR_TEST);
    auto colour = [](int x, int y) {
      return std::array<std::uint8_t, 3>{std::uint8_t(y % 256), std::uint8_t(y / 256 * 16 + x % 5),
                                         std::uint8_t(x / 5)};
    };
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        if (x % 5 != 0 && x != width - 1) continue;  // stripes of five columns: one clear each
        const int x0 = x - x % 5;
        const auto c = colour(x0, y);
        glScissor(x0, y, std::min(5, width - x0), 1);
        glClearColor(c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, 1);
        glClear(GL_COLOR_BUFFER_BIT);
      }
    std::vector<std::uint8_t> rgb;
    context.readRgb(rgb);
    ASSERT_EQ(rgb.size(), std::size_t(width) * height * 3);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const auto expected = colour(x - x % 5, y);
        const std::uint8_t* got = &rgb[(std::size_t(y) * width + x) * 3];
        ASSERT_TRUE(got[0] == expected[0] && got[1] == expected[1] && got[2] == expected[2])
            << width << "x" << height << ": pixel (" << x << ", " << y << ")";
      }
  }
}

}  // namespace
}  // namespace sl

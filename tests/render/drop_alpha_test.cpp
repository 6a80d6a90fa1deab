// The read-back frame's RGBA to RGB packing: the SIMD path and the portable one give the same bytes, at every
// pixel count (the SIMD loop leaves a tail of up to eight pixels to the portable one).

#include <gtest/gtest.h>

#include <vector>

#include "render/gl/drop_alpha.hpp"

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

}  // namespace
}  // namespace sl

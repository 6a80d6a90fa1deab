// The time grids: counts, end points and the rounding allowances they document.

#include <gtest/gtest.h>

#include "contracts/time_grid.hpp"

namespace sl {
namespace {

TEST(TimeGrid, FrameCountIncludesBothEnds) {
  EXPECT_EQ(frameCount(20, 30), 601);
  EXPECT_EQ(frameCount(0.1 * 3, 10), 4);  // 0.30000000000000004 s at 10 fps: still frames 0..3
  EXPECT_EQ(frameCount(0, 30), 1);
  const std::vector<double> times = frameTimes(1, 4);
  ASSERT_EQ(times.size(), 5u);
  EXPECT_EQ(times.back(), 1.0);
  EXPECT_EQ(frameTime(3, 30), 3 / 30.0);
}

TEST(TimeGrid, UniformTimesStopAtTheDuration) {
  const std::vector<double> times = uniformTimes(1, 0.1);
  ASSERT_EQ(times.size(), 11u);
  EXPECT_DOUBLE_EQ(times.back(), 1.0);
  EXPECT_EQ(uniformTimes(1, 0.3).size(), 4u);  // 0, 0.3, 0.6, 0.9
}

TEST(TimeGrid, GridThroughEndsExactlyAtTheDuration) {
  const std::vector<double> even = gridTimesThrough(2, 0.5);
  ASSERT_EQ(even.size(), 5u);
  EXPECT_EQ(even.back(), 2.0);
  const std::vector<double> odd = gridTimesThrough(1, 0.3);
  ASSERT_EQ(odd.size(), 5u);  // 0, 0.3, 0.6, 0.9, 1
  EXPECT_EQ(odd.back(), 1.0);
  EXPECT_DOUBLE_EQ(odd[3], 0.9);
}

}  // namespace
}  // namespace sl

#include <gtest/gtest.h>

#include "scene/did_you_mean.hpp"

namespace sl {
namespace {

TEST(DidYouMean, EditDistanceCountsInsertionsDeletionsSubstitutions) {
  EXPECT_EQ(editDistance("", ""), 0);
  EXPECT_EQ(editDistance("abc", ""), 3);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3);
  EXPECT_EQ(editDistance("duration", "durration"), 1);
  EXPECT_EQ(editDistance("rk4", "kr4"), 2);
}

TEST(DidYouMean, SuggestsOnlyNearMisses) {
  const std::vector<std::string> keys = {"duration", "runs", "output", "linkage"};
  EXPECT_EQ(closestName("durration", keys), "duration");
  EXPECT_EQ(closestName("run", keys), "runs");
  EXPECT_EQ(closestName("zzzzzzzz", keys), "");
  EXPECT_EQ(didYouMean("linkgae", keys), " (did you mean \"linkage\"?)");
  EXPECT_EQ(didYouMean("camera", keys), "");
}

}  // namespace
}  // namespace sl

// A title names values of the scene, so that an override shows in the frames (scene/title_placeholders.hpp).
#include <gtest/gtest.h>

#include "scene/scene_loader.hpp"
#include "scene/title_placeholders.hpp"
#include "support/files.hpp"
#include "support/scene_files.hpp"

namespace sl {
namespace {

const char* kTwoRuns = R"({
  "name": "two", "title": "t",
  "linkage": { "rods": 4, "L": 3.2 },
  "initial": { "coords": [0.1, 0.2], "velocity": [1, 0] }, "duration": 1,
  "runs": [ { "name": "plain" },
            { "name": "feather", "method": "ambient", "family": { "kind": "fan", "count": 12, "spread": 0.3 } } ]
})";

TEST(TitlePlaceholders, NameTheChainAndEachRunsFamily) {
  const Scene scene = parseScene(kTwoRuns, "two.json");
  EXPECT_EQ(fillTitlePlaceholders("{n} rods, L = {L}, {name}: {runs[1].family.count} members", scene),
            "4 rods, L = 3.2, two: 12 members");
  // A run without a family has no count: the braces stay as written, as for any unknown name.
  EXPECT_EQ(fillTitlePlaceholders("{runs[0].family.count} {runs[2].family.count} {count}", scene),
            "{runs[0].family.count} {runs[2].family.count} {count}");
}

// fan.json says how many geodesics it draws, so the benchmark's `--set runs[0].family.count=64` shows in its frames.
TEST(TitlePlaceholders, ShippedFanTitleFollowsItsCount) {
  const std::string text = testing::readFile(testing::shippedScene("fan.json"));
  const Scene shipped = parseScene(text, "fan.json");
  EXPECT_EQ(fillTitlePlaceholders(shipped.title, shipped).rfind("A fan of 32 geodesics", 0), 0u);
  const Scene more = parseScene(text, "fan.json", {"runs[0].family.count=64"});
  EXPECT_EQ(fillTitlePlaceholders(more.title, more).rfind("A fan of 64 geodesics", 0), 0u);
}

}  // namespace
}  // namespace sl

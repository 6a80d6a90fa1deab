// Every bad scene (tests/data/scenes/bad/expected.tsv): exit status 2, the message names the JSON
// path, and nothing is written, for `validate` and for `render`.
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "cli_support.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

const std::string kBadDir = std::string(SL_SOURCE_DIR) + "/tests/data/scenes/bad/";

std::vector<std::pair<std::string, std::string>> badCases() {
  std::vector<std::pair<std::string, std::string>> cases;  // file, JSON path
  std::ifstream table(kBadDir + "expected.tsv");
  std::string line;
  while (std::getline(table, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string file, path;
    std::getline(fields, file, '\t');
    std::getline(fields, path, '\t');
    cases.push_back({file, path});
  }
  return cases;
}

TEST(BadScenesCli, ValidateAndRenderRefuseNamingThePathAndWriteNothing) {
  const auto cases = badCases();
  ASSERT_GE(cases.size(), 30u);
  for (const auto& [file, path] : cases) {
    SCOPED_TRACE(file);
    TempFolder folder;
    const CommandResult validate = runLinkage("validate " + quoted(kBadDir + file), folder.path());
    EXPECT_EQ(validate.status, 2) << validate.err;
    EXPECT_NE(validate.err.find(file), std::string::npos) << validate.err;
    EXPECT_NE(validate.err.find(": " + path + ": "), std::string::npos) << validate.err;
    const CommandResult render = runLinkage("render " + quoted(kBadDir + file) + " --quiet", folder.path());
    EXPECT_EQ(render.status, 2) << render.err;
    EXPECT_NE(render.err.find(": " + path + ": "), std::string::npos) << render.err;
    EXPECT_TRUE(fs::is_empty(folder.path())) << "something was written";
  }
}

TEST(BadScenesCli, BadOptionsAreUsageErrors) {
  TempFolder folder;
  const std::string scene = quoted(shippedScene("default.json"));
  for (const char* options :
       {"--frames 5:2", "--frames 0:9999", "--frames x", "--size 12x12", "--size big", "--no-png",
        "--size 321x180 --video v.mp4", "--resume --video v.mp4", "--out /proc/linkage-nope", "--frobnicate"}) {
    SCOPED_TRACE(options);
    const CommandResult result = runLinkage("render " + scene + " " + std::string(options), folder.path());
    EXPECT_EQ(result.status, 2) << result.err;
    EXPECT_FALSE(result.err.empty());
    EXPECT_TRUE(fs::is_empty(folder.path()));
  }
  EXPECT_EQ(runLinkage("validate /nonexistent.json", folder.path()).status, 2);
  EXPECT_EQ(runLinkage("", folder.path()).status, 2);
}

}  // namespace
}  // namespace sl::testing

// Every bad scene (tests/data/scenes/bad/expected.tsv): exit status 2, the message names the JSON
// path, and nothing is written, for `validate` and for `render`.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

TEST(BadScenesCli, ValidateAndRenderRefuseNamingThePathAndWriteNothing) {
  const auto table = badSceneExpectations();
  ASSERT_GE(table.size(), 30u);
  for (const auto& [file, expectations] : table) {
    SCOPED_TRACE(file);
    TempFolder folder;
    const std::string scene = badSceneFolder() + file;
    const ProcessResult validate = runLinkage({"validate", scene}, folder.path());
    const ProcessResult render = runLinkage({"render", scene, "--quiet"}, folder.path());
    EXPECT_EQ(validate.code, 2) << validate.err;
    EXPECT_NE(validate.err.find(file), std::string::npos) << validate.err;
    EXPECT_EQ(render.code, 2) << render.err;
    for (const BadSceneExpectation& expected : expectations) {
      EXPECT_NE(validate.err.find(": " + expected.jsonPath + ": "), std::string::npos) << validate.err;
      EXPECT_NE(render.err.find(": " + expected.jsonPath + ": "), std::string::npos) << render.err;
    }
    EXPECT_TRUE(fs::is_empty(folder.path())) << "something was written";
  }
}

TEST(BadScenesCli, BadOptionsAreUsageErrors) {
  TempFolder folder;
  const std::vector<std::vector<std::string>> badOptions = {{"--frames", "5:2"},
                                                            {"--frames", "0:9999"},
                                                            {"--frames", "x"},
                                                            {"--time", "3:2.5"},
                                                            {"--time", "19:40"},
                                                            {"--time", "1e400:"},
                                                            {"--time", "2"},
                                                            {"--time", "2:3", "--frames", "1:2"},
                                                            {"--size", "12x12"},
                                                            {"--size", "big"},
                                                            {"--no-png"},
                                                            {"--size", "321x180", "--video", "v.mp4"},
                                                            {"--resume", "--video", "v.mp4"},
                                                            {"--out", "/proc/linkage-nope"},
                                                            {"--frobnicate"}};
  for (const std::vector<std::string>& options : badOptions) {
    std::vector<std::string> args = {"render", shippedScene("default.json")};
    std::string trace;
    for (const std::string& option : options) {
      args.push_back(option);
      trace += " " + option;
    }
    SCOPED_TRACE(trace);
    const ProcessResult result = runLinkage(args, folder.path());
    EXPECT_EQ(result.code, 2) << result.err;
    EXPECT_FALSE(result.err.empty());
    EXPECT_TRUE(fs::is_empty(folder.path()));
  }
  EXPECT_EQ(runLinkage({"validate", "/nonexistent.json"}, folder.path()).code, 2);
  EXPECT_EQ(runLinkage({}, folder.path()).code, 2);
}

}  // namespace
}  // namespace sl::testing

// Outputs that could alias each other or an input, and child processes that could be trusted too much: each
// test pins one class of defect of the third round of hostile inputs.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/child_process.hpp"
#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

// Two outputs of one command, or an output and the scene, are the same file (also through a link, a hard link
// or another spelling): refused before any work, exit 2, both named, and the scene left as it was.
TEST(OutputsCli, NoOutputIsAnotherOutputOrAnInput) {
  TempFolder folder;
  const std::string text = readFile(shippedScene("default.json"));
  writeFile(folder.path() / "s.json", text);
  fs::create_symlink("s.json", folder.path() / "link.json");
  fs::create_hard_link(folder.path() / "s.json", folder.path() / "hard.json");
  fs::create_directories(folder.path() / "sub");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"simulate", "s.json", "--csv", "X", "--events", "X"}, "--events X is the same file as --csv X"},
      {{"simulate", "s.json", "--csv", "sub/../X", "--events", "./X"}, "--events ./X is the same file as --csv"},
      {{"simulate", "s.json", "--csv", "s.json"}, "--csv s.json is the same file as the scene"},
      {{"simulate", "s.json", "--events", "hard.json"}, "--events hard.json is the same file as the scene"},
      {{"geometry", "s.json", "--summary", "--csv", "link.json"}, "--csv link.json is the same file as the scene"},
      {{"geometry", "s.json", "--sweep-L", "2.1:3.9:3", "--csv", "c.png", "--chart", "c.png"},
       "--chart c.png is the same file as --csv c.png"},
  };
  for (const auto& [args, expected] : cases) {
    SCOPED_TRACE(args[0] + " " + args[2] + " " + args[3]);
    const ProcessResult result = runLinkage(args, folder.path());
    EXPECT_EQ(result.code, 2) << result.err;
    EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
    EXPECT_EQ(readFile(folder.path() / "s.json"), text);
    EXPECT_FALSE(fs::exists(folder.path() / "X"));
  }
  // A video named like the scene (a link with the video's extension) is refused by validate and render alike.
  fs::create_symlink("s.json", folder.path() / "v.mp4");
  for (const char* command : {"validate", "render"}) {
    const ProcessResult result =
        runLinkage({command, "s.json", "--set", "output.video=\"v.mp4\"", "--set", "output.folder=\"f\""}, folder.path());
    EXPECT_EQ(result.code, 2) << command << ": " << result.err;
    EXPECT_NE(result.err.find("output.video: is the scene file itself"), std::string::npos) << result.err;
  }
  EXPECT_EQ(readFile(folder.path() / "s.json"), text);
}

// A chart that cannot be drawn (no gnuplot on the PATH) leaves no CSV behind either: the command fails before
// writing anything.
TEST(OutputsCli, AChartWithoutGnuplotWritesNothing) {
  TempFolder folder;
  const ProcessResult result =
      runShell("PATH=/nonexistent " + shellQuoted(linkageBinary()) + " geometry " +
                   shellQuoted(shippedScene("default.json")) + " --sweep-L 2.1:3.9:3 --csv F.csv --chart P.png",
               folder.path(), 60);
  EXPECT_EQ(result.code, 3) << result.err;
  EXPECT_NE(result.err.find("need gnuplot"), std::string::npos) << result.err;
  EXPECT_TRUE(fs::is_empty(folder.path())) << "left: " << fs::directory_iterator(folder.path())->path();
}

}  // namespace
}  // namespace sl::testing

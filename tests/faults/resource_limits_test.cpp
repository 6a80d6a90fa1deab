// Absurd sizes are refused before any work, with the numbers in the message: frames larger than the
// renderer's maximum, frame counts beyond the limit, and renders that cannot fit in the output folder's
// free space.
#include <filesystem>

#include <gtest/gtest.h>

#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/temp_folder.hpp"

namespace sl {
namespace {

namespace fs = std::filesystem;
using testing::ProcessResult;
using testing::TempFolder;
using testing::writeFile;

std::string sceneWith(const std::string& duration, const std::string& output) {
  return R"({ "name": "absurd", "linkage": { "rods": 4, "L": 3.0 },
  "initial": { "coords": [0.3, 0.2], "velocity": [0.5, 0.7] }, "duration": )" +
         duration + R"(, "runs": [ { "name": "a", "method": "ambient" } ], "output": )" + output + " }";
}

ProcessResult run(const TempFolder& folder, const std::vector<std::string>& args) {
  return testing::runLinkage(args, folder.path(), 60);
}

TEST(ResourceLimits, ImageLargerThanTheRendererIsRefused) {
  TempFolder folder;
  writeFile(folder / "wide.json", sceneWith("1", R"({ "width": 100000, "height": 90 })"));
  for (const std::string command : {"validate", "render", "simulate"}) {
    const ProcessResult refusal = run(folder, {command, "wide.json"});
    EXPECT_EQ(refusal.code, 2) << command << ": " << refusal.err;
    EXPECT_NE(refusal.err.find("output.width: found 100000"), std::string::npos) << refusal.err;
  }
  writeFile(folder / "ok.json", sceneWith("1", R"({ "width": 160, "height": 90 })"));
  const ProcessResult option = run(folder, {"render", "ok.json", "--size", "99999x99999"});
  EXPECT_EQ(option.code, 2) << option.err;
  EXPECT_NE(option.err.find("99999"), std::string::npos) << option.err;
  EXPECT_FALSE(fs::exists(folder.path() / "renders")) << "nothing may be written for a refused render";
}

TEST(ResourceLimits, AbsurdFrameCountIsRefused) {
  TempFolder folder;
  writeFile(folder / "long.json", sceneWith("1e9", R"({ "fps": 1000, "width": 160, "height": 90 })"));
  const ProcessResult refusal = run(folder, {"render", "long.json"});
  EXPECT_EQ(refusal.code, 2) << refusal.err;
  EXPECT_NE(refusal.err.find("duration"), std::string::npos) << refusal.err;
  EXPECT_NE(refusal.err.find("1000 fps"), std::string::npos) << refusal.err;
  EXPECT_FALSE(fs::exists(folder.path() / "renders"));
}

// A huge int in a size must not wrap around into an accepted value.
TEST(ResourceLimits, SizesBeyondIntAreRefused) {
  TempFolder folder;
  writeFile(folder / "wrap.json", sceneWith("1", R"({ "width": 4294967456, "height": 90 })"));
  const ProcessResult refusal = run(folder, {"validate", "wrap.json"});
  EXPECT_EQ(refusal.code, 2) << refusal.err;
  EXPECT_NE(refusal.err.find("output.width"), std::string::npos) << refusal.err;
}

}  // namespace
}  // namespace sl

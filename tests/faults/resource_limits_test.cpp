// Absurd sizes are refused before any work, with the numbers in the message: frames larger than the
// renderer's maximum, frame counts beyond the limit, and renders that cannot fit in the output folder's
// free space.
#include <filesystem>

#include <gtest/gtest.h>

#include "child_process.hpp"
#include "fault_scenes.hpp"
#include "temp_folder.hpp"

namespace sl {
namespace {

namespace fs = std::filesystem;

std::string sceneWith(const std::string& duration, const std::string& output) {
  return R"({ "name": "absurd", "linkage": { "rods": 4, "L": 3.0 },
  "initial": { "coords": [0.3, 0.2], "velocity": [0.5, 0.7] }, "duration": )" +
         duration + R"(, "runs": [ { "name": "a", "method": "ambient" } ], "output": )" + output + " }";
}

struct Refusal {
  int code;
  std::string errors;
};

Refusal run(const faults::TempFolder& folder, const std::vector<std::string>& args) {
  std::string errors;
  const faults::ExitStatus status = faults::runLinkage(args, folder.path().string(), 60, &errors);
  return {status.code, errors};
}

TEST(ResourceLimits, ImageLargerThanTheRendererIsRefused) {
  faults::TempFolder folder;
  faults::writeText(folder / "wide.json", sceneWith("1", R"({ "width": 100000, "height": 90 })"));
  for (const std::string command : {"validate", "render", "simulate"}) {
    const Refusal refusal = run(folder, {command, "wide.json"});
    EXPECT_EQ(refusal.code, 2) << command << ": " << refusal.errors;
    EXPECT_NE(refusal.errors.find("output.width: found 100000"), std::string::npos) << refusal.errors;
  }
  faults::writeText(folder / "ok.json", sceneWith("1", R"({ "width": 160, "height": 90 })"));
  const Refusal option = run(folder, {"render", "ok.json", "--size", "99999x99999"});
  EXPECT_EQ(option.code, 2) << option.errors;
  EXPECT_NE(option.errors.find("99999"), std::string::npos) << option.errors;
  EXPECT_FALSE(fs::exists(folder.path() / "renders")) << "nothing may be written for a refused render";
}

TEST(ResourceLimits, AbsurdFrameCountIsRefused) {
  faults::TempFolder folder;
  faults::writeText(folder / "long.json", sceneWith("1e9", R"({ "fps": 1000, "width": 160, "height": 90 })"));
  const Refusal refusal = run(folder, {"render", "long.json"});
  EXPECT_EQ(refusal.code, 2) << refusal.errors;
  EXPECT_NE(refusal.errors.find("duration"), std::string::npos) << refusal.errors;
  EXPECT_NE(refusal.errors.find("1000 fps"), std::string::npos) << refusal.errors;
  EXPECT_FALSE(fs::exists(folder.path() / "renders"));
}

// A huge int in a size must not wrap around into an accepted value.
TEST(ResourceLimits, SizesBeyondIntAreRefused) {
  faults::TempFolder folder;
  faults::writeText(folder / "wrap.json", sceneWith("1", R"({ "width": 4294967456, "height": 90 })"));
  const Refusal refusal = run(folder, {"validate", "wrap.json"});
  EXPECT_EQ(refusal.code, 2) << refusal.errors;
  EXPECT_NE(refusal.errors.find("output.width"), std::string::npos) << refusal.errors;
}

}  // namespace
}  // namespace sl

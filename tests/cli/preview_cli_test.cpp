// The edit loop: previews, renders of another size, frame rate or frame step, and stills never touch the render of
// the scene's own settings in renders/<name>; a shard or --resume that meets another render names what differs.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

// A short copy of default.json (1280x720 at 30 fps, 1 s: 31 frames), so the full render stays cheap.
void writeShortScene(const TempFolder& folder) {
  std::string scene = readFile(shippedScene("default.json"));
  scene.replace(scene.find("\"duration\": 20.0"), 16, "\"duration\": 1.0");
  writeFile(folder.path() / "default.json", scene);
}

TEST(PreviewCli, PreviewsAndStillsLeaveTheFullRenderIntact) {
  TempFolder folder;
  writeShortScene(folder);
  ASSERT_EQ(runLinkage({"render", "default.json", "--quiet"}, folder.path()).code, 0);
  const auto full = folderContents(folder.path() / "renders/default");
  ASSERT_EQ(full.count("frame_00030.png"), 1u);

  const ProcessResult preview = runLinkage({"render", "default.json", "--preview"}, folder.path());
  ASSERT_EQ(preview.code, 0) << preview.err;
  EXPECT_NE(preview.err.find("16 frames of 320x180 -> renders/default-preview/"), std::string::npos) << preview.err;
  EXPECT_EQ(preview.err.find("replacing"), std::string::npos) << preview.err;
  const ProcessResult smaller = runLinkage({"render", "default.json", "--size", "320x180"}, folder.path());
  ASSERT_EQ(smaller.code, 0) << smaller.err;
  EXPECT_NE(smaller.err.find("-> renders/default-320x180/"), std::string::npos) << smaller.err;
  const ProcessResult range = runLinkage({"render", "default.json", "--size", "640x360", "--frames", "0:6"}, folder.path());
  ASSERT_EQ(range.code, 0) << range.err;
  EXPECT_NE(range.err.find("-> renders/default-640x360/"), std::string::npos) << range.err;
  const ProcessResult rate = runLinkage({"render", "default.json", "--set", "output.fps=10", "--frames", "::5",
                                         "--size", "160x90"},
                                        folder.path());
  ASSERT_EQ(rate.code, 0) << rate.err;
  EXPECT_NE(rate.err.find("-> renders/default-160x90-10fps-every5/"), std::string::npos) << rate.err;
  ASSERT_EQ(runLinkage({"still", "default.json", "--time", "0.5", "--out", "still.png", "--quiet"}, folder.path()).code, 0);

  EXPECT_EQ(folderContents(folder.path() / "renders/default"), full);  // byte for byte, every file
  const ProcessResult diff = runLinkage({"diff", "renders/default", "renders/default", "--quiet"}, folder.path());
  EXPECT_EQ(diff.code, 0) << diff.out;
}

TEST(PreviewCli, ShardsAndResumeNameWhatDiffers) {
  TempFolder folder;
  writeShortScene(folder);
  const std::vector<std::string> base{"render", "default.json", "--size", "160x90", "--out", "out", "--quiet"};
  const auto run = [&](std::vector<std::string> more) {
    std::vector<std::string> args = base;
    args.insert(args.end(), more.begin(), more.end());
    return runLinkage(args, folder.path());
  };
  ASSERT_EQ(run({"--frames", "0:10"}).code, 0);
  const ProcessResult edited = run({"--frames", "10:20", "--set", "linkage.L=3.1"});
  EXPECT_EQ(edited.code, 2);
  EXPECT_NE(edited.err.find("out holds another render; what differs: the scene's text or its --set/--unset overrides."),
            std::string::npos)
      << edited.err;
  const ProcessResult rate = run({"--frames", "10:20", "--set", "output.fps=20"});
  EXPECT_EQ(rate.code, 2);
  EXPECT_NE(rate.err.find("the frame rate: 30 fps there, 20 here; the frame count: 31 there, 21 here"),
            std::string::npos)
      << rate.err;
  const ProcessResult size = runLinkage({"render", "default.json", "--size", "320x180", "--out", "out", "--resume"},
                                        folder.path());
  EXPECT_EQ(size.code, 2);
  EXPECT_NE(size.err.find("the size: 160x90 there, 320x180 here"), std::string::npos) << size.err;
  EXPECT_EQ(size.err.find("the scene's text"), std::string::npos) << size.err;
  // Nothing was written by the refused runs: the folder holds frames 0..9 only, and they check out.
  EXPECT_FALSE(fs::exists(folder.path() / "out/frame_00010.png"));
  EXPECT_EQ(run({"--resume"}).code, 0);
  EXPECT_TRUE(fs::exists(folder.path() / "out/frame_00030.png"));
}

}  // namespace
}  // namespace sl::testing

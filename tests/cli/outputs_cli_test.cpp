// Outputs that could alias each other or an input, and child processes that could be trusted too much: each
// test pins one class of defect of the third round of hostile inputs.
#include <cstdio>
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

// A stand-in for ffmpeg, first on the PATH: `body` is its shell script after the line that records its pid.
void writeFakeEncoder(const fs::path& folder, const std::string& body) {
  fs::create_directories(folder / "bin");
  writeFile(folder / "bin" / "ffmpeg", "#!/bin/sh\necho $$ > encoder.pid\n" + body);
  fs::permissions(folder / "bin" / "ffmpeg", fs::perms::owner_all);
}

std::string withFakeEncoder(const fs::path& folder) {
  return "PATH=" + shellQuoted((folder / "bin").string()) + ":\"$PATH\" ";
}

// An earlier render in "frames" and an earlier video v.gif (the real ffmpeg), made with the default scene.
void renderEarlier(const fs::path& folder) {
  const ProcessResult earlier =
      runLinkage({"render", shippedScene("default.json"), "--set", "duration=0.5", "--size", "160x90", "--out",
                  "frames", "--video", "v.gif", "--quiet"},
                 folder);
  ASSERT_EQ(earlier.code, 0) << earlier.err;
}

const std::string kEditedRender = " render " + shellQuoted(shippedScene("default.json")) +
                                  " --set duration=0.4 --size 160x90 --out frames --video v.gif";

// No encoder on the PATH: the render fails before it takes the folder over, so the earlier frames, manifest
// and video are untouched.
TEST(OutputsCli, AMissingEncoderIsFoundBeforeAnythingIsReplaced) {
  TempFolder folder;
  renderEarlier(folder.path());
  const auto before = folderContents(folder.path());
  const ProcessResult result = runShell("PATH=/nonexistent " + shellQuoted(linkageBinary()) + kEditedRender, folder.path(), 60);
  EXPECT_EQ(result.code, 3) << result.err;
  EXPECT_NE(result.err.find("cannot start ffmpeg"), std::string::npos) << result.err;
  EXPECT_EQ(folderContents(folder.path()), before) << "the earlier render was touched";
}

// An encoder that stops reading: the render says so after a second, answers SIGTERM (exit 130)
// and ends the encoder; with LINKAGE_ENCODER_WAIT=1 it gives up by itself (exit 3). The earlier video stays.
TEST(OutputsCli, AStalledEncoderIsNamedStoppedAndEnded) {
  TempFolder folder;
  renderEarlier(folder.path());
  const std::string video = readFile(folder.path() / "v.gif");
  writeFakeEncoder(folder.path(), "exec sleep 100000\n");  // never reads its input
  const std::string start = withFakeEncoder(folder.path()) + shellQuoted(linkageBinary()) + kEditedRender;
  const ProcessResult signalled = runShell(
      start + " > out.txt 2> err.txt & pid=$!; "
              "for i in $(seq 300); do grep -q 'waiting for ffmpeg' err.txt && break; sleep 0.1; done; "
              "kill -TERM $pid; wait $pid; rc=$?; "
              "if kill -0 $(cat encoder.pid) 2>/dev/null; then echo encoder-alive; kill -9 $(cat encoder.pid); fi; "
              "echo $rc",
      folder.path(), 120);
  const std::string err = readFile(folder.path() / "err.txt");
  EXPECT_NE(err.find("waiting for ffmpeg to read the frames for v.gif"), std::string::npos) << err;
  EXPECT_EQ(signalled.out.find("encoder-alive"), std::string::npos) << "the stalled encoder outlived the render";
  int code = -1;
  ASSERT_EQ(std::sscanf(signalled.out.c_str(), "%d", &code), 1) << signalled.out << signalled.err;
  EXPECT_EQ(code, 130) << err;

  const ProcessResult bounded = runShell("LINKAGE_ENCODER_WAIT=1 " + start + "; if kill -0 $(cat encoder.pid) "
                                         "2>/dev/null; then echo encoder-alive; kill -9 $(cat encoder.pid); fi",
                                         folder.path(), 120);
  EXPECT_EQ(bounded.code, 0);
  EXPECT_NE(bounded.err.find("gave up after 1 s: ffmpeg read nothing of the frames for v.gif"), std::string::npos)
      << bounded.err;
  EXPECT_EQ(bounded.out.find("encoder-alive"), std::string::npos) << "the stalled encoder outlived the render";
  EXPECT_EQ(readFile(folder.path() / "v.gif"), video);
  for (const auto& entry : fs::directory_iterator(folder.path()))
    EXPECT_EQ(entry.path().string().find(".tmp."), std::string::npos) << "left behind: " << entry.path();
}

// An encoder that exits 0 having written a cut file (as ffmpeg does on a full disk): the render fails (exit 3),
// saying how many frames the file holds, and the earlier video and its manifest stay as they were.
TEST(OutputsCli, AnEncodersSuccessIsCheckedByWhatItWrote) {
  TempFolder folder;
  renderEarlier(folder.path());
  const std::string video = readFile(folder.path() / "v.gif");
  const std::string manifest = readFile(folder.path() / "v.gif.manifest.json");
  writeFakeEncoder(folder.path(), "for last; do :; done\ncat > /dev/null\nhead -c 2000 v.gif > \"${last#file:}\"\nexit 0\n");
  const ProcessResult result =
      runShell(withFakeEncoder(folder.path()) + shellQuoted(linkageBinary()) + kEditedRender, folder.path(), 120);
  EXPECT_EQ(result.code, 3) << result.err;
  EXPECT_NE(result.err.find("the video v.gif was not replaced: ffmpeg exited 0 but its output holds"),
            std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find("of 13 frames"), std::string::npos) << result.err;
  EXPECT_EQ(readFile(folder.path() / "v.gif"), video);
  EXPECT_EQ(readFile(folder.path() / "v.gif.manifest.json"), manifest);
  for (const auto& entry : fs::directory_iterator(folder.path()))
    EXPECT_EQ(entry.path().string().find(".tmp."), std::string::npos) << "left behind: " << entry.path();
}

}  // namespace
}  // namespace sl::testing

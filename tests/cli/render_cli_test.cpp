// `linkage render` and `simulate` on shipped scenes: small renders, shards by the documented GNU
// parallel recipe, an interrupted render finished by --resume.
#include <spawn.h>
#include <sys/wait.h>
#include <csignal>
#include <fstream>
#include <functional>
#include <thread>

#include <gtest/gtest.h>

#include "cli_support.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

TEST(RenderCli, EveryShippedSceneValidatesAndRendersAFewSmallFrames) {
  for (const char* name :
       {"default.json", "comparison.json", "pole-passage.json", "seam.json", "massive-rods.json", "five-rods.json"}) {
    SCOPED_TRACE(name);
    TempFolder folder;
    const CommandResult validate = runLinkage("validate " + quoted(shippedScene(name)), folder.path());
    EXPECT_EQ(validate.status, 0) << validate.err;
    EXPECT_NE(validate.out.find(": ok"), std::string::npos);
    const CommandResult render = runLinkage(
        "render " + quoted(shippedScene(name)) + " --size 320x180 --frames 0:3 --out out --quiet", folder.path());
    ASSERT_EQ(render.status, 0) << render.err;
    for (const char* file : {"frame_00000.png", "frame_00001.png", "frame_00002.png", "manifest.json"}) {
      EXPECT_TRUE(fs::exists(folder.path() / "out" / file)) << file;
    }
    EXPECT_FALSE(fs::exists(folder.path() / "out" / "frame_00003.png"));
  }
}

TEST(RenderCli, DefaultFolderIsRendersSlashSceneName) {
  TempFolder folder;
  const CommandResult render =
      runLinkage("render " + quoted(shippedScene("seam.json")) + " --size 160x90 --frames 4:5", folder.path());
  ASSERT_EQ(render.status, 0) << render.err;
  EXPECT_TRUE(fs::exists(folder.path() / "renders" / "seam" / "frame_00004.png"));
}

// The recipe as scenes/README.md prints it, run as is (only the program path, size and folder added).
std::string readmeParallelRecipe() {
  std::ifstream readme(std::string(SL_SOURCE_DIR) + "/scenes/README.md");
  std::string line;
  while (std::getline(readme, line)) {
    if (line.rfind("parallel linkage render scenes/default.json", 0) == 0) return line;
  }
  return "";
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

TEST(RenderCli, ShardsByTheReadmeRecipeEqualAWholeRenderByteForByte) {
  std::string recipe = readmeParallelRecipe();
  ASSERT_FALSE(recipe.empty()) << "scenes/README.md lost its GNU parallel recipe";
  TempFolder folder;
  recipe = replaceAll(recipe, "parallel linkage ", "parallel " + quoted(linkageBinary()) + " ");
  recipe =
      replaceAll(recipe, "scenes/default.json", quoted(shippedScene("default.json")) + " --size 160x90 --out shards");
  const CommandResult shards = runShell(recipe, folder.path());
  ASSERT_EQ(shards.status, 0) << recipe << "\n" << shards.err;
  const CommandResult whole = runLinkage(
      "render " + quoted(shippedScene("default.json")) + " --size 160x90 --out whole --quiet", folder.path());
  ASSERT_EQ(whole.status, 0) << whole.err;
  const auto a = folderContents(folder.path() / "shards"), b = folderContents(folder.path() / "whole");
  EXPECT_EQ(a.size(), 601u + 2u);  // frames, manifest.json, .manifest.json.lock
  EXPECT_TRUE(a == b) << "shard union differs from the whole render";
}

// Starts a render, sends SIGTERM once `started` says so (polled for at most 15 s); returns the exit status.
int renderUntilTerminated(const std::vector<std::string>& arguments, const std::function<bool()>& started) {
  std::vector<char*> argv;
  const std::string program = linkageBinary();
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, program.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return -1;
  for (int i = 0; i < 3000 && !started(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(RenderCli, ResumeAfterSigtermEqualsAnUninterruptedRender) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  const std::string out = folder / "resumed";
  const int status = renderUntilTerminated({"render", scene, "--size", "160x90", "--quiet", "--out", out},
                                           [&] { return fs::exists(fs::path(out) / "frame_00020.png"); });
  EXPECT_EQ(status, 130);
  std::size_t partial = 0, frames = 0;
  for (const auto& entry : fs::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    partial += name.find(".tmp") != std::string::npos || name.find("partial") != std::string::npos;
    frames += entry.path().extension() == ".png";
  }
  EXPECT_EQ(partial, 0u) << "a partial file was left behind";
  EXPECT_LT(frames, 601u) << "the render finished before it could be interrupted";
  const CommandResult resume =
      runLinkage("render " + quoted(scene) + " --size 160x90 --quiet --resume --out resumed", folder.path());
  ASSERT_EQ(resume.status, 0) << resume.err;
  const CommandResult whole =
      runLinkage("render " + quoted(scene) + " --size 160x90 --quiet --out whole", folder.path());
  ASSERT_EQ(whole.status, 0) << whole.err;
  EXPECT_TRUE(folderContents(out) == folderContents(folder.path() / "whole"));
}

// A video interrupted while ffmpeg encodes it: the earlier video of that name and its manifest stay as they
// were, and nothing else is left (ffmpeg writes a temporary that only a finished render renames).
TEST(RenderCli, InterruptedVideoLeavesTheEarlierVideoUntouched) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  const CommandResult first = runLinkage(
      "render " + quoted(scene) + " --size 160x90 --frames 0:30 --no-png --video v.mp4 --quiet", folder.path());
  ASSERT_EQ(first.status, 0) << first.err;
  const auto before = folderContents(folder.path());
  ASSERT_EQ(before.size(), 2u);  // v.mp4 and v.mp4.manifest.json, nothing else
  const auto encoding = [&] {
    for (const auto& entry : fs::directory_iterator(folder.path()))
      if (std::error_code gone; entry.path().filename().string().find(".tmp.") != std::string::npos &&
                                fs::file_size(entry.path(), gone) > 0 && !gone)
        return true;
    return false;
  };
  const std::string video = folder / "v.mp4";
  const int status =
      renderUntilTerminated({"render", scene, "--size", "160x90", "--no-png", "--video", video, "--quiet"}, encoding);
  EXPECT_EQ(status, 130);
  const auto after = folderContents(folder.path());
  std::string names;
  for (const auto& [name, bytes] : after)
    names += " " + name + (before.count(name) && before.at(name) == bytes ? "" : " (new or changed)");
  EXPECT_TRUE(after == before) << "the interrupted video changed or left files in the folder:" << names;
}

TEST(SimulateCli, WritesOneRowPerFrameTimeAndRunToStdoutOrAFile) {
  TempFolder folder;
  const std::string scene = quoted(shippedScene("seam.json"));
  const CommandResult toStdout = runLinkage("simulate " + scene, folder.path());
  ASSERT_EQ(toStdout.status, 0) << toStdout.err;
  EXPECT_EQ(toStdout.out.rfind("run,time,phi,t,phidot,tdot,", 0), 0u);
  const CommandResult toFile = runLinkage("simulate " + scene + " --csv traj.csv", folder.path());
  ASSERT_EQ(toFile.status, 0) << toFile.err;
  EXPECT_EQ(readFile(folder / "traj.csv"), toStdout.out);  // deterministic, and the same either way
  const CommandResult fine = runLinkage("simulate " + scene + " --dt 0.5", folder.path());
  ASSERT_EQ(fine.status, 0);
  // exact: 21 rows at 0, 0.5, .., 10; the published run may stop early and end with its stop row.
  EXPECT_NE(fine.out.find("\nexact,10,"), std::string::npos) << fine.out.substr(0, 400);
}

}  // namespace
}  // namespace sl::testing

// `linkage render` and `simulate` on shipped scenes: small renders, shards by the documented GNU
// parallel recipe, an interrupted render finished by --resume.
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
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

TEST(RenderCli, EveryShippedSceneValidatesAndRendersAFewSmallFrames) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(sourcePath("scenes")))
    if (entry.path().extension() == ".json" && entry.path().filename() != "scene.schema.json")
      names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  ASSERT_GE(names.size(), 9u);
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    TempFolder folder;
    const ProcessResult validate = runLinkage({"validate", shippedScene(name)}, folder.path());
    EXPECT_EQ(validate.code, 0) << validate.err;
    EXPECT_NE(validate.out.find(": ok"), std::string::npos);
    const ProcessResult render =
        runLinkage({"render", shippedScene(name), "--size", "320x180", "--frames", "0:3", "--out", "out", "--quiet"},
                   folder.path());
    ASSERT_EQ(render.code, 0) << render.err;
    for (const char* file : {"frame_00000.png", "frame_00001.png", "frame_00002.png", "manifest.json"}) {
      EXPECT_TRUE(fs::exists(folder.path() / "out" / file)) << file;
    }
    EXPECT_FALSE(fs::exists(folder.path() / "out" / "frame_00003.png"));
  }
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// The everyday loop: render, edit the scene, render again into the same folder. A whole render replaces the
// earlier one (its frames go, nothing is mixed); a shard or --resume of another render is refused with a hint.
TEST(RenderCli, EditAndRenderAgainReplacesTheEarlierRender) {
  TempFolder folder;
  std::string scene = readFile(shippedScene("default.json"));
  scene = replaceAll(scene, "\"duration\": 20.0", "\"duration\": 0.3");
  scene = replaceAll(scene, "\"fps\": 30", "\"fps\": 10");
  writeFile(folder / "scene.json", scene);
  const std::vector<std::string> render{"render", "scene.json", "--size", "160x90", "--out", "out"};
  const ProcessResult first = runLinkage(render, folder.path());
  ASSERT_EQ(first.code, 0) << first.err;
  const std::string firstFrame = readFile(folder.path() / "out" / "frame_00001.png");

  writeFile(folder / "scene.json", replaceAll(scene, "\"L\": 3.0", "\"L\": 3.2"));
  const ProcessResult second = runLinkage(render, folder.path());
  ASSERT_EQ(second.code, 0) << second.err;
  EXPECT_NE(second.err.find("replacing the earlier render in out"), std::string::npos) << second.err;
  EXPECT_NE(readFile(folder.path() / "out" / "frame_00001.png"), firstFrame);
  // The folder now holds the edited render only: its manifest checks out against every file.
  const ProcessResult resume =
      runLinkage({"render", "scene.json", "--size", "160x90", "--out", "out", "--resume"}, folder.path());
  EXPECT_EQ(resume.code, 0) << resume.err;

  // A shard of the scene as it was: refused, saying what to do.
  writeFile(folder / "scene.json", scene);
  const ProcessResult shard =
      runLinkage({"render", "scene.json", "--size", "160x90", "--out", "out", "--frames", "0:1"}, folder.path());
  EXPECT_EQ(shard.code, 2);
  EXPECT_NE(shard.err.find("a whole render (without --frames or --resume) replaces it"), std::string::npos)
      << shard.err;
}

// Two different scenes rendered into one folder at the same time. Whatever the timing, the folder ends
// up holding one whole render that exited 0, whose manifest matches every file on disk (diff checks each file's
// hash against it), and nothing else: a render that lost the folder says so and exits non-zero.
TEST(RenderCli, TwoScenesRenderingIntoOneFolderAtOnceNeverMix) {
  TempFolder folder;
  std::string scene = readFile(shippedScene("default.json"));
  scene = replaceAll(scene, "\"duration\": 20.0", "\"duration\": 1.0");
  writeFile(folder / "a.json", scene);
  writeFile(folder / "b.json", replaceAll(scene, "\"L\": 3.0", "\"L\": 3.2"));
  for (const char* name : {"a", "b"}) {
    const ProcessResult alone = runLinkage(
        {"render", std::string(name) + ".json", "--size", "160x90", "--out", std::string("alone-") + name, "--quiet"},
        folder.path());
    ASSERT_EQ(alone.code, 0) << alone.err;
  }
  const std::string binary = shellQuoted(linkageBinary());
  for (int attempt = 0; attempt < 3; ++attempt) {
    SCOPED_TRACE(attempt);
    fs::remove_all(folder.path() / "shared");
    const ProcessResult both = runShell(
        binary + " render a.json --size 160x90 --out shared --quiet 2> a.err & a=$!; " + binary +
            " render b.json --size 160x90 --out shared --quiet 2> b.err & b=$!; wait $a; ra=$?; wait $b; rb=$?; "
            "echo $ra $rb",
        folder.path(), 120);
    ASSERT_EQ(both.code, 0) << both.err;
    int codeA = -1, codeB = -1;
    ASSERT_EQ(std::sscanf(both.out.c_str(), "%d %d", &codeA, &codeB), 2) << both.out;
    EXPECT_TRUE(codeA == 0 || codeB == 0) << readFile(folder.path() / "a.err") << readFile(folder.path() / "b.err");
    const bool isA = runLinkage({"diff", "shared", "alone-a"}, folder.path()).code == 0;
    const bool isB = runLinkage({"diff", "shared", "alone-b"}, folder.path()).code == 0;
    EXPECT_TRUE(isA != isB) << "the folder holds neither whole render, or both";
    EXPECT_EQ(isA ? codeA : codeB, 0) << "the render the folder holds did not succeed";
    for (const auto& entry : fs::directory_iterator(folder.path() / "shared"))
      EXPECT_EQ(entry.path().string().find(".tmp."), std::string::npos) << "left behind: " << entry.path();
  }
}

// renders/<name> for the scene's own size; another size gets its own folder beside it (docs/guide.md).
TEST(RenderCli, DefaultFolderIsRendersSlashSceneName) {
  TempFolder folder;
  const ProcessResult render = runLinkage({"render", shippedScene("seam.json"), "--frames", "4:5"}, folder.path());
  ASSERT_EQ(render.code, 0) << render.err;
  EXPECT_TRUE(fs::exists(folder.path() / "renders" / "seam" / "frame_00004.png"));
  const ProcessResult small =
      runLinkage({"render", shippedScene("seam.json"), "--size", "160x90", "--frames", "4:5"}, folder.path());
  ASSERT_EQ(small.code, 0) << small.err;
  EXPECT_TRUE(fs::exists(folder.path() / "renders" / "seam-160x90" / "frame_00004.png"));
}

// The recipe as scenes/README.md prints it, run as is (only the program path, size and folder added).
std::string readmeParallelRecipe() {
  std::ifstream readme(sourcePath("scenes/README.md"));
  std::string line;
  while (std::getline(readme, line)) {
    if (line.rfind("parallel linkage render scenes/default.json", 0) == 0) return line;
  }
  return "";
}

TEST(RenderCli, ShardsByTheReadmeRecipeEqualAWholeRenderByteForByte) {
  std::string recipe = readmeParallelRecipe();
  ASSERT_FALSE(recipe.empty()) << "scenes/README.md lost its GNU parallel recipe";
  TempFolder folder;
  recipe = replaceAll(recipe, "parallel linkage ", "parallel " + shellQuoted(linkageBinary()) + " ");
  recipe = replaceAll(recipe, "scenes/default.json",
                      shellQuoted(shippedScene("default.json")) + " --size 160x90 --out shards");
  const ProcessResult shards = runShell(recipe, folder.path());
  ASSERT_EQ(shards.code, 0) << recipe << "\n" << shards.err;
  const ProcessResult whole = runLinkage(
      {"render", shippedScene("default.json"), "--size", "160x90", "--out", "whole", "--quiet"}, folder.path());
  ASSERT_EQ(whole.code, 0) << whole.err;
  const auto a = folderContents(folder.path() / "shards"), b = folderContents(folder.path() / "whole");
  EXPECT_EQ(a.size(), 601u + 3u);  // frames, manifest.json, .manifest.json.lock, .manifest.json.active
  EXPECT_TRUE(a == b) << "shard union differs from the whole render";
}

// --frames K/N, as a job array's tasks give it (scripts/slurm/render-array.sbatch): N contiguous shards, any
// order, equal to the whole render byte for byte; bad K/N refused with the allowed range.
TEST(RenderCli, ShardsKOfNCoverTheAnimationOnceAndEqualAWholeRender) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  for (const char* shard : {"3/3", "1/3", "2/3"}) {
    const ProcessResult part =
        runLinkage({"render", scene, "--size", "160x90", "--frames", shard, "--out", "shards", "--quiet"}, folder.path());
    ASSERT_EQ(part.code, 0) << shard << ": " << part.err;
    if (std::string(shard) == "3/3") {  // frames 400..600 of 601
      EXPECT_TRUE(fs::exists(folder.path() / "shards" / "frame_00400.png"));
      EXPECT_FALSE(fs::exists(folder.path() / "shards" / "frame_00399.png"));
    }
  }
  ASSERT_EQ(runLinkage({"render", scene, "--size", "160x90", "--out", "whole", "--quiet"}, folder.path()).code, 0);
  EXPECT_TRUE(folderContents(folder.path() / "shards") == folderContents(folder.path() / "whole"));
  for (const char* bad : {"0/3", "4/3", "1/0", "1/602", "a/3"}) {
    const ProcessResult refused = runLinkage({"render", scene, "--frames", bad, "--out", "x"}, folder.path());
    EXPECT_EQ(refused.code, 2) << bad;
    EXPECT_NE(refused.err.find("or K/N with 1 <= K <= N <= 601"), std::string::npos) << refused.err;
  }
}

// The frames drawn side by side (--threads: in worker processes, or for a range of fewer than two frames per
// renderer on threads of one process) are the frames one renderer draws, byte for byte, manifest included.
TEST(RenderCli, TheNumberOfThreadsDrawingChangesNoByte) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  auto render = [&](const std::string& frames, const std::string& threads) {
    const std::string out = "t" + threads + "-" + frames.substr(frames.find(':') + 1);
    const ProcessResult result = runLinkage(
        {"render", scene, "--size", "160x90", "--frames", frames, "--threads", threads, "--out", out}, folder.path());
    EXPECT_EQ(result.code, 0) << threads << ": " << result.err;
    return std::make_pair(folderContents(folder.path() / out), result.err);
  };
  const auto [one, oneSays] = render("100:160", "1");
  EXPECT_EQ(one.size(), 60u + 3u);
  for (const char* threads : {"2", "3"}) {
    const auto [files, says] = render("100:160", threads);
    EXPECT_TRUE(one == files) << threads << " processes";
    EXPECT_NE(says.find("60 frames of 160x90"), std::string::npos) << says;  // every worker's frames counted
  }
  EXPECT_TRUE(render("100:103", "1").first == render("100:103", "2").first) << "two renderers on threads";
  const ProcessResult refused = runLinkage({"render", scene, "--threads", "0", "--out", "x"}, folder.path());
  EXPECT_EQ(refused.code, 2) << refused.err;
}

// Starts `linkage arguments...` in folder, sends SIGTERM once `started` says so (or the render has ended: no
// deadline, so a loaded machine only makes it slower), and waits for it to end.
ProcessResult renderUntilTerminated(const std::vector<std::string>& arguments, const fs::path& folder,
                                    const std::function<bool()>& started) {
  ChildProcess child(linkageBinary(), arguments, folder);
  while (child.running() && !started()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  child.sendSignal(SIGTERM);
  return child.wait();
}

TEST(RenderCli, ResumeAfterSigtermEqualsAnUninterruptedRender) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  const std::string out = folder / "resumed";
  const ProcessResult terminated =
      renderUntilTerminated({"render", scene, "--size", "320x180", "--quiet", "--out", out}, folder.path(),
                            [&] { return fs::exists(fs::path(out) / "frame_00020.png"); });
  EXPECT_EQ(terminated.code, 130) << terminated.err;
  std::size_t partial = 0, frames = 0;
  for (const auto& entry : fs::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    partial += name.find(".tmp") != std::string::npos || name.find("partial") != std::string::npos;
    frames += entry.path().extension() == ".png";
  }
  EXPECT_EQ(partial, 0u) << "a partial file was left behind";
  EXPECT_LT(frames, 601u) << "the render finished before it could be interrupted";
  const ProcessResult resume =
      runLinkage({"render", scene, "--size", "320x180", "--quiet", "--resume", "--out", "resumed"}, folder.path());
  ASSERT_EQ(resume.code, 0) << resume.err;
  const ProcessResult whole =
      runLinkage({"render", scene, "--size", "320x180", "--quiet", "--out", "whole"}, folder.path());
  ASSERT_EQ(whole.code, 0) << whole.err;
  EXPECT_TRUE(folderContents(out) == folderContents(folder.path() / "whole"));
}

// The processes of a render (their pids, from /proc: the kernel lists a task's children).
std::vector<pid_t> childrenOf(pid_t pid) {
  std::ifstream list("/proc/" + std::to_string(pid) + "/task/" + std::to_string(pid) + "/children");
  std::vector<pid_t> children;
  for (pid_t child = 0; list >> child;) children.push_back(child);
  return children;
}

// A worker process that dies (here SIGKILL, as the OOM killer would) fails the render with a message saying so; the
// frames written are complete, and --resume finishes the render to the same bytes as one run.
TEST(RenderCli, AWorkerThatDiesFailsTheRenderAndResumeFinishesIt) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  const std::string out = folder / "killed";
  ChildProcess render(linkageBinary(), {"render", scene, "--size", "160x90", "--threads", "2", "--out", out},
                      folder.path());
  while (render.running() && !fs::exists(fs::path(out) / "frame_00020.png"))  // events only: no deadline
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  // Everything held still while one worker is picked and killed, so the render cannot finish first.
  render.sendSignal(SIGSTOP);
  const std::vector<pid_t> workers = childrenOf(render.pid());
  ASSERT_EQ(workers.size(), 2u) << "the render's worker processes";
  for (pid_t worker : workers) ::kill(worker, SIGSTOP);
  ::kill(workers[1], SIGKILL);
  ::kill(workers[0], SIGCONT);
  render.sendSignal(SIGCONT);
  const ProcessResult failed = render.wait();
  EXPECT_EQ(failed.code, 3) << failed.err;
  EXPECT_NE(failed.err.find("a process drawing frames was killed by"), std::string::npos) << failed.err;
  const ProcessResult resumed =
      runLinkage({"render", scene, "--size", "160x90", "--quiet", "--resume", "--out", out}, folder.path());
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  const ProcessResult whole =
      runLinkage({"render", scene, "--size", "160x90", "--quiet", "--out", "whole"}, folder.path());
  ASSERT_EQ(whole.code, 0) << whole.err;
  EXPECT_TRUE(folderContents(out) == folderContents(folder.path() / "whole"));
}

// A worker process that is stopped (SIGSTOP, a debugger, a batch system's suspend) is said after a second, and
// SIGTERM still ends the render (class 7 of the fourth round): the render hung silently, SIGTERM included, since a
// stopped worker never acted on the SIGTERM sent on to it.
TEST(RenderCli, AStoppedWorkerIsSaidAndSigtermStillEndsTheRender) {
  TempFolder folder;
  const std::string out = folder / "stopped";
  ChildProcess render(linkageBinary(),
                      {"render", shippedScene("default.json"), "--size", "160x90", "--threads", "2", "--out", out},
                      folder.path());
  while (render.running() && !fs::exists(fs::path(out) / "frame_00010.png"))  // events only: no deadline
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  render.sendSignal(SIGSTOP);  // held still while a worker is picked, so the render cannot finish first
  const std::vector<pid_t> workers = childrenOf(render.pid());
  ASSERT_EQ(workers.size(), 2u) << "the render's worker processes";
  ::kill(workers[0], SIGSTOP);
  render.sendSignal(SIGCONT);
  const fs::path log = fs::read_symlink("/proc/" + std::to_string(render.pid()) + "/fd/2");
  const std::string said = "(pid " + std::to_string(workers[0]) + ") is stopped";
  while (render.running() && readFile(log).find(said) == std::string::npos)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  render.sendSignal(SIGTERM);
  const ProcessResult stopped = render.wait();
  EXPECT_EQ(stopped.code, 130) << stopped.err;
  EXPECT_NE(stopped.err.find(said), std::string::npos) << stopped.err;
  EXPECT_NE(stopped.err.find("kill -CONT " + std::to_string(workers[0])), std::string::npos) << stopped.err;
}

// A video interrupted while ffmpeg encodes it: the earlier video of that name and its manifest stay as they
// were, and nothing else is left (ffmpeg writes a temporary that only a finished render renames).
TEST(RenderCli, InterruptedVideoLeavesTheEarlierVideoUntouched) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  const ProcessResult first =
      runLinkage({"render", scene, "--size", "160x90", "--frames", "0:30", "--no-png", "--video", "v.mp4", "--quiet"},
                 folder.path());
  ASSERT_EQ(first.code, 0) << first.err;
  const auto before = folderContents(folder.path());
  // v.mp4, v.mp4.manifest.json and the claim that one render at a time writes it, nothing else.
  ASSERT_EQ(before.size(), 3u);
  ASSERT_TRUE(before.count(".v.mp4.manifest.json.active"));
  const auto encoding = [&] {
    for (const auto& entry : fs::directory_iterator(folder.path()))
      if (std::error_code gone; entry.path().filename().string().find(".tmp.") != std::string::npos &&
                                fs::file_size(entry.path(), gone) > 0 && !gone)
        return true;
    return false;
  };
  const std::string video = folder / "v.mp4";
  const ProcessResult terminated = renderUntilTerminated(
      {"render", scene, "--size", "160x90", "--no-png", "--video", video, "--quiet"}, folder.path(), encoding);
  EXPECT_EQ(terminated.code, 130) << terminated.err;
  const auto after = folderContents(folder.path());
  std::string names;
  for (const auto& [name, bytes] : after)
    names += " " + name + (before.count(name) && before.at(name) == bytes ? "" : " (new or changed)");
  EXPECT_TRUE(after == before) << "the interrupted video changed or left files in the folder:" << names;
}

TEST(SimulateCli, WritesOneRowPerFrameTimeAndRunToStdoutOrAFile) {
  TempFolder folder;
  const std::string scene = shippedScene("seam.json");
  const ProcessResult toStdout = runLinkage({"simulate", scene}, folder.path());
  ASSERT_EQ(toStdout.code, 0) << toStdout.err;
  EXPECT_EQ(toStdout.out.rfind("run,time,phi,t,phidot,tdot,", 0), 0u);
  const ProcessResult toFile = runLinkage({"simulate", scene, "--csv", "traj.csv"}, folder.path());
  ASSERT_EQ(toFile.code, 0) << toFile.err;
  EXPECT_EQ(readFile(folder / "traj.csv"), toStdout.out);  // deterministic, and the same either way
  const ProcessResult fine = runLinkage({"simulate", scene, "--dt", "0.5"}, folder.path());
  ASSERT_EQ(fine.code, 0);
  // exact: 21 rows at 0, 0.5, .., 10; the published run may stop early and end with its stop row.
  EXPECT_NE(fine.out.find("\nexact,10,"), std::string::npos) << fine.out.substr(0, 400);
}

}  // namespace
}  // namespace sl::testing

// Edges of the command line that a plausible slip would move: the default --tol of `diff` and its boundary, a
// relative link resolved against its own folder, and a superseded render deleting only its own frames.
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/files.hpp"
#include "support/child_process.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

// A one-run, one-row trajectory CSV whose first hinge is at (x, 0).
std::string trajectoryWithFirstHingeAt(const std::string& x) {
  return "run,time,phi,t,phidot,tdot,energy,p1x,p1y,p2x,p2y,p3x,p3y,status\n"
         "r,0,0.3,0.2,0.4,0.3,0.5," +
         x + ",0,1.5,-0.5,2.5,-0.4,ok\n";
}

// The default tolerance is 1e-9 and inclusive: a difference of exactly 1e-9 matches, the next double does not.
TEST(EdgesCli, DiffsDefaultToleranceIsOneNanoRodLengthInclusive) {
  TempFolder folder;
  writeFile(folder.path() / "a.csv", trajectoryWithFirstHingeAt("0"));
  writeFile(folder.path() / "at.csv", trajectoryWithFirstHingeAt("1e-9"));
  char beyond[40];
  std::snprintf(beyond, sizeof beyond, "%.17g", std::nextafter(1e-9, 1.0));
  writeFile(folder.path() / "beyond.csv", trajectoryWithFirstHingeAt(beyond));
  const ProcessResult at = runLinkage({"diff", "a.csv", "at.csv"}, folder.path());
  EXPECT_EQ(at.code, 0) << at.out << at.err;
  const ProcessResult past = runLinkage({"diff", "a.csv", "beyond.csv"}, folder.path());
  EXPECT_EQ(past.code, 1) << past.out << past.err;
  EXPECT_EQ(runLinkage({"diff", "a.csv", "beyond.csv", "--tol", "2e-9"}, folder.path()).code, 0);
}

// A relative link names its target from the link's own folder, not from the working directory.
TEST(EdgesCli, ARelativeLinkIsResolvedFromItsOwnFolder) {
  TempFolder folder;
  fs::create_directories(folder.path() / "sub");
  fs::create_symlink("target.csv", folder.path() / "sub" / "link.csv");
  const ProcessResult run = runLinkage(
      {"simulate", shippedScene("default.json"), "--set", "duration=0.1", "--csv", "sub/link.csv", "--quiet"},
      folder.path());
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_TRUE(fs::is_symlink(folder.path() / "sub" / "link.csv"));
  EXPECT_TRUE(fs::exists(folder.path() / "sub" / "target.csv"));
  EXPECT_FALSE(fs::exists(folder.path() / "target.csv")) << "resolved against the working directory";
}

// Superseding a render deletes the frames its manifest lists by this program's own names only: a manifest is
// data, and names outside the folder or of another pattern are never deleted.
TEST(EdgesCli, SupersedingDeletesOnlyItsOwnFrameNames) {
  TempFolder folder;
  const auto render = [&](const std::string& duration) {
    return runLinkage({"render", shippedScene("seam.json"), "--out", "out", "--size", "160x90", "--set",
                       "duration=" + duration, "--quiet"},
                      folder.path());
  };
  ASSERT_EQ(render("0.04").code, 0);
  writeFile(folder.path() / "victim.txt", "keep");
  writeFile(folder.path() / "out" / "notes.txt", "keep");
  fs::create_directories(folder.path() / "out" / "sub");
  writeFile(folder.path() / "out" / "sub" / "frame_00000.png", "keep");
  nlohmann::json manifest = nlohmann::json::parse(readFile(folder.path() / "out" / "manifest.json"));
  ASSERT_FALSE(manifest["frames"].empty());
  nlohmann::json foreign = manifest["frames"][0];
  for (const char* name : {"../victim.txt", "notes.txt", "sub/frame_00000.png"}) {
    foreign["file"] = name;
    manifest["frames"].push_back(foreign);
  }
  writeFile(folder.path() / "out" / "manifest.json", manifest.dump(1));
  render("0.05");  // another scene, rendered whole: supersedes the folder (or refuses the edited manifest)
  EXPECT_EQ(readFile(folder.path() / "victim.txt"), "keep");
  EXPECT_EQ(readFile(folder.path() / "out" / "notes.txt"), "keep");
  EXPECT_EQ(readFile(folder.path() / "out" / "sub" / "frame_00000.png"), "keep");
}

// The environment is read in one place (cli/environment.hpp): a value that is not a number of seconds is refused
// with the variable's name before any work, never taken silently as the default.
TEST(EdgesCli, UnusableEnvironmentValuesAreNamed) {
  TempFolder folder;
  const std::string render = shellQuoted(linkageBinary()) + " render " + shellQuoted(shippedScene("seam.json")) +
                             " --size 160x90 --frames 0:1 --out r --quiet";
  for (const std::string variable : {"LINKAGE_LOCK_WAIT", "LINKAGE_ENCODER_WAIT"}) {
    // A word, and a number too large for a deadline (the steady clock would overflow: a wait of no time at all).
    for (const std::string value : {"soon", "1e300", "nan"}) {
      const ProcessResult refused = runShell(variable + "=" + value + " " + render, folder.path());
      EXPECT_EQ(refused.code, 2) << refused.err;
      EXPECT_NE(refused.err.find(variable + ": found \"" + value + "\"; expected seconds, a number from 0 to 604800"),
                std::string::npos)
          << refused.err;
      EXPECT_FALSE(fs::exists(folder.path() / "r"));
    }
  }
  EXPECT_EQ(runShell("LINKAGE_LOCK_WAIT=2.5 " + render, folder.path()).code, 0);
  const ProcessResult progress = runShell("LINKAGE_PROGRESS=xml " + render, folder.path());
  EXPECT_EQ(progress.code, 2);
  EXPECT_NE(progress.err.find("LINKAGE_PROGRESS: found \"xml\"; expected json or text"), std::string::npos)
      << progress.err;
}

// LINKAGE_PROGRESS=json: every progress line on stderr is one JSON object a script can read, counting up to the
// whole work, and the one-line summary still ends the command.
TEST(EdgesCli, ProgressAsJsonLines) {
  TempFolder folder;
  const ProcessResult render =
      runShell("LINKAGE_PROGRESS=json " + shellQuoted(linkageBinary()) + " render " +
                   shellQuoted(shippedScene("seam.json")) + " --size 160x90 --frames 0:20 --out r",
               folder.path());
  ASSERT_EQ(render.code, 0) << render.err;
  std::istringstream lines(render.err);
  long last = -1, reports = 0;
  std::string line, summary;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] != '{') {
      summary = line;
      continue;
    }
    const nlohmann::json report = nlohmann::json::parse(line);
    EXPECT_EQ(report["command"], "render");
    EXPECT_EQ(report["unit"], "frame");
    EXPECT_EQ(report["total"], 20);
    EXPECT_GT(report["done"].get<long>(), last);
    EXPECT_GE(report["eta_seconds"].get<long>(), 0);
    last = report["done"].get<long>();
    ++reports;
  }
  EXPECT_GE(reports, 2);
  EXPECT_EQ(last, 20);
  EXPECT_EQ(summary.rfind("linkage render: ", 0), 0u) << render.err;
}

}  // namespace
}  // namespace sl::testing

// Temporary names say who writes them; the sweep removes only the leftovers of dead local writers.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "output/temporary_file.hpp"
#include "support/temp_folder.hpp"

namespace sl {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& path) { std::ofstream(path) << "x"; }

// A pid that certainly belonged to a process that has ended (until the kernel reuses it).
pid_t endedProcess() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

// "frame.png.tmp.<host>.<pid>.<serial>" with `pid` in place of this process's.
std::string withWriter(const std::string& temporary, pid_t pid) {
  const std::string own = "." + std::to_string(::getpid()) + ".";
  std::string name = fs::path(temporary).filename().string();
  return name.replace(name.find(own), own.size(), "." + std::to_string(pid) + ".");
}

TEST(TemporaryFile, KeepsTheFolderHidesTheExtensionAndIsUnique) {
  const std::string a = temporaryPathFor("out/frames/frame_00012.png"),
                    b = temporaryPathFor("out/frames/frame_00012.png");
  EXPECT_NE(a, b);
  EXPECT_EQ(fs::path(a).parent_path(), "out/frames");
  EXPECT_NE(fs::path(a).extension(), ".png") << "a glob for *.png would see a frame still being written";
  EXPECT_EQ(a.rfind("out/frames/frame_00012.png.tmp.", 0), 0u) << a;
  EXPECT_NE(a.find("." + std::to_string(::getpid()) + "."), std::string::npos) << a;
}

TEST(TemporaryFile, SweepRemovesOnlyLeftoversOfEndedLocalWriters) {
  const testing::TempFolder temp;
  const fs::path& folder = temp.path();
  const std::string mine = temporaryPathFor((folder / "frame_00001.png").string());
  const std::string dead = withWriter(temporaryPathFor((folder / "frame_00002.png").string()), endedProcess());
  const std::string deadVideo = withWriter(temporaryPathFor((folder / "clip.mp4").string()) + ".mp4", endedProcess());
  const std::string otherHost = "frame_00003.png.tmp.elsewhere.999999.0";
  for (const std::string& name : {fs::path(mine).filename().string(), dead, deadVideo, otherHost,
                                  std::string("frame_00004.png"), std::string("notes.tmp.txt")})
    touch(folder / name);

  std::vector<std::string> removed = removeStaleTemporaries(folder.string());
  std::sort(removed.begin(), removed.end());
  std::vector<std::string> expected = {dead, deadVideo};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(removed, expected);
  EXPECT_TRUE(fs::exists(mine)) << "a live writer's temporary was removed";
  EXPECT_TRUE(fs::exists(folder / otherHost)) << "another host's temporary was removed";
  EXPECT_TRUE(fs::exists(folder / "frame_00004.png"));
  EXPECT_TRUE(fs::exists(folder / "notes.tmp.txt"));
  EXPECT_TRUE(removeStaleTemporaries((folder / "missing").string()).empty());
}

// A writer that has ended but is not reaped yet (a zombie: a render's worker killed with it, under an init that does
// not reap) writes nothing: its temporaries are swept like a dead writer's.
TEST(TemporaryFile, SweepRemovesAZombieWritersLeftovers) {
  const testing::TempFolder temp;
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  siginfo_t ended = {};
  ASSERT_EQ(::waitid(P_PID, static_cast<id_t>(child), &ended, WEXITED | WNOWAIT), 0);  // ended, not reaped
  const std::string zombie = withWriter(temporaryPathFor((temp.path() / "frame_00005.png").string()), child);
  touch(temp.path() / zombie);
  const std::vector<std::string> removed = removeStaleTemporaries(temp.path().string());
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_EQ(removed, std::vector<std::string>{zombie});
}

}  // namespace
}  // namespace sl

// Hostile options, outputs and inputs from the command line: each test pins one class of defect so
// that it cannot come back. Crashes, hangs and silent loss first; then what validate must refuse; then files.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
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

// A scene that is slow on purpose: a tiny tolerance over a long time with one frame per second, so that
// computing the motion alone takes far longer than any test waits.
void writeSlowScene(const fs::path& file) {
  std::string scene = readFile(shippedScene("default.json"));
  scene.replace(scene.find("\"duration\": 20.0"), 16, "\"duration\": 100000.0");
  scene.replace(scene.find("\"tolerance\": 1e-10"), 18, "\"tolerance\": 1e-16");
  scene.replace(scene.find("\"fps\": 30"), 9, "\"fps\": 1");
  writeFile(file, scene);
}

// 13.1: a NaN or absurd error-grid interval was a SIGSEGV (an empty grid) or a 5e11-sample allocation.
TEST(HostileCli, ErrorGridIntervalsAreCheckedBeforeAnyWork) {
  TempFolder folder;
  for (const char* interval : {"nan", "1e-300", "1e-12", "inf", "-1", "0"}) {
    SCOPED_TRACE(interval);
    const ProcessResult stability = runLinkage(
        {"stability", "--interval", interval, "--grid", "2", "--no-charts", "--out", "st"}, folder.path(), 60);
    EXPECT_EQ(stability.code, 2) << stability.err;
    EXPECT_NE(stability.err.find("--interval"), std::string::npos) << stability.err;
    const ProcessResult bench =
        runLinkage({"bench", "--interval", interval, "--quick", "--no-charts", "--out", "bn"}, folder.path(), 60);
    EXPECT_EQ(bench.code, 2) << bench.err;
  }
}

// 13.15: NaN where a positive number is required is refused, by every command.
TEST(HostileCli, NonFiniteNumbersAreRefusedEverywhere) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  writeFile(folder.path() / "a.csv", "run,time,phi,t,phidot,tdot,energy,p1x,p1y,p2x,p2y,p3x,p3y,status\n");
  const std::vector<std::vector<std::string>> commands{
      {"simulate", scene, "--dt", "nan"},
      {"simulate", scene, "--dt", "inf"},
      {"diff", "a.csv", "a.csv", "--tol", "nan"},
      {"stability", "--tolerance", "nan", "--grid", "2", "--no-charts"},
      {"stability", "--step", "nan", "--grid", "2", "--no-charts"},
      {"stability", "--duration", "nan", "--grid", "2", "--no-charts"},
  };
  for (const auto& command : commands) {
    const ProcessResult result = runLinkage(command, folder.path(), 60);
    EXPECT_EQ(result.code, 2) << command[0] << " " << command[2] << " " << command[3] << ": " << result.err;
    EXPECT_NE(result.err.find("expected a finite number"), std::string::npos) << result.err;
  }
}

// A killed command's temporaries do not pile up in an analysis folder: bench and stability sweep what writers that
// no longer exist left there, as render does in its folders (a live writer's temporaries stay).
TEST(HostileCli, AnalysisCommandsSweepAKilledRunsTemporaries) {
  TempFolder folder;
  writeSlowScene(folder.path() / "slow.json");
  fs::create_directories(folder.path() / "st");
  // A simulate killed while it streams its CSV leaves its temporary beside the CSV it never finished.
  const ProcessResult killed = runShell(shellQuoted(linkageBinary()) +
                                            " simulate slow.json --csv st/run.csv & pid=$!; "
                                            "for i in $(seq 300); do ls st/*.tmp.* >/dev/null 2>&1 && break; sleep 0.1; "
                                            "done; kill -KILL $pid; wait $pid; true",
                                        folder.path(), 60);
  ASSERT_EQ(killed.code, 0) << killed.err;
  auto temporaries = [&] {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder.path() / "st"))
      if (entry.path().filename().string().find(".tmp.") != std::string::npos) names.push_back(entry.path().string());
    return names;
  };
  ASSERT_EQ(temporaries().size(), 1u) << "the killed simulate left no temporary to sweep";
  const ProcessResult sweep =
      runLinkage({"stability", "--grid", "2", "--no-charts", "--no-reference", "--out", "st"}, folder.path(), 120);
  EXPECT_EQ(sweep.code, 0) << sweep.err;
  EXPECT_TRUE(temporaries().empty());
  EXPECT_FALSE(fs::exists(folder.path() / "st" / "run.csv"));
}

// 13.15: tolerances outside what a run accepts (a scene's 1e-16 to 0.1) are refused by bench and stability before
// any work, as the scene loader refuses them.
TEST(HostileCli, TolerancesOutsideTheRunsRangeAreRefused) {
  TempFolder folder;
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"stability", "--tolerance", "1e-300", "--grid", "2", "--no-charts"},
        std::vector<std::string>{"stability", "--tolerance", "0.5", "--grid", "2", "--no-charts"},
        std::vector<std::string>{"bench", "--tolerances", "1e-6,1e-300", "--no-charts", "--out", "b"}}) {
    const ProcessResult result = runLinkage(command, folder.path(), 60);
    EXPECT_EQ(result.code, 2) << command[1] << " " << command[2] << ": " << result.err;
    EXPECT_NE(result.err.find("from 1e-16 to 0.1"), std::string::npos) << result.err;
  }
  EXPECT_FALSE(fs::exists(folder.path() / "b"));
}

// 13.16: shard numbers beyond int and merges of missing or corrupt shards are input errors (2), named.
TEST(HostileCli, ShardAndMergeProblemsAreInputErrors) {
  TempFolder folder;
  const ProcessResult huge =
      runLinkage({"stability", "--shard", "1/99999999999", "--grid", "2", "--no-charts"}, folder.path());
  EXPECT_EQ(huge.code, 2);
  EXPECT_NE(huge.err.find("--shard: expected K/N"), std::string::npos) << huge.err;
  const std::vector<std::string> merge{"stability", "--merge", "--out", "st", "--no-charts"};
  fs::create_directories(folder.path() / "st");
  EXPECT_EQ(runLinkage(merge, folder.path()).code, 2);
  ASSERT_EQ(runLinkage({"stability", "--shard", "1/2", "--grid", "2", "--no-reference", "--no-charts", "--out", "st",
                        "--quiet"},
                       folder.path())
                .code,
            0);
  const ProcessResult missing = runLinkage(merge, folder.path());
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("missing shards: st/stability-launch.shard-2-of-2.csv"), std::string::npos)
      << missing.err;
  writeFile(folder.path() / "st" / "stability-launch.shard-2-of-2.csv", "junk\n");
  const ProcessResult corrupt = runLinkage(merge, folder.path());
  EXPECT_EQ(corrupt.code, 2);
  EXPECT_NE(corrupt.err.find("stability-launch.shard-2-of-2.csv: not a stability shard"), std::string::npos)
      << corrupt.err;
}

// 13.3 and 13.20: standard output's write errors end the command with 3, never a silent short CSV.
TEST(HostileCli, WriteErrorsOnStandardOutputAreFailures) {
  TempFolder folder;
  const ProcessResult full =
      runShell(shellQuoted(linkageBinary()) + " simulate " + shellQuoted(shippedScene("default.json")) + " > /dev/full",
               folder.path());
  EXPECT_EQ(full.code, 3) << full.err;
  EXPECT_NE(full.err.find("cannot write the CSV to standard output"), std::string::npos) << full.err;
}

// docs/hardening.md, principle 1: every command that writes to standard output fails when it cannot (its output is
// flushed and checked before exit), and succeeds on the same command into a file.
TEST(HostileCli, EveryCommandsStandardOutputIsCheckedBeforeExit) {
  TempFolder folder;
  const std::string scene = shellQuoted(shippedScene("default.json"));
  for (const std::string& command :
       {std::string("schema"), std::string("list-methods"), std::string("--version"), std::string("--help"),
        "validate " + scene, "geometry --summary --set linkage.L=3 " + scene}) {
    SCOPED_TRACE(command);
    const ProcessResult full = runShell(shellQuoted(linkageBinary()) + " " + command + " > /dev/full", folder.path());
    EXPECT_EQ(full.code, 3) << full.err;
    EXPECT_NE(full.err.find("standard output"), std::string::npos) << full.err;
    const ProcessResult file = runShell(shellQuoted(linkageBinary()) + " " + command + " > out.txt", folder.path());
    EXPECT_EQ(file.code, 0) << file.err;
  }
}

// Runs `linkage <arguments>` in `folder` (stdout to out.txt, stderr to err.txt) and sends `signal` once the program
// has installed its handlers and the shell condition `awaited` holds (at most 60 s each). Returns its exit code. Nothing is
// timed: the work left is hours long, so an exit by the signal's answer is the event; a program that did not
// answer would outlive runShell's limit and fail the test.
int signalAfter(const std::string& arguments, const fs::path& folder, const char* signal = "TERM",
                const std::string& awaited = "") {
  const std::string wait = awaitSignalHandlers() +
                           (awaited.empty() ? std::string()
                                            : "; for i in $(seq 600); do " + awaited + " && break; sleep 0.1; done");
  const ProcessResult result = runShell(shellQuoted(linkageBinary()) + " " + arguments + " > out.txt 2> err.txt & pid=$!; " +
                                            wait + "; kill -" + signal + " $pid; wait $pid; echo $?",
                                        folder, 120);
  EXPECT_EQ(result.code, 0) << result.err;
  int code = -1;
  EXPECT_EQ(std::sscanf(result.out.c_str(), "%d", &code), 1) << result.out;
  return code;
}

// 13.7 and 13.20: SIGTERM is answered inside one long sample (hours of work left); stdout says it is cut.
TEST(HostileCli, SimulateAnswersSigtermInsideALongSample) {
  TempFolder folder;
  writeSlowScene(folder.path() / "slow.json");
  // The CSV's header is out: the first sample, about 20 s of work at this tolerance, has begun.
  EXPECT_EQ(signalAfter("simulate slow.json", folder.path(), "TERM", "[ -s out.txt ]"), 130);
  const std::string err = readFile(folder.path() / "err.txt");
  EXPECT_NE(err.find("stopped by SIGTERM"), std::string::npos) << err;
  EXPECT_NE(err.find("the CSV on standard output is incomplete"), std::string::npos) << err;
}

// 13.7: render answers SIGTERM and SIGINT even when one frame's motion takes long to compute (it
// took 23 s), leaving no temporary behind.
TEST(HostileCli, RenderAnswersSignalsInsideALongFrame) {
  TempFolder folder;
  writeSlowScene(folder.path() / "slow.json");
  for (const char* signal : {"TERM", "INT"}) {
    SCOPED_TRACE(signal);
    EXPECT_EQ(signalAfter("render slow.json --out frames", folder.path(), signal), 130);
    const std::string err = readFile(folder.path() / "err.txt");
    EXPECT_NE(err.find(std::string("stopped by SIG") + signal), std::string::npos) << err;
    // Frames so far are whole. The signal may come before the first frame (the motion is planned first): no folder.
    if (fs::exists(folder.path() / "frames")) {
      for (const auto& entry : fs::directory_iterator(folder.path() / "frames")) {
        EXPECT_EQ(entry.path().string().find(".tmp."), std::string::npos) << "left behind: " << entry.path();
      }
    }
  }
}

// 13.8 from the command line: a render waiting for a folder another process holds says so, answers SIGTERM
// while it waits, and gives up after LINKAGE_LOCK_WAIT seconds with the reason (exit 3).
TEST(HostileCli, ARenderWaitingForALockSaysSoAndCanBeStopped) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  fs::create_directories(folder.path() / "frames");
  // The test holds the folder's manifest lock, as a shard stopped with SIGSTOP would.
  const std::string lockPath = (folder.path() / "frames" / ".manifest.json.lock").string();
  const int lock = ::open(lockPath.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  ASSERT_GE(lock, 0);
  ASSERT_EQ(::flock(lock, LOCK_EX), 0);
  const std::string render = "render " + shellQuoted(scene) + " --out frames --size 160x90 --set duration=0.2";
  EXPECT_EQ(signalAfter(render, folder.path(), "TERM", "grep -q 'waiting for' err.txt"), 130);
  const std::string err = readFile(folder.path() / "err.txt");
  EXPECT_NE(err.find("waiting for frames/.manifest.json.lock, held by another process"), std::string::npos) << err;
  EXPECT_NE(err.find("stopped by SIGTERM"), std::string::npos) << err;

  const ProcessResult bounded =
      runShell("LINKAGE_LOCK_WAIT=1 " + shellQuoted(linkageBinary()) + " " + render, folder.path(), 60);
  EXPECT_EQ(bounded.code, 3) << bounded.err;
  EXPECT_NE(bounded.err.find("gave up after 1 s waiting for frames/.manifest.json.lock"), std::string::npos)
      << bounded.err;
  EXPECT_FALSE(fs::exists(folder.path() / "frames" / "frame_00000.png"));
  ::close(lock);
}

// 13.6: outputs through a symbolic link go to its target (the link stays); devices and folders are refused.
TEST(HostileCli, LinksAreWrittenThroughAndDevicesRefused) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  writeFile(folder.path() / "target.csv", "stale\n");
  fs::create_symlink("target.csv", folder.path() / "link.csv");
  ASSERT_EQ(runLinkage({"simulate", scene, "--csv", "link.csv", "--quiet"}, folder.path()).code, 0);
  EXPECT_TRUE(fs::is_symlink(folder.path() / "link.csv"));
  EXPECT_EQ(readFile(folder.path() / "target.csv").rfind("run,time,", 0), 0u);
  for (const char* bad : {"/dev/null", "."}) {
    const ProcessResult refused = runLinkage({"simulate", scene, "--csv", bad}, folder.path());
    EXPECT_EQ(refused.code, 2) << bad;
    EXPECT_NE(refused.err.find("--csv"), std::string::npos) << refused.err;
  }
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

// 13.12 and 13.13: output paths given on the command line that cannot work are refused before any work (exit 2,
// the option named, nothing created): components over 255 bytes, file names without room for the temporary,
// folders where a file is expected, unknown video formats.
TEST(HostileCli, OutputPathsOnTheCommandLineAreCheckedBeforeAnyWork) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  const std::string component(300, 'a'), name(230, 'b');
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"render", scene, "--out", component + "/frames"}, "--out"},
      {{"render", scene, "--video", component + "/v.mp4", "--no-png"}, "--video"},
      {{"render", scene, "--video", name + ".mp4", "--no-png"}, "--video"},
      {{"render", scene, "--video", "v.txt", "--no-png"}, "--video"},
      {{"render", scene, "--video", "sub/", "--no-png"}, "--video"},
      {{"simulate", scene, "--csv", name + ".csv"}, "--csv"},
      {{"simulate", scene, "--csv", "sub/"}, "--csv"},
      {{"simulate", scene, "--events", name + ".csv"}, "--events"},
      {{"simulate", scene, "--events", component + "/e.csv"}, "--events"},
  };
  for (const auto& [args, option] : cases) {
    SCOPED_TRACE(args[2] + " " + args[3].substr(0, 20));
    const ProcessResult result = runLinkage(args, folder.path());
    EXPECT_EQ(result.code, 2) << result.err;
    EXPECT_NE(result.err.find(option + ": "), std::string::npos) << result.err;
  }
  EXPECT_TRUE(fs::is_empty(folder.path())) << "a refused command created something";
}

// 13.6: a video written through a symbolic link lands in the link's target, also on another file system (the
// temporary is made beside the target, so the final rename never crosses file systems), and the link stays.
TEST(HostileCli, AVideoThroughALinkLandsInItsTargetOnAnyFileSystem) {
  TempFolder folder;
  // /dev/shm is a tmpfs on Linux: another file system than the temporary folder's, where there is one.
  const fs::path elsewhere = fs::is_directory("/dev/shm") ? fs::path("/dev/shm") / folder.path().filename()
                                                          : folder.path() / "elsewhere";
  fs::create_directories(elsewhere);
  fs::create_symlink(elsewhere / "target.mp4", folder.path() / "link.mp4");
  const ProcessResult result =
      runLinkage({"render", shippedScene("default.json"), "--set", "duration=0.3", "--size", "160x90", "--video",
                  "link.mp4", "--no-png", "--quiet"},
                 folder.path());
  EXPECT_EQ(result.code, 0) << result.err;
  EXPECT_TRUE(fs::is_symlink(folder.path() / "link.mp4"));
  EXPECT_GT(fs::file_size(elsewhere / "target.mp4"), 1000u);
  for (const auto& entry : fs::directory_iterator(elsewhere))
    EXPECT_EQ(entry.path().filename(), "target.mp4") << "left behind: " << entry.path();
  fs::remove_all(elsewhere);
}

// 13.17 and 13.18: the program reads its own CSV whatever the run names; diff handles NaN, CRLF, missing files,
// frame sizes and frames changed behind the manifest's back.
TEST(HostileCli, DiffReadsEveryCsvTheProgramWritesAndSaysWhatIsWrong) {
  TempFolder folder;
  std::string scene = readFile(shippedScene("comparison.json"));
  scene.replace(scene.find("\"christoffel (published)\""), 25, "\"a, \\\"quoted\\\"\\nname\"");
  writeFile(folder.path() / "names.json", scene);
  ASSERT_EQ(runLinkage({"simulate", "names.json", "--csv", "a.csv", "--quiet"}, folder.path()).code, 0);
  const ProcessResult own = runLinkage({"diff", "a.csv", "a.csv"}, folder.path());
  EXPECT_EQ(own.code, 0) << own.out << own.err;

  const std::string header = "run,time,phi,t,phidot,tdot,energy,p1x,p1y,p2x,p2y,p3x,p3y,status";
  writeFile(folder.path() / "nan.csv", header + "\nr,0,0,0,0,0,0.5,nan,0,0,0,0,0,ok\nr,1,0,0,0,0,0.5,0,0,0,0,0,0,ok\n");
  EXPECT_EQ(runLinkage({"diff", "nan.csv", "nan.csv"}, folder.path()).code, 0);
  writeFile(folder.path() / "zero.csv", header + "\nr,0,0,0,0,0,0.5,0,0,0,0,0,0,ok\nr,1,0,0,0,0,0.5,0,0,0,0,0,0,ok\n");
  const ProcessResult nanVsZero = runLinkage({"diff", "nan.csv", "zero.csv"}, folder.path());
  EXPECT_EQ(nanVsZero.code, 1);
  EXPECT_NE(nanVsZero.out.find("worst hinge difference inf at t = 0"), std::string::npos) << nanVsZero.out;
  writeFile(folder.path() / "crlf.csv",
            header + "\r\nr,0,0,0,0,0,0.5,0,0,0,0,0,0,ok\r\nr,1,0,0,0,0,0.5,0,0,0,0,0,0,ok\r\n");
  EXPECT_EQ(runLinkage({"diff", "crlf.csv", "zero.csv"}, folder.path()).code, 0);

  const ProcessResult missing = runLinkage({"diff", "zero.csv", "nothere.csv"}, folder.path());
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("nothere.csv: no such file or folder"), std::string::npos) << missing.err;

  const std::string seam = shippedScene("seam.json");
  ASSERT_EQ(runLinkage({"render", seam, "--size", "160x90", "--frames", "0:2", "--out", "small", "--quiet"},
                       folder.path())
                .code,
            0);
  ASSERT_EQ(runLinkage({"render", seam, "--size", "320x180", "--frames", "0:2", "--out", "big", "--quiet"},
                       folder.path())
                .code,
            0);
  const ProcessResult sizes = runLinkage({"diff", "small", "big", "--images"}, folder.path());
  EXPECT_EQ(sizes.code, 1);
  EXPECT_NE(sizes.out.find("the frames are 160x90 and 320x180"), std::string::npos) << sizes.out;
  // A frame replaced behind the manifest's back: the folder is not a consistent render.
  fs::copy_file(folder.path() / "big" / "frame_00001.png", folder.path() / "small" / "frame_00001.png",
                fs::copy_options::overwrite_existing);
  const ProcessResult tampered = runLinkage({"diff", "small", "small"}, folder.path());
  EXPECT_EQ(tampered.code, 2);
  EXPECT_NE(tampered.err.find("frame_00001.png: does not match its entry"), std::string::npos) << tampered.err;
  fs::remove(folder.path() / "small" / "frame_00001.png");
  EXPECT_EQ(runLinkage({"diff", "small", "big"}, folder.path()).code, 2);
}

}  // namespace
}  // namespace sl::testing

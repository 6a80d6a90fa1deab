// Process faults on the built `linkage` binary: SIGTERM and SIGKILL at random frames of a render, a full
// disk and a read-only output folder. Afterwards no partial PNG exists, the manifest lists only complete
// frames, and --resume finishes with files byte-identical to an uninterrupted render.
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "fault_scenes.hpp"
#include "support/child_process.hpp"
#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/temp_folder.hpp"

namespace sl {
namespace {

namespace fs = std::filesystem;
using testing::ChildProcess;
using testing::linkageBinary;
using testing::ProcessResult;
using testing::readFile;
using testing::TempFolder;

constexpr int kFrames = 40;

bool isFrameFile(const fs::path& file) {
  return file.extension() == ".png" && file.filename().string().rfind("frame_", 0) == 0;
}

// The final files of a render folder (frames and manifest), by name; temporaries and locks excluded.
std::map<std::string, std::string> renderFiles(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (isFrameFile(entry.path()) || name == "manifest.json") files[name] = readFile(entry.path());
  }
  return files;
}

// Leftovers of interrupted atomic writes (frame_00012.png.tmp.HOST.PID.N, output/temporary_file.hpp):
// all of them, or with a pid only those that process wrote.
std::vector<std::string> temporaries(const fs::path& folder, pid_t writer = 0) {
  const std::string marker = writer > 0 ? "." + std::to_string(writer) + "." : std::string(".tmp.");
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().filename().string().find(marker) != std::string::npos) names.push_back(entry.path().filename());
  }
  return names;
}

int frameFileCount(const fs::path& folder) {
  std::error_code error;
  int count = 0;
  for (const auto& entry : fs::directory_iterator(folder, error)) count += isFrameFile(entry.path());
  return count;
}

class ProcessFaults : public ::testing::Test {
 protected:
  void SetUp() override {
    testing::writeFile(folder_ / "small.json", faults::smallRenderScene(kFrames, "reference"));
    const ProcessResult reference = render({"--quiet"});
    ASSERT_EQ(reference.code, 0) << reference.err;
    reference_ = renderFiles(folder_.path() / "reference");
    ASSERT_EQ(reference_.size(), kFrames + 1u);  // the frames and the manifest
  }

  ProcessResult render(std::vector<std::string> options) {
    options.insert(options.begin(), {"render", "small.json"});
    return testing::runLinkage(options, folder_.path(), 300);
  }

  // Starts a render into `out`, waits until it has written `frame` frames, then sends `signal`.
  // Starts a resumed render and signals it once `frame` frame files exist and it has written at least one
  // of them itself (so the signal lands during rendering, not while the process is still starting up).
  ProcessResult interruptAt(const std::string& out, int frame, int signal, pid_t* pid = nullptr) {
    const int before = fs::exists(folder_.path() / out) ? frameFileCount(folder_.path() / out) : 0;
    ChildProcess child(linkageBinary(), {"render", "small.json", "--quiet", "--resume", "--out", out}, folder_.path());
    if (pid != nullptr) *pid = child.pid();
    const int target = std::max(frame, before + 1);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (child.running() && frameFileCount(folder_.path() / out) < target &&
           std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    child.sendSignal(signal);
    return child.wait(120);
  }

  // Every frame file present and every manifest entry equals the uninterrupted render's.
  void expectOnlyCompleteFrames(const std::string& out) {
    const fs::path folder = folder_.path() / out;
    for (const auto& [name, bytes] : renderFiles(folder)) {
      if (name == "manifest.json") continue;
      EXPECT_TRUE(bytes == reference_.at(name)) << name << " is not the complete frame";
    }
    if (!fs::exists(folder / "manifest.json")) return;
    const auto manifest = nlohmann::json::parse(readFile(folder / "manifest.json"));
    const auto complete = nlohmann::json::parse(reference_.at("manifest.json"));
    ASSERT_TRUE(manifest.contains("frames")) << manifest.dump();
    for (const auto& entry : manifest["frames"]) {
      const std::string file = entry.value("file", "");
      EXPECT_TRUE(fs::exists(folder / file)) << "the manifest lists " << file << ", which does not exist";
      bool listed = false;
      for (const auto& expected : complete["frames"]) listed = listed || expected == entry;
      EXPECT_TRUE(listed) << "entry differs from the complete render's: " << entry.dump();
    }
  }

  TempFolder folder_;
  std::map<std::string, std::string> reference_;
};

TEST_F(ProcessFaults, SignalsAtRandomFramesThenResumeGivesIdenticalBytes) {
  std::mt19937 random(20261121);  // fixed: the same frames every run
  std::uniform_int_distribution<int> pick(1, kFrames - 4);
  const std::vector<std::vector<int>> plans = {{SIGTERM}, {SIGKILL}, {SIGKILL, SIGTERM}, {SIGTERM, SIGKILL, SIGKILL}};
  for (size_t p = 0; p < plans.size(); ++p) {
    const std::string out = "run" + std::to_string(p);
    int frame = 0;
    for (const int signal : plans[p]) {
      frame = std::max(frame + 1, pick(random));
      SCOPED_TRACE(out + ": signal " + std::to_string(signal) + " after " + std::to_string(frame) + " frames");
      pid_t pid = 0;
      const ProcessResult status = interruptAt(out, frame, signal, &pid);
      EXPECT_FALSE(status.timedOut);
      if (signal == SIGTERM) {
        EXPECT_TRUE(status.code == 130 || status.code == 0) << "exit " << status.code << ", signal " << status.signal;
        // (A SIGKILLed predecessor's temporaries may remain: never listed, never renamed into place.)
        EXPECT_TRUE(temporaries(folder_.path() / out, pid).empty()) << "SIGTERM left a temporary file";
      } else {  // (a render that finished before the signal came, its last frames drawn side by side, exits 0)
        EXPECT_TRUE(status.signal == SIGKILL || status.code == 0) << "exit " << status.code << ", signal " << status.signal;
      }
      expectOnlyCompleteFrames(out);
    }
    const ProcessResult resumed = render({"--quiet", "--resume", "--out", out});
    ASSERT_EQ(resumed.code, 0) << resumed.err;
    EXPECT_TRUE(renderFiles(folder_.path() / out) == reference_) << out << ": resumed render differs";
    EXPECT_TRUE(temporaries(folder_.path() / out).empty()) << out << ": the resume left a killed render's temporaries";
  }
}

// A tmpfs mounted for the test (root only; skipped where mount is not permitted).
class Mount {
 public:
  Mount(const fs::path& where, const std::string& options) : where_(where) {
    fs::create_directories(where);
    const std::string command = "mount -t tmpfs -o " + options + " tmpfs '" + where.string() + "' 2>/dev/null";
    mounted_ = std::system(command.c_str()) == 0;
  }
  ~Mount() {
    if (mounted_) std::system(("umount '" + where_.string() + "'").c_str());
  }
  bool mounted() const { return mounted_; }
  bool remountReadOnly() { return std::system(("mount -o remount,ro '" + where_.string() + "'").c_str()) == 0; }

 private:
  fs::path where_;
  bool mounted_ = false;
};

// Writes zeros into `path` until the file system is full.
void fillDisk(const fs::path& path) {
  std::FILE* filler = std::fopen(path.c_str(), "wb");
  ASSERT_NE(filler, nullptr);
  const std::vector<char> block(64 * 1024, 0);
  while (std::fwrite(block.data(), 1, block.size(), filler) == block.size()) {
  }
  std::fclose(filler);
}

// The disk fills up while the render runs (it is stopped, the disk filled, then it continues).
TEST_F(ProcessFaults, FullDiskGivesAClearErrorAndKeepsCompletedFrames) {
  Mount disk(folder_.path() / "disk", "size=8m");
  if (!disk.mounted()) GTEST_SKIP() << "mounting a tmpfs is not permitted here (needs root)";
  ChildProcess child(linkageBinary(), {"render", "small.json", "--quiet", "--out", "disk/frames"}, folder_.path());
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (child.running() && frameFileCount(folder_.path() / "disk/frames") < 5 &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  child.sendSignal(SIGSTOP);
  fillDisk(folder_.path() / "disk/filler");
  child.sendSignal(SIGCONT);
  const ProcessResult status = child.wait(120);
  const std::string& errors = status.err;
  ASSERT_FALSE(status.timedOut);
  EXPECT_EQ(status.code, 3) << errors;  // the work failed: cannot write
  EXPECT_NE(errors.find("No space left"), std::string::npos) << errors;
  EXPECT_NE(errors.find("disk/frames"), std::string::npos) << "the message should name the folder or file: " << errors;
  EXPECT_GE(frameFileCount(folder_.path() / "disk/frames"), 5);
  EXPECT_TRUE(temporaries(folder_.path() / "disk/frames").empty()) << "a failed write left its temporary";
  expectOnlyCompleteFrames("disk/frames");
}

// A CSV that does not fit, written by simulate to a file or to standard output, is a failure
// (exit 3, the reason and what is incomplete), never a CSV cut mid-row with exit 0; a --csv file leaves nothing
// behind (no CSV, no temporary).
TEST_F(ProcessFaults, ACsvThatDoesNotFitIsAFailureNotACutFile) {
  Mount disk(folder_.path() / "csv-disk", "size=64k");
  if (!disk.mounted()) GTEST_SKIP() << "mounting a tmpfs is not permitted here (needs root)";
  const std::string simulate = testing::shellQuoted(linkageBinary()) + " simulate small.json --dt 0.0001";
  const ProcessResult toFile = testing::runShell(simulate + " --csv csv-disk/out.csv", folder_.path(), 120);
  EXPECT_EQ(toFile.code, 3) << toFile.err;
  EXPECT_NE(toFile.err.find("No space left"), std::string::npos) << toFile.err;
  EXPECT_TRUE(fs::is_empty(folder_.path() / "csv-disk")) << "a failed --csv left a file";
  const ProcessResult toStdout = testing::runShell(simulate + " > csv-disk/stdout.csv", folder_.path(), 120);
  EXPECT_EQ(toStdout.code, 3) << toStdout.err;
  EXPECT_NE(toStdout.err.find("cannot write the CSV to standard output: No space left on device"), std::string::npos)
      << toStdout.err;
  EXPECT_NE(toStdout.err.find("incomplete"), std::string::npos) << toStdout.err;
}

// Frames that cannot fit are refused before the first is written, with the numbers in the message.
TEST_F(ProcessFaults, RenderThatCannotFitIsRefusedUpFront) {
  Mount disk(folder_.path() / "small-disk", "size=64k");
  if (!disk.mounted()) GTEST_SKIP() << "mounting a tmpfs is not permitted here (needs root)";
  ASSERT_GT(kFrames * reference_.at("frame_00000.png").size(), 64u * 1024u)
      << "the test needs frames that do not fit into 64 kB";
  const ProcessResult status = render({"--quiet", "--out", "small-disk/frames"});
  const std::string& errors = status.err;
  EXPECT_EQ(status.code, 2) << errors;
  EXPECT_NE(errors.find("small-disk/frames: " + std::to_string(kFrames) + " frames of 160x90 need about"),
            std::string::npos)
      << errors;
  EXPECT_NE(errors.find("kB are free there"), std::string::npos) << errors;
  EXPECT_FALSE(fs::exists(folder_.path() / "small-disk/frames")) << "a refused render must write nothing";
}

// Out of inodes while rendering: the error names the cause, the frames finished so far stay listed in the
// manifest (rewritten in place: there is no inode for a temporary), and validate names the cause too.
TEST_F(ProcessFaults, NoFreeInodesKeepsTheFinishedFramesResumable) {
  Mount disk(folder_.path() / "few-inodes", "size=16m,nr_inodes=64");
  if (!disk.mounted()) GTEST_SKIP() << "mounting a tmpfs is not permitted here (needs root)";
  ChildProcess child(linkageBinary(), {"render", "small.json", "--quiet", "--out", "few-inodes/frames"},
                     folder_.path());
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (child.running() && frameFileCount(folder_.path() / "few-inodes/frames") < 5 &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  child.sendSignal(SIGSTOP);
  for (int k = 0;; ++k) {  // use up every inode
    std::FILE* file = std::fopen((folder_.path() / "few-inodes" / ("inode" + std::to_string(k))).c_str(), "w");
    if (!file) break;
    std::fclose(file);
  }
  child.sendSignal(SIGCONT);
  const ProcessResult status = child.wait(120);
  ASSERT_FALSE(status.timedOut);
  EXPECT_EQ(status.code, 3) << status.err;
  EXPECT_NE(status.err.find("no free inodes"), std::string::npos) << status.err;
  const int finished = frameFileCount(folder_.path() / "few-inodes/frames");
  EXPECT_GE(finished, 5);
  expectOnlyCompleteFrames("few-inodes/frames");
  // The manifest lists (nearly) every finished frame: the last flush went in place.
  const std::string manifest = readFile(folder_.path() / "few-inodes/frames/manifest.json");
  int listed = 0;
  for (std::size_t at = manifest.find("\"file\""); at != std::string::npos; at = manifest.find("\"file\"", at + 1))
    ++listed;
  EXPECT_EQ(listed, finished) << manifest;
  const ProcessResult validate = testing::runLinkage({"validate", "small.json", "--set", "output.folder=\"few-inodes/x\""},
                                            folder_.path());
  EXPECT_EQ(validate.code, 2);
  EXPECT_NE(validate.err.find("no space left (or no free inodes)"), std::string::npos) << validate.err;
  // Inodes freed, --resume renders only what is missing and ends with the uninterrupted render's bytes.
  for (int k = 0; fs::remove(folder_.path() / "few-inodes" / ("inode" + std::to_string(k))); ++k) {
  }
  const ProcessResult resumed = render({"--resume", "--out", "few-inodes/frames"});
  EXPECT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find(std::to_string(finished) + " already complete"), std::string::npos) << resumed.err;
  EXPECT_EQ(renderFiles(folder_.path() / "few-inodes/frames"), reference_);
}

TEST_F(ProcessFaults, ReadOnlyFolderGivesAClearErrorAndKeepsItsFrames) {
  Mount disk(folder_.path() / "ro", "size=4m");
  if (!disk.mounted()) GTEST_SKIP() << "mounting a tmpfs is not permitted here (needs root)";
  // A first shard completes, then the folder becomes read-only (root ignores permission bits).
  ASSERT_EQ(render({"--quiet", "--frames", "0:5", "--out", "ro/frames"}).code, 0);
  const auto before = renderFiles(folder_.path() / "ro/frames");
  ASSERT_TRUE(disk.remountReadOnly());
  const ProcessResult status = render({"--quiet", "--resume", "--out", "ro/frames"});
  const std::string& errors = status.err;
  EXPECT_EQ(status.code, 2) << errors;  // refused up front, nothing attempted
  EXPECT_NE(errors.find("ro/frames"), std::string::npos) << errors;
  EXPECT_TRUE(renderFiles(folder_.path() / "ro/frames") == before);
  expectOnlyCompleteFrames("ro/frames");
}

}  // namespace
}  // namespace sl

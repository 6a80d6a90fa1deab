// The manifest: sorted deterministic content, resume checks against the files, refusal to mix renders,
// and concurrent writers (threads and processes, one of them SIGKILLed) never losing entries.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <thread>

#include "output/atomic_file.hpp"
#include "output/frame_manifest.hpp"
#include "output/sha256.hpp"
#include "support/files.hpp"
#include "support/temp_folder.hpp"

namespace sl::output {
namespace {

using testing::readFile;
using testing::TempFolder;

const nlohmann::json kInfo{{"scene", "test"}, {"size", "32x24"}};

// Writes a small "frame file" for frame k and records it, as a sink does.
void writeFrame(FrameManifest& manifest, const std::string& folder, int k) {
  const std::string name = "frame_" + std::to_string(k) + ".png";
  const std::string content = "pixels of frame " + std::to_string(k);
  writeFileAtomically(folder + "/" + name, content);
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(content.data());
  manifest.record({k, name, sha256Hex(bytes, content.size()), sha256Hex(bytes, content.size())});
}

TEST(FrameManifest, EntriesSortedAndCheckedAgainstFiles) {
  const TempFolder temp;
  const std::string folder = temp.path();
  {
    FrameManifest manifest(folder, kInfo);
    manifest.addRenderer("llvmpipe", "4.5");
    for (int k : {7, 2, 5}) writeFrame(manifest, folder, k);
    manifest.flush();
  }
  const auto json = nlohmann::json::parse(readFile(folder + "/manifest.json"));
  ASSERT_EQ(json.at("frames").size(), 3u);
  EXPECT_EQ(json["frames"][0]["frame"], 2);
  EXPECT_EQ(json["frames"][2]["frame"], 7);
  EXPECT_EQ(json["renderers"][0], "llvmpipe | 4.5");
  EXPECT_EQ(json["info"], kInfo);

  FrameManifest resumed(folder, kInfo);
  EXPECT_TRUE(resumed.isFrameComplete(5));
  EXPECT_FALSE(resumed.isFrameComplete(3));  // never recorded
  writeFileAtomically(folder + "/frame_5.png", std::string("truncated"));
  EXPECT_FALSE(resumed.isFrameComplete(5));  // file no longer matches
  std::filesystem::remove(folder + "/frame_7.png");
  EXPECT_FALSE(resumed.isFrameComplete(7));  // file gone
}

TEST(FrameManifest, RefusesAFolderOfAnotherRender) {
  const TempFolder temp;
  const std::string folder = temp.path();
  {
    FrameManifest manifest(folder, kInfo);
    writeFrame(manifest, folder, 0);
  }
  try {
    FrameManifest other(folder, {{"scene", "different"}});
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("different render"), std::string::npos) << e.what();
  }
}

TEST(FrameManifest, MalformedManifestIsNamed) {
  const TempFolder temp;
  const std::string folder = temp.path();
  writeFileAtomically(folder + "/manifest.json", std::string("{ not json"));
  try {
    FrameManifest manifest(folder, kInfo);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(folder + "/manifest.json"), std::string::npos) << e.what();
  }
}

// Shards rendered concurrently (two processes, plus two threads in this one) give the same bytes as
// one process writing every frame.
TEST(FrameManifest, ConcurrentShardsEqualASingleRun) {
  const TempFolder temp;
  const std::string sharded = temp / "sharded";
  const std::string single = temp / "single";
  std::vector<pid_t> children;
  for (int shard = 0; shard < 2; ++shard) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      int status = 0;
      try {
        FrameManifest manifest(sharded, kInfo);
        manifest.setFlushInterval(std::chrono::milliseconds(0));  // a merge per frame: maximal contention
        for (int k = shard; k < 120; k += 4) writeFrame(manifest, sharded, k);
        manifest.flush();
      } catch (...) {
        status = 1;
      }
      ::_exit(status);
    }
    children.push_back(pid);
  }
  std::vector<std::thread> threads;
  FrameManifest shared(sharded, kInfo);
  shared.setFlushInterval(std::chrono::milliseconds(0));
  for (int shard = 2; shard < 4; ++shard)
    threads.emplace_back([&, shard] {
      for (int k = shard; k < 120; k += 4) writeFrame(shared, sharded, k);
    });
  for (auto& t : threads) t.join();
  shared.flush();
  for (pid_t pid : children) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  }
  {
    FrameManifest manifest(single, kInfo);
    for (int k = 0; k < 120; ++k) writeFrame(manifest, single, k);
  }
  EXPECT_EQ(readFile(sharded + "/manifest.json"), readFile(single + "/manifest.json"));
}

// reload() (folder lock, then the object's mutex) racing record() (mutex, then folder lock) must not deadlock.
TEST(FrameManifest, ReloadWhileRecording) {
  const TempFolder temp;
  const std::string folder = temp.path();
  FrameManifest manifest(folder, kInfo);
  manifest.setFlushInterval(std::chrono::milliseconds(0));
  std::thread reader([&] {
    for (int k = 0; k < 200; ++k) manifest.reload();
  });
  for (int k = 0; k < 200; ++k) writeFrame(manifest, folder, k);
  reader.join();
  manifest.flush();
  for (int k = 0; k < 200; ++k) EXPECT_TRUE(manifest.isFrameComplete(k)) << k;
}

// A writer killed with SIGKILL at an arbitrary moment leaves a valid manifest whose every entry is complete.
TEST(FrameManifest, SurvivesSigkill) {
  const TempFolder temp;
  const std::string folder = temp.path();
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    FrameManifest manifest(folder, kInfo);
    manifest.setFlushInterval(std::chrono::milliseconds(5));
    for (int k = 0;; ++k) writeFrame(manifest, folder, k % 5000);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  FrameManifest resumed(folder, kInfo);  // parses, or this throws
  const auto json = nlohmann::json::parse(readFile(folder + "/manifest.json"));
  EXPECT_GT(json.at("frames").size(), 0u);
  for (const auto& entry : json.at("frames")) EXPECT_TRUE(resumed.isFrameComplete(entry.at("frame").get<int>()));
}

}  // namespace
}  // namespace sl::output

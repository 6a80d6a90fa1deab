// The manifest: sorted deterministic content, resume checks against the files, refusal to mix renders,
// and concurrent writers (threads and processes, one of them SIGKILLed) never losing entries.

#include <gtest/gtest.h>
#include <signal.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include "output/atomic_file.hpp"
#include "output/frame_manifest.hpp"
#include "output/sha256.hpp"
#include "support/files.hpp"
#include "support/temp_folder.hpp"

namespace sl {
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
    manifest.addRenderer("llvmpipe | 4.5", "egl");
    for (int k : {7, 2, 5}) writeFrame(manifest, folder, k);
    manifest.flush();
  }
  const auto json = nlohmann::json::parse(readFile(folder + "/manifest.json"));
  ASSERT_EQ(json.at("frames").size(), 3u);
  EXPECT_EQ(json["frames"][0]["frame"], 2);
  EXPECT_EQ(json["frames"][2]["frame"], 7);
  EXPECT_EQ(json["renderers"][0], "llvmpipe | 4.5");
  EXPECT_EQ(json["backends"][0], "egl");
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
    EXPECT_NE(std::string(e.what()).find("not of this one"), std::string::npos) << e.what();
  }
}

// Frames of one render drawn by another renderer (llvmpipe generating code for another CPU: docs/rendering.md,
// "Across machines") are not joined: refused before this process draws, and at a flush that finds them (a shard
// that started at the same time). The backend alone is not compared: EGL and OSMesa are the same llvmpipe.
TEST(FrameManifest, RefusesFramesOfAnotherRenderer) {
  const TempFolder temp;
  const std::string folder = temp.path();
  {
    FrameManifest first(folder, kInfo);
    first.addRenderer("llvmpipe | 4.5 | cpu x86-64 avx2", "egl");
    writeFrame(first, folder, 0);
  }
  {
    FrameManifest sameRendererOtherBackend(folder, kInfo);
    sameRendererOtherBackend.addRenderer("llvmpipe | 4.5 | cpu x86-64 avx2", "osmesa");
    writeFrame(sameRendererOtherBackend, folder, 1);
    sameRendererOtherBackend.flush();
  }
  FrameManifest other(folder, kInfo);
  try {
    other.addRenderer("llvmpipe | 4.5 | cpu x86-64 sse4.1", "egl");
    FAIL() << "joined frames of another renderer";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("holds frames drawn by llvmpipe | 4.5 | cpu x86-64 avx2"), std::string::npos)
        << e.what();
  }
  // A shard of another renderer that checked an empty folder, then flushes after the first one wrote: refused.
  const TempFolder race;
  FrameManifest late(race.path(), kInfo);
  late.addRenderer("llvmpipe | 4.5 | cpu x86-64 sse4.1", "egl");
  {
    FrameManifest early(race.path(), kInfo);
    early.addRenderer("llvmpipe | 4.5 | cpu x86-64 avx2", "egl");
    writeFrame(early, race.path(), 0);
  }
  writeFrame(late, race.path(), 1);
  EXPECT_THROW(late.flush(), std::runtime_error);
  const auto json = nlohmann::json::parse(readFile(race.path() / "manifest.json"));
  EXPECT_EQ(json.at("frames").size(), 1u);
  EXPECT_EQ(json.at("renderers").size(), 1u);
  const auto joined = nlohmann::json::parse(readFile(temp.path() / "manifest.json"));
  EXPECT_EQ(joined.at("frames").size(), 2u);
  EXPECT_EQ(joined.at("backends"), nlohmann::json::array({"egl", "osmesa"}));
}

// The edit-render loop: a whole render of another scene takes the folder over, deleting the frames the old
// manifest lists (and nothing else); a render of the same scene merges as before.
TEST(FrameManifest, SupersedeReplacesAnotherRenderAndKeepsTheSameOne) {
  const TempFolder temp;
  const std::string folder = temp.path();
  {
    FrameManifest manifest(folder, kInfo);
    for (int k = 0; k < 3; ++k) writeFrame(manifest, folder, k);
  }
  writeFileAtomically(folder + "/notes.txt", std::string("mine"));
  {
    FrameManifest same(folder, kInfo, "manifest.json", FrameManifest::Existing::merge, FrameManifest::Claim::supersede);
    EXPECT_FALSE(same.supersededInfo());
    EXPECT_TRUE(same.isFrameComplete(2));
  }
  const nlohmann::json other{{"scene", "edited"}, {"size", "32x24"}};
  FrameManifest replacing(folder, other, "manifest.json", FrameManifest::Existing::merge,
                          FrameManifest::Claim::supersede);
  ASSERT_TRUE(replacing.supersededInfo());
  EXPECT_EQ(*replacing.supersededInfo(), kInfo);
  EXPECT_EQ(replacing.supersededFrames(), 3);
  for (int k = 0; k < 3; ++k) EXPECT_FALSE(std::filesystem::exists(folder + "/frame_" + std::to_string(k) + ".png"));
  EXPECT_TRUE(std::filesystem::exists(folder + "/notes.txt"));
  EXPECT_FALSE(replacing.isFrameComplete(0));
  EXPECT_NE(readFile(folder + "/manifest.json").find("edited"), std::string::npos);
  // While it runs, neither a shard of the old scene nor a whole render of a third one gets in.
  EXPECT_THROW(FrameManifest(folder, kInfo), std::runtime_error);
  try {
    FrameManifest third(folder, {{"scene", "third"}}, "manifest.json", FrameManifest::Existing::merge,
                        FrameManifest::Claim::supersede);
    FAIL() << "a running render was replaced";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("still running"), std::string::npos) << e.what();
  }
}

// A process holding the manifest lock for ever (stopped with SIGSTOP, hung) makes others give up after the
// bound, naming the lock, rather than wait silently for ever.
TEST(FrameManifest, LockWaitsAreBoundedAndNamed) {
  const TempFolder temp;
  const std::string folder = temp.path();
  { FrameManifest manifest(folder, kInfo); }
  const pid_t holder = fork();
  if (holder == 0) {
    const int fd = ::open((folder + "/.manifest.json.lock").c_str(), O_RDWR);
    ::flock(fd, LOCK_EX);
    ::raise(SIGSTOP);
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(holder, &status, WUNTRACED), holder);
  ASSERT_TRUE(WIFSTOPPED(status));
  const auto start = std::chrono::steady_clock::now();
  try {
    FrameManifest blocked(folder, kInfo, "manifest.json", FrameManifest::Existing::merge, FrameManifest::Claim::join,
                          nullptr, 1.5);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(".manifest.json.lock"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  ::kill(holder, SIGKILL);
  waitpid(holder, &status, 0);
}

TEST(FrameManifest, MalformedManifestIsNamed) {
  const TempFolder temp;
  const std::string folder = temp.path();
  writeFileAtomically(folder + "/manifest.json", std::string("{ not json"));
  try {
    FrameManifest manifest(folder, kInfo);
    FAIL() << "no error";
  } catch (const ManifestInvalid& e) {
    EXPECT_NE(std::string(e.what()).find(folder + "/manifest.json"), std::string::npos) << e.what();
  }
}

// Entries read back are checked like a scene: each malformed one is refused naming the file and the JSON path.
TEST(FrameManifest, MalformedEntriesAreRefusedWithTheirPath) {
  const TempFolder temp;
  const std::string folder = temp.path();
  const std::string hash(64, 'a');
  const std::vector<std::pair<std::string, std::string>> cases{
      {R"({"frame": 1e12, "file": "f.png", "fileSha256": "H"})", "frames[0].frame: found 1000000000000.0; expected an integer from 0 to 999999"},
      {R"({"frame": 1000000, "file": "f.png", "fileSha256": "H"})", "frames[0].frame: found 1000000; expected an integer"},
      {R"({"frame": "x", "file": "f.png", "fileSha256": "H"})", "frames[0].frame: found \"x\"; expected an integer"},
      {R"({"frame": -3, "file": "f.png", "fileSha256": "H"})", "frames[0].frame: found -3;"},
      {R"({"file": "f.png", "fileSha256": "H"})", "frames[0].frame: missing"},
      {R"({"frame": 1, "file": "../x.png", "fileSha256": "H"})", "frames[0].file: found \"../x.png\"; expected a file name"},
      {R"({"frame": 1, "file": "f.png", "fileSha256": "ABC"})", "frames[0].fileSha256: found \"ABC\"; expected a SHA-256"},
      {R"({"frame": 1, "file": "f.png"})", "frames[0]: file without fileSha256"},
      {R"({"frame": 1})", "frames[0]: no hash"},
      {R"({"frame": 1, "pixelSha256": "H", "colour": 3})", "frames[0].colour: unknown key"},
      {R"({"frame": 1, "pixelSha256": "H"}, {"frame": 1, "pixelSha256": "H"})", "frames[1].frame: frame 1 is listed twice"},
      {R"(7)", "frames[0]: found 7; expected an object"},
  };
  for (auto [entries, expected] : cases) {
    for (std::size_t at; (at = entries.find("\"H\"")) != std::string::npos;) entries.replace(at, 3, "\"" + hash + "\"");
    const nlohmann::json manifest{{"format", "sphere-linkages frame manifest 2"},
                                  {"info", kInfo},
                                  {"renderers", nlohmann::json::array()},
                                  {"frames", nlohmann::json::parse("[" + entries + "]")}};
    writeFileAtomically(folder + "/manifest.json", manifest.dump(1));
    try {
      FrameManifest reopened(folder, kInfo);
      ADD_FAILURE() << "accepted " << entries;
    } catch (const ManifestInvalid& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("manifest " + folder + "/manifest.json: "), std::string::npos) << message;
      EXPECT_NE(message.find(expected), std::string::npos) << message;
    }
  }
}

// A PNG frame listed without its file (edited, or foreign) is not complete: --resume draws it again.
TEST(FrameManifest, AnEntryWithoutItsFileIsNotComplete) {
  const TempFolder temp;
  const std::string folder = temp.path();
  {
    FrameManifest manifest(folder, kInfo);
    for (int k : {0, 1}) writeFrame(manifest, folder, k);
  }
  nlohmann::json json = nlohmann::json::parse(readFile(folder + "/manifest.json"));
  json["frames"][1].erase("file");
  json["frames"][1].erase("fileSha256");
  json["frames"][1]["pixelSha256"] = std::string(64, 'b');
  writeFileAtomically(folder + "/manifest.json", json.dump(1));
  FrameManifest resumed(folder, kInfo);
  EXPECT_TRUE(resumed.isFrameComplete(0));
  EXPECT_FALSE(resumed.isFrameComplete(1));
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
  // The moment is the first flush with a frame in it (an event, not a time), plus whatever the writer does
  // while this process notices it.
  while (!std::filesystem::exists(folder + "/manifest.json") ||
         nlohmann::json::parse(readFile(folder + "/manifest.json")).at("frames").empty())
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  FrameManifest resumed(folder, kInfo);  // parses, or this throws
  const auto json = nlohmann::json::parse(readFile(folder + "/manifest.json"));
  EXPECT_GT(json.at("frames").size(), 0u);
  for (const auto& entry : json.at("frames")) EXPECT_TRUE(resumed.isFrameComplete(entry.at("frame").get<int>()));
}

}  // namespace
}  // namespace sl

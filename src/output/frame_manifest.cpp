#include "output/frame_manifest.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

#include "output/atomic_file.hpp"
#include "output/sha256.hpp"

namespace sl::output {
namespace {

constexpr const char* kFormat = "sphere-linkages frame manifest 1";

// flock(2) on <folder>/.<manifest name>.lock for the lifetime of the object: serialises merges between
// processes. The manifest itself cannot carry the lock: each write replaces it with a new file.
class ManifestLock {
 public:
  ManifestLock(const std::string& folder, const std::string& manifestName) {
    const std::string path = folder + "/." + manifestName + ".lock";
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw std::runtime_error("cannot open lock file " + path + ": " + std::strerror(errno));
    while (::flock(fd_, LOCK_EX) != 0) {
      if (errno != EINTR) throw std::runtime_error("cannot lock " + path + ": " + std::strerror(errno));
    }
  }
  ~ManifestLock() {
    ::flock(fd_, LOCK_UN);
    ::close(fd_);
  }
  ManifestLock(const ManifestLock&) = delete;
  ManifestLock& operator=(const ManifestLock&) = delete;

 private:
  int fd_ = -1;
};

nlohmann::json toJson(const FrameEntry& e) {
  nlohmann::json j{{"frame", e.frame}, {"pixelSha256", e.pixelSha256}};
  if (!e.file.empty()) j["file"] = e.file, j["fileSha256"] = e.fileSha256;
  return j;
}

FrameEntry fromJson(const nlohmann::json& j) {
  return {j.at("frame").get<int>(), j.value("file", ""), j.at("pixelSha256").get<std::string>(),
          j.value("fileSha256", "")};
}

}  // namespace

FrameManifest::FrameManifest(std::string folder, nlohmann::json info, std::string fileName, Existing existing)
    : folder_(std::move(folder)),
      fileName_(std::move(fileName)),
      info_(std::move(info)),
      existing_(existing),
      lastFlush_(std::chrono::steady_clock::now()) {
  std::filesystem::create_directories(folder_);
  if (existing_ == Existing::merge) reload();
}

FrameManifest::~FrameManifest() {
  try {
    flush();
  } catch (...) {
    // A destructor must not throw; callers who care call flush() themselves and see the error.
  }
}

nlohmann::json FrameManifest::emptyManifest() const {
  return {{"format", kFormat},
          {"info", info_},
          {"renderers", nlohmann::json::array()},
          {"frames", nlohmann::json::array()}};
}

nlohmann::json FrameManifest::readLocked() const {
  std::ifstream in(path());
  if (!in) return emptyManifest();
  nlohmann::json manifest;
  try {
    manifest = nlohmann::json::parse(in);
    if (manifest.at("format") != kFormat) throw std::runtime_error("unknown format " + manifest.at("format").dump());
    manifest.at("frames").get_ref<const nlohmann::json::array_t&>();
  } catch (const std::exception& e) {
    throw std::runtime_error("manifest " + path() + " is not a frame manifest: " + e.what());
  }
  if (manifest.at("info") != info_)
    throw std::runtime_error("manifest " + path() + " belongs to a different render: its info is " +
                             manifest.at("info").dump() + ", this render's is " + info_.dump());
  return manifest;
}

void FrameManifest::reload() {
  nlohmann::json manifest;
  {
    // The manifest lock is released before taking mutex_: flushLocked() takes them in the other order.
    ManifestLock lock(folder_, fileName_);
    manifest = readLocked();
  }
  std::lock_guard guard(mutex_);
  for (const auto& j : manifest.at("frames")) {
    const FrameEntry e = fromJson(j);
    known_[e.frame] = e;
  }
}

void FrameManifest::addRenderer(const std::string& glRenderer, const std::string& glVersion) {
  std::lock_guard guard(mutex_);
  renderers_.insert(glRenderer + " | " + glVersion);
}

void FrameManifest::record(const FrameEntry& entry) {
  std::lock_guard guard(mutex_);
  pending_[entry.frame] = entry;
  // A replaced manifest describes a whole file: written once, by flush(), never part-way.
  if (existing_ == Existing::merge && std::chrono::steady_clock::now() - lastFlush_ >= flushInterval_) flushLocked();
}

void FrameManifest::flush() {
  std::lock_guard guard(mutex_);
  flushLocked();
}

void FrameManifest::flushLocked() {
  lastFlush_ = std::chrono::steady_clock::now();
  if (pending_.empty()) return;
  // merge: what other processes wrote since, plus ours, under the lock; replace: ours alone (known_ holds
  // earlier flushes), with no lock, as nothing is merged.
  std::optional<ManifestLock> lock;
  if (existing_ == Existing::merge) lock.emplace(folder_, fileName_);
  nlohmann::json manifest = lock ? readLocked() : emptyManifest();
  std::map<int, FrameEntry> merged = lock ? std::map<int, FrameEntry>{} : known_;
  for (const auto& j : manifest.at("frames")) merged[j.at("frame").get<int>()] = fromJson(j);
  for (const auto& [frame, e] : pending_) merged[frame] = e;
  std::set<std::string> renderers = renderers_;
  for (const auto& r : manifest.at("renderers")) renderers.insert(r.get<std::string>());
  manifest["renderers"] = renderers;
  manifest["frames"] = nlohmann::json::array();
  for (const auto& [frame, e] : merged) manifest["frames"].push_back(toJson(e));
  writeFileAtomically(path(), manifest.dump(1) + "\n", Sync::data);
  known_ = std::move(merged);
  pending_.clear();
}

std::optional<FrameEntry> FrameManifest::entry(int frame) const {
  std::lock_guard guard(mutex_);
  if (auto p = pending_.find(frame); p != pending_.end()) return p->second;
  if (auto k = known_.find(frame); k != known_.end()) return k->second;
  return std::nullopt;
}

bool FrameManifest::isFrameComplete(int frame) const {
  const auto e = entry(frame);
  if (!e) return false;
  if (e->file.empty()) return true;  // video frames: the hash of the pixels is all there is
  return sha256OfFile(folder_ + "/" + e->file) == e->fileSha256;
}

}  // namespace sl::output

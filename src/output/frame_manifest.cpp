#include "output/frame_manifest.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <stdexcept>
#include <thread>

#include "contracts/limits.hpp"
#include "output/atomic_file.hpp"
#include "output/sha256.hpp"

namespace sl {
namespace {

constexpr const char* kFormat = "sphere-linkages frame manifest 2";
constexpr const char* kFormat1 = "sphere-linkages frame manifest 1";  // read, never joined (see the header)

// flock(2) with a bounded wait: polls, says once (after a second) what it waits for, and gives up after
// maxWait seconds naming the file. A process stopped while holding a lock must not hang the others.
void lockWithTimeout(int fd, int operation, const std::string& path, double maxWait, bool (*cancelled)() = nullptr) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  bool announced = false;
  while (::flock(fd, operation | LOCK_NB) != 0) {
    if (errno != EWOULDBLOCK && errno != EINTR) throw std::runtime_error("cannot lock " + path + ": " + std::strerror(errno));
    if (cancelled && cancelled()) throw LockWaitCancelled("stopped waiting for " + path);
    const double waited = std::chrono::duration<double>(Clock::now() - start).count();
    if (waited > maxWait)
      throw std::runtime_error("gave up after " + std::to_string(int(maxWait)) + " s waiting for " +
                               path + ": another process holds it (a render stopped or hung in this folder?)");
    if (!announced && waited > 1.0) {
      std::cerr << "waiting for " << path << ", held by another process (at most " << int(maxWait)
                << " s; LINKAGE_LOCK_WAIT sets the bound)\n";
      announced = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

int openLockFile(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot open lock file " + path + ": " + std::strerror(errno));
  return fd;
}

// flock(2) on <folder>/.<manifest name>.lock for the lifetime of the object: serialises merges between
// processes. The manifest itself cannot carry the lock: each write replaces it with a new file.
class ManifestLock {
 public:
  ManifestLock(const std::string& folder, const std::string& manifestName, double maxWait,
               bool (*cancelled)() = nullptr) {
    const std::string path = folder + "/." + manifestName + ".lock";
    fd_ = openLockFile(path);
    try {
      lockWithTimeout(fd_, LOCK_EX, path, maxWait, cancelled);
    } catch (...) {
      ::close(fd_);
      throw;
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

// Overwrites an existing file's content without creating anything; false if that is impossible too.
bool rewriteInPlace(const std::string& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) return false;
  bool ok = true;
  for (std::size_t written = 0; ok && written < text.size();) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    ok = n > 0;
    if (ok) written += static_cast<std::size_t>(n);
  }
  ok = ::fsync(fd) == 0 && ok;
  return ::close(fd) == 0 && ok;
}

std::string describeRender(const nlohmann::json& info) {
  if (info.is_object() && info.contains("scene") && info["scene"].is_string())
    return "scene \"" + info["scene"].get<std::string>() + "\"";
  return "info " + info.dump();
}

nlohmann::json toJson(const FrameEntry& e) {
  nlohmann::json j{{"frame", e.frame}};
  if (!e.pixelSha256.empty()) j["pixelSha256"] = e.pixelSha256;
  if (!e.file.empty()) j["file"] = e.file, j["fileSha256"] = e.fileSha256;
  return j;
}

// Of an entry already checked by parseManifest (readAnyLocked gives only those).
FrameEntry fromJson(const nlohmann::json& j) {
  return {j.at("frame").get<int>(), j.value("file", ""), j.value("pixelSha256", ""), j.value("fileSha256", "")};
}

[[noreturn]] void invalid(const std::string& path, const std::string& where, const std::string& what) {
  throw ManifestInvalid("manifest " + path + ": " + where + ": " + what);
}

std::string shown(const nlohmann::json& value) {
  std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return text.size() > 80 ? text.substr(0, 77) + "..." : text;
}

bool isSha256Hex(const std::string& text) {
  return text.size() == 64 && text.find_first_not_of("0123456789abcdef") == std::string::npos;
}

std::string hashField(const nlohmann::json& j, const char* key, const std::string& path, const std::string& where) {
  if (!j.contains(key)) return "";
  const nlohmann::json& value = j.at(key);
  if (!value.is_string() || !isSha256Hex(value.get<std::string>()))
    invalid(path, where + "." + key, "found " + shown(value) + "; expected a SHA-256 as 64 lowercase hex digits");
  return value.get<std::string>();
}

FrameEntry parseEntry(const nlohmann::json& j, const std::string& path, const std::string& where) {
  if (!j.is_object()) invalid(path, where, "found " + shown(j) + "; expected an object {\"frame\": ..., ...}");
  for (const auto& [key, value] : j.items())
    if (key != "frame" && key != "file" && key != "fileSha256" && key != "pixelSha256")
      invalid(path, where + "." + key, "unknown key; expected frame, file, fileSha256 and/or pixelSha256");
  FrameEntry e;
  const std::string range = "from 0 to " + std::to_string(limits::kMaxFrames - 1);
  if (!j.contains("frame")) invalid(path, where + ".frame", "missing; expected an integer " + range);
  const nlohmann::json& frame = j.at("frame");
  if (!frame.is_number_integer() ||
      (frame.is_number_unsigned() ? frame.get<std::uint64_t>() >= std::uint64_t(limits::kMaxFrames)
                                  : (frame.get<std::int64_t>() < 0 || frame.get<std::int64_t>() >= limits::kMaxFrames)))
    invalid(path, where + ".frame", "found " + shown(frame) + "; expected an integer " + range);
  e.frame = static_cast<int>(frame.get<std::int64_t>());
  if (j.contains("file")) {
    const nlohmann::json& file = j.at("file");
    const std::string name = file.is_string() ? file.get<std::string>() : "";
    if (name.empty() || name[0] == '.' || name.find('/') != std::string::npos || name.find('\0') != std::string::npos)
      invalid(path, where + ".file", "found " + shown(file) + "; expected a file name inside the folder");
    e.file = name;
  }
  e.fileSha256 = hashField(j, "fileSha256", path, where);
  e.pixelSha256 = hashField(j, "pixelSha256", path, where);
  if (e.file.empty() != e.fileSha256.empty())
    invalid(path, where, e.file.empty() ? "fileSha256 without a file; expected both or neither"
                                        : "file without fileSha256; expected both or neither");
  if (e.fileSha256.empty() && e.pixelSha256.empty())
    invalid(path, where, "no hash; expected file with fileSha256 (a PNG frame) or pixelSha256 (a video frame)");
  return e;
}

}  // namespace

ManifestContents parseManifest(const nlohmann::json& manifest, const std::string& path) {
  if (!manifest.is_object()) invalid(path, "(top)", "found " + shown(manifest) + "; expected an object");
  ManifestContents contents;
  const nlohmann::json* format = manifest.contains("format") ? &manifest.at("format") : nullptr;
  if (!format || (*format != kFormat && *format != kFormat1))
    invalid(path, "format", "found " + (format ? shown(*format) : std::string("nothing")) + "; expected \"" + kFormat +
                                "\" (or format 1 of earlier versions)");
  contents.format = *format == kFormat ? 2 : 1;
  if (!manifest.contains("info")) invalid(path, "info", "missing; expected what identifies the render");
  contents.info = manifest.at("info");
  const nlohmann::json* renderers = manifest.contains("renderers") ? &manifest.at("renderers") : nullptr;
  if (!renderers || !renderers->is_array()) invalid(path, "renderers", "expected an array of strings");
  for (std::size_t i = 0; i < renderers->size(); ++i) {
    if (!(*renderers)[i].is_string())
      invalid(path, "renderers[" + std::to_string(i) + "]", "found " + shown((*renderers)[i]) + "; expected a string");
    contents.renderers.push_back((*renderers)[i].get<std::string>());
  }
  if (manifest.contains("backends")) {  // since 0.5; older manifests have none
    const nlohmann::json& backends = manifest.at("backends");
    if (!backends.is_array()) invalid(path, "backends", "found " + shown(backends) + "; expected an array of strings");
    for (std::size_t i = 0; i < backends.size(); ++i) {
      if (!backends[i].is_string())
        invalid(path, "backends[" + std::to_string(i) + "]", "found " + shown(backends[i]) + "; expected a string");
      contents.backends.push_back(backends[i].get<std::string>());
    }
  }
  const nlohmann::json* frames = manifest.contains("frames") ? &manifest.at("frames") : nullptr;
  if (!frames || !frames->is_array()) invalid(path, "frames", "expected an array of frame entries");
  for (std::size_t i = 0; i < frames->size(); ++i) {
    const std::string where = "frames[" + std::to_string(i) + "]";
    FrameEntry e = parseEntry((*frames)[i], path, where);
    if (contents.frames.count(e.frame))
      invalid(path, where + ".frame", "frame " + std::to_string(e.frame) + " is listed twice; expected each once");
    contents.frames[e.frame] = std::move(e);
  }
  return contents;
}

ManifestContents readManifestFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ManifestInvalid("manifest " + path + ": cannot read");
  nlohmann::json manifest;
  try {
    manifest = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw ManifestInvalid("manifest " + path + ": not JSON (" + e.what() + ")");
  }
  return parseManifest(manifest, path);
}

FrameManifest::FrameManifest(std::string folder, nlohmann::json info, std::string fileName, Existing existing,
                             Claim claim, bool (*cancelled)(), double lockWaitSeconds)
    : folder_(std::move(folder)),
      fileName_(std::move(fileName)),
      info_(std::move(info)),
      lockWaitSeconds_(lockWaitSeconds),
      existing_(existing),
      claim_(claim),
      lastFlush_(std::chrono::steady_clock::now()) {
  std::filesystem::create_directories(folder_);
  const std::string activePath = folder_ + "/." + fileName_ + ".active";
  activeFd_ = openLockFile(activePath);
  if (existing_ != Existing::merge) {
    // One render writes a video at a time: two finishing the same path would interleave their renames and
    // manifests (one render's video beside the other's manifest). The claim lasts until this manifest is written.
    try {
      lockWithTimeout(activeFd_, LOCK_EX, activePath, lockWaitSeconds_, cancelled);
    } catch (...) {
      ::close(activeFd_);
      activeFd_ = -1;
      throw;
    }
    return;
  }
  try {
    lockWithTimeout(activeFd_, LOCK_SH, activePath, lockWaitSeconds_, cancelled);  // waits only while a render takes the folder over
    {
      ManifestLock lock(folder_, fileName_, lockWaitSeconds_, cancelled);
      const nlohmann::json manifest = readAnyLocked();
      if (claim == Claim::supersede && manifest.at("info") != info_) supersedeLocked(manifest);
      // The manifest's file exists from the start: if the file system later runs out of inodes, the entries
      // can still be written into it in place (flushLocked), and the finished frames stay resumable.
      if (!std::filesystem::exists(path())) writeFileAtomically(path(), emptyManifest().dump(1) + "\n", Sync::data);
    }
    reload();
  } catch (...) {
    ::close(activeFd_);
    throw;
  }
}

FrameManifest::~FrameManifest() {
  try {
    flush();
  } catch (...) {
    // A destructor must not throw; callers who care call flush() themselves and see the error.
  }
  if (activeFd_ >= 0) ::close(activeFd_);  // releases the claim (shared, or a video's exclusive one)
}

void FrameManifest::supersedeLocked(const nlohmann::json& other) {
  // Exclusive only if no other render (of any scene) holds its shared claim: never waited for.
  if (::flock(activeFd_, LOCK_EX | LOCK_NB) != 0) {
    throw std::runtime_error("the folder " + folder_ + " holds a render of " + describeRender(other.at("info")) +
                             " that is still running; wait for it to finish, stop it, or render elsewhere (--out)");
  }
  for (const auto& j : other.at("frames")) {
    const std::string file = j.value("file", "");
    // Only names of this program's own pattern, inside the folder: a manifest is data, not a list of paths to trust.
    if (file.rfind("frame_", 0) != 0 || file.find('/') != std::string::npos) continue;
    std::error_code error;
    if (std::filesystem::remove(std::filesystem::path(folder_) / file, error)) ++supersededFrames_;
  }
  writeFileAtomically(path(), emptyManifest().dump(1) + "\n", Sync::data);
  supersededInfo_ = other.at("info");
  ::flock(activeFd_, LOCK_SH);  // back to a shared claim, like every render in the folder
}

nlohmann::json FrameManifest::emptyManifest() const {
  return {{"format", kFormat},
          {"info", info_},
          {"renderers", nlohmann::json::array()},
          {"backends", nlohmann::json::array()},
          {"frames", nlohmann::json::array()}};
}

nlohmann::json FrameManifest::readLocked() const {
  nlohmann::json manifest = readAnyLocked();
  if (manifest.at("format") == kFormat1)
    throw std::runtime_error("the folder " + folder_ + " holds frames of an earlier version of linkage (manifest " +
                             path() + " is format 1; its PNG files were written by another encoder): render it "
                             "again whole (without --frames or --resume), or use another --out");
  if (manifest.at("info") != info_)
    throw std::runtime_error("the folder " + folder_ + " holds a render of " + describeRender(manifest.at("info")) +
                             " (manifest " + path() + "), not of this one: " + manifest.at("info").dump() + " vs " +
                             info_.dump() +
                             ". Shards (--frames) and --resume only join the same render; a whole render (without "
                             "--frames or --resume) replaces it, or use another --out");
  checkSameRenderer(manifest);
  return manifest;
}

void FrameManifest::checkSameRenderer(const nlohmann::json& manifest) const {
  if (manifest.at("frames").empty()) return;
  std::set<std::string> mine;
  {
    std::lock_guard guard(renderersMutex_);
    mine = renderers_;
  }
  if (mine.empty()) return;  // not drawing (yet): nothing to compare
  for (const auto& theirs : manifest.at("renderers")) {
    if (mine.count(theirs.get<std::string>())) continue;
    throw std::runtime_error(
        "the folder " + folder_ + " holds frames drawn by " + theirs.get<std::string>() + "; this process draws with " +
        *mine.begin() +
        ". Their bytes may differ (llvmpipe generates code for the CPU it runs on: docs/rendering.md, \"Across "
        "machines\"), so they are not joined: draw the rest on a machine like the first, render it again whole here "
        "(without --frames or --resume), or use another --out");
  }
}

nlohmann::json FrameManifest::readAnyLocked() const {
  if (!std::filesystem::exists(path())) return emptyManifest();
  ManifestContents contents = readManifestFile(path());
  nlohmann::json manifest = emptyManifest();
  manifest["format"] = contents.format == 1 ? kFormat1 : kFormat;
  manifest["info"] = std::move(contents.info);
  manifest["renderers"] = contents.renderers;
  manifest["backends"] = contents.backends;
  for (const auto& [frame, e] : contents.frames) manifest["frames"].push_back(toJson(e));
  return manifest;
}

void FrameManifest::reload() {
  nlohmann::json manifest;
  {
    // The manifest lock is released before taking mutex_: flushLocked() takes them in the other order.
    ManifestLock lock(folder_, fileName_, lockWaitSeconds_);
    manifest = readLocked();
  }
  std::lock_guard guard(mutex_);
  for (const auto& j : manifest.at("frames")) {
    const FrameEntry e = fromJson(j);
    known_[e.frame] = e;
  }
}

void FrameManifest::addRenderer(const std::string& renderer, const std::string& backend) {
  {
    std::lock_guard guard(renderersMutex_);
    renderers_.insert(renderer);
    backends_.insert(backend);
  }
  if (existing_ != Existing::merge) return;
  bool superseded = false;
  {
    ManifestLock lock(folder_, fileName_, lockWaitSeconds_);
    const nlohmann::json manifest = readAnyLocked();
    // A render that takes the folder over (--replace) removes frames of another renderer as it removes another
    // render's; shards and --resume are refused below.
    superseded = claim_ == Claim::supersede && manifest.at("info") == info_ && !manifest.at("frames").empty() &&
                 manifest.at("renderers") != nlohmann::json::array({renderer});
    if (superseded) supersedeLocked(manifest);
    readLocked();  // refuses a folder of another renderer's frames before this process draws any
  }
  if (!superseded) return;
  {
    std::lock_guard guard(mutex_);
    known_.clear();
  }
  reload();
}

void FrameManifest::record(const FrameEntry& entry) {
  std::lock_guard guard(mutex_);
  pending_[entry.frame] = entry;
  // A replaced manifest describes a whole file: written once, by flush(), never part-way.
  // Every flush rewrites the whole manifest: with many frames, flush less often (0.5 s more per 10,000 frames),
  // so a 40,000-frame render does not spend its time rewriting megabytes of JSON.
  const auto interval = flushInterval_ * static_cast<long>(1 + known_.size() / 10000);
  if (existing_ == Existing::merge && std::chrono::steady_clock::now() - lastFlush_ >= interval) flushLocked();
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
  if (existing_ == Existing::merge) lock.emplace(folder_, fileName_, lockWaitSeconds_);
  nlohmann::json manifest = lock ? readLocked() : emptyManifest();
  std::map<int, FrameEntry> merged = lock ? std::map<int, FrameEntry>{} : known_;
  for (const auto& j : manifest.at("frames")) merged[j.at("frame").get<int>()] = fromJson(j);
  for (const auto& [frame, e] : pending_) merged[frame] = e;
  std::set<std::string> renderers, backends;
  {
    std::lock_guard guard(renderersMutex_);
    renderers = renderers_, backends = backends_;
  }
  for (const auto& r : manifest.at("renderers")) renderers.insert(r.get<std::string>());
  for (const auto& b : manifest.at("backends")) backends.insert(b.get<std::string>());
  manifest["renderers"] = renderers;
  manifest["backends"] = backends;
  manifest["frames"] = nlohmann::json::array();
  for (const auto& [frame, e] : merged) manifest["frames"].push_back(toJson(e));
  const std::string text = manifest.dump(1) + "\n";
  try {
    writeFileAtomically(path(), text, Sync::data);
  } catch (const FileSystemFull&) {
    // No inode for a temporary: rewrite the manifest's own file in place, so that the frames already finished
    // stay listed and --resume can use them once space is freed. Not atomic; only in this emergency, and
    // followed by the error.
    if (!rewriteInPlace(path(), text)) throw;
    known_ = std::move(merged);
    pending_.clear();
    throw;
  }
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
  if (e->file.empty() || e->fileSha256.empty()) return false;  // listed without its file: drawn again
  return sha256OfFile(folder_ + "/" + e->file) == e->fileSha256;
}

}  // namespace sl

#pragma once
// The manifest of a render folder: which frames are completely written, with checksums.
//
// API for the CLI (`linkage render --frames A:B --resume`), safe for several processes rendering
// disjoint frame ranges into the same folder at once, any of them killed at any moment:
//
//   FrameManifest manifest(folder, info);      // info: a JSON object identifying the render (scene
//                                              // hash, size, ...); throws if the folder's manifest
//                                              // was written for a different info
//   manifest.addRenderer(renderer, backend);   // what draws the frames (docs/rendering.md, "Across machines")
//   if (resume && manifest.isFrameComplete(k)) skip;   // entry present, file present, file SHA-256 matches
//   ... write frame_0000k.png atomically, then:
//   manifest.record({k, "frame_0000k.png", pixelSha, fileSha});  // buffered; thread-safe
//   manifest.flush();                          // also automatic every 0.5 s and in the destructor
//
// What an entry means (format 2): a PNG frame is listed with its file's name and the SHA-256 of the file's bytes,
// one hash per frame. The file is a function of the pixels and of the encoder, which the render's info names
// ("png": PngEncoder::identity), so within one encoder equal file hashes mean equal pixels; `linkage diff` of
// folders written by different encoders decodes the files and compares pixel hashes. A video frame is listed
// with the SHA-256 of its raw RGB pixels (rows top-down) only. Format 1 (before) listed both hashes for PNG
// frames: it is still read (diff, and a whole render replaces it), but never joined: its files came from another
// encoder, so such a folder is rendered again whole rather than resumed.
//
// Everything read back is checked like a scene: a malformed manifest or entry ends with ManifestInvalid naming
// the file and the JSON path (frames[3].frame: ...). An entry without a file (or whose file is gone or differs)
// is not complete: --resume draws that frame again.
//
// On disk: <folder>/manifest.json (or the given name), replaced atomically (temporary + rename) while
// holding flock(2) on <folder>/.manifest.json.lock (a hidden lock file per manifest), merging the entries already
// there, so concurrent shards never lose each other's entries. Entries are listed only after their file was renamed
// into place. Content is deterministic: frames sorted, keys sorted, no timestamps or host names; the union of shards
// equals a single run byte for byte. After SIGKILL at most the last 0.5 s of entries are missing (0.5 s more per
// 10,000 frames already listed, as each flush rewrites the whole manifest); their frames are simply rendered again
// on resume. A video render records pixel hashes only (file empty).
//
// One folder, one render. Every merge-mode manifest holds a shared flock(2) on <folder>/.<name>.active for its
// lifetime. Claim::join (shards, --resume) refuses a folder whose manifest belongs to another render.
// Claim::supersede (a whole new render) takes that folder over instead: only when no other render is active
// there (an exclusive lock on .active, never waited for), it deletes the frames the old manifest lists and
// starts an empty manifest of its own, all under the manifest lock; so a render of another scene can neither
// join nor replace it while it runs. Lock waits are bounded (limits::kMaxLockWaitSeconds) and announced.
//
// Existing::replace is for a file that is always written whole (a video): the manifest on disk, of any
// earlier render, is neither read nor merged but replaced by this render's entries, written only by flush()
// (record() does not flush part-way). Such a manifest holds an exclusive flock(2) on .<name>.active for its
// lifetime (waited for like the other locks): one render at a time writes a video and its manifest. A replaced manifest with no entries recorded is never written;
// a merged one exists (empty) from the start, so that it can be rewritten in place when the file system has no
// inode left for a temporary.

#include <chrono>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "contracts/limits.hpp"

namespace sl {

struct FrameEntry {
  int frame = 0;
  std::string file;         // name inside the folder; empty for video frames
  std::string pixelSha256;  // of the raw RGB pixels, rows top-down; video frames (and format 1 PNG entries)
  std::string fileSha256;   // of the file; empty for video frames
  bool operator==(const FrameEntry&) const = default;
};

// A manifest that cannot be trusted: not JSON, another format, or an entry out of shape. A bad input file,
// like a bad scene (the CLI's exit status 2).
struct ManifestInvalid : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// A manifest's content, checked: every entry well formed, frame numbers unique and in range.
// The manifest format this version writes; format 1 (earlier versions) is read, never joined.
inline constexpr int kCurrentManifestFormat = 2;

struct ManifestContents {
  int format = kCurrentManifestFormat;
  nlohmann::json info;
  // What drew the frames, each as "GL_RENDERER | GL_VERSION[ | cpu FEATURES]": what their bytes depend on
  // (docs/rendering.md, "Across machines"). Shards and --resume join only frames of one such renderer.
  std::vector<std::string> renderers;
  std::vector<std::string> backends;  // the GL backends ("egl", "osmesa", ...): for the reader, not compared
  std::map<int, FrameEntry> frames;
};
// `path` names the file in messages. Throws ManifestInvalid.
ManifestContents parseManifest(const nlohmann::json& manifest, const std::string& path);
// Reads and parses; throws ManifestInvalid if the file cannot be read or parsed.
ManifestContents readManifestFile(const std::string& path);

// A lock wait given up at the caller's request (FrameManifest's `cancelled`).
struct LockWaitCancelled : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class FrameManifest {
 public:
  enum class Existing { merge, replace };
  enum class Claim { join, supersede };
  // `cancelled`, if given, is asked while the constructor waits for a lock (another render holds the folder): when
  // it says yes, the wait ends with LockWaitCancelled, so SIGINT/SIGTERM are answered within a second before any
  // frame is written. Later waits (flushes) are not cancelled: they save finished frames.
  FrameManifest(std::string folder, nlohmann::json info, std::string fileName = "manifest.json",
                Existing existing = Existing::merge, Claim claim = Claim::join, bool (*cancelled)() = nullptr,
                double lockWaitSeconds = limits::kMaxLockWaitSeconds);
  ~FrameManifest();  // flushes; never throws
  FrameManifest(const FrameManifest&) = delete;
  FrameManifest& operator=(const FrameManifest&) = delete;

  // What draws this process's frames (ManifestContents::renderers) and through which backend. In merge mode,
  // throws std::runtime_error if the folder already lists frames drawn by another renderer (Claim::supersede:
  // removes them, as for another render); so does a flush that finds them (a shard on another kind of machine that
  // started at the same time).
  void addRenderer(const std::string& renderer, const std::string& backend);
  void record(const FrameEntry& entry);
  void flush();
  void setFlushInterval(std::chrono::milliseconds interval) { flushInterval_ = interval; }

  // The entry for frame k as last seen on disk or recorded here.
  std::optional<FrameEntry> entry(int frame) const;
  bool isFrameComplete(int frame) const;
  // Re-reads the manifest from disk (to see other processes' entries).
  void reload();

  std::string path() const { return folder_ + "/" + fileName_; }
  // What Claim::supersede replaced: the earlier render's info and how many of its frames were deleted.
  std::optional<nlohmann::json> supersededInfo() const { return supersededInfo_; }
  int supersededFrames() const { return supersededFrames_; }

 private:
  nlohmann::json emptyManifest() const;
  nlohmann::json readLocked() const;  // the manifest on disk, or an empty one; throws if malformed or another's
  nlohmann::json readAnyLocked() const;  // the same, whoever's render it is
  void checkSameRenderer(const nlohmann::json& manifest) const;  // readLocked(): frames of another renderer
  void supersedeLocked(const nlohmann::json& other);  // caller holds the manifest lock and the shared claim
  void flushLocked();                 // caller holds mutex_

  std::string folder_, fileName_;
  nlohmann::json info_;
  double lockWaitSeconds_;  // how long a lock another process holds is waited for (then: an error naming it)
  Existing existing_;
  Claim claim_;
  mutable std::mutex mutex_;
  std::map<int, FrameEntry> known_, pending_;
  mutable std::mutex renderersMutex_;  // renderers_ and backends_ (read while mutex_ is held, and without it)
  std::set<std::string> renderers_, backends_;
  std::chrono::steady_clock::time_point lastFlush_;
  std::chrono::milliseconds flushInterval_{500};
  int activeFd_ = -1;  // the shared claim on .<name>.active (merge mode)
  std::optional<nlohmann::json> supersededInfo_;
  int supersededFrames_ = 0;
};

}  // namespace sl

#pragma once
// Whole-file writes that readers never see half done: the bytes go to a temporary name in the same
// folder (same file system; output/temporary_file.hpp names it), then rename(2) replaces the final name in
// one step. A process killed mid-write leaves at most a temporary, never a truncated final file; every error
// path removes the temporary.
//
// Durability: with Sync::data the bytes are fsync'd before the rename and the folder after it, so the file
// survives a power loss too. Frames are written without it: the manifest records each frame's SHA-256 and
// --resume re-renders any frame whose bytes do not match, so a frame lost to a crash costs time, not
// correctness, and an fsync per frame would cost throughput. The manifest itself is synced.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace sl {

enum class Sync { none, data };

// Throws std::runtime_error naming the path and the system error.
void writeFileAtomically(const std::string& path, const std::uint8_t* data, std::size_t size, Sync sync = Sync::none);
inline void writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes,
                                Sync sync = Sync::none) {
  writeFileAtomically(path, bytes.data(), bytes.size(), sync);
}
void writeFileAtomically(const std::string& path, const std::string& text, Sync sync = Sync::none);

// Thrown when a file cannot be created or written because the file system is full: no space, no free inodes or
// the quota used up (ENOSPC, EDQUOT). Callers that must still record something can fall back (frame_manifest).
struct FileSystemFull : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Where an output named `path` really goes: `path` itself, or the file a symbolic link there points to (written
// through, never replaced by a regular file). Throws std::invalid_argument if that exists and is not a regular
// file (a device such as /dev/null, a folder, a pipe): such things are never replaced. Used by every writer here.
std::string outputTarget(const std::string& path);

// A file written in pieces (a long CSV) that appears under its name only when complete: the pieces go to a
// temporary beside it; commit() checks every write, closes and renames; destroyed uncommitted (an error, an
// interruption), it removes the temporary. Memory stays bounded whatever the file's size.
class AtomicFileWriter {
 public:
  explicit AtomicFileWriter(const std::string& path);  // throws if the file cannot be created
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  void write(const std::string& text);  // throws naming the file (disk full, quota, I/O error)
  void commit();
  const std::string& path() const { return path_; }

 private:
  std::string path_, temporary_;
  int fd_ = -1;
};

}  // namespace sl

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
#include <string>
#include <vector>

namespace sl::output {

enum class Sync { none, data };

// Throws std::runtime_error naming the path and the system error.
void writeFileAtomically(const std::string& path, const std::uint8_t* data, std::size_t size, Sync sync = Sync::none);
inline void writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes,
                                Sync sync = Sync::none) {
  writeFileAtomically(path, bytes.data(), bytes.size(), sync);
}
void writeFileAtomically(const std::string& path, const std::string& text, Sync sync = Sync::none);

}  // namespace sl::output

#pragma once
// Whole-file writes that readers never see half done: the bytes go to a temporary name in the same
// folder (same file system), then rename(2) replaces the final name in one step. A process killed
// mid-write leaves at most a ".tmp" file, never a truncated final file.

#include <cstdint>
#include <string>
#include <vector>

namespace sl::output {

// Throws std::runtime_error naming the path and the system error.
void writeFileAtomically(const std::string& path, const std::uint8_t* data, std::size_t size);
inline void writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  writeFileAtomically(path, bytes.data(), bytes.size());
}
void writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace sl::output

#include "scene/output_folder.hpp"

#include "contracts/registry.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace sl {

namespace fs = std::filesystem;

namespace {

// Creates and removes a uniquely named empty file in an existing directory; the reason if that fails (no
// permission, no space or no free inodes, a read-only file system: errno says which).
std::string whyNoFileIn(const fs::path& directory) {
  const fs::path probe = directory / (".linkage-write-probe-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    switch (errno) {
      case EACCES:
      case EPERM: return "no permission to create files in ";
      case ENOSPC: return "no space left (or no free inodes) to create files in ";
      case EDQUOT: return "the disk quota is used up in ";
      case EROFS: return "the file system is read-only at ";
      default: return std::string(std::strerror(errno)) + ": cannot create files in ";
    }
  }
  ::close(fd);
  std::error_code ignored;
  fs::remove(probe, ignored);
  return "";
}

}  // namespace

std::string unusablePathReason(const std::string& path) {
  if (path.find('\0') != std::string::npos) return "holds a NUL character";
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find('/', start), path.size());
    if (end - start > 255)
      return "has a component of " + std::to_string(end - start) + " bytes; file systems allow 255";
    start = end + 1;
  }
  return "";
}

std::vector<SceneProblem> checkOutputFolder(const std::string& folder, const std::string& jsonPath) {
  if (const std::string reason = unusablePathReason(folder); !reason.empty())
    return {{jsonPath, "\"" + folder + "\" " + reason + "; expected a usable folder path"}};
  std::error_code error;
  fs::path existing = fs::absolute(folder, error);
  while (!existing.empty() && !fs::exists(existing, error)) {
    if (existing == existing.parent_path()) break;
    existing = existing.parent_path();
  }
  const std::string found = "\"" + folder + "\"";
  if (!fs::is_directory(existing, error)) {
    return {{jsonPath, "cannot write " + found + ": " + existing.string() + " is not a directory"}};
  }
  if (const std::string why = whyNoFileIn(existing); !why.empty()) {
    return {{jsonPath, "cannot write " + found + ": " + why + existing.string()}};
  }
  return {};
}

std::vector<SceneProblem> checkOutputFile(const std::string& file, const std::string& jsonPath) {
  const std::string found = "found \"" + file + "\"";
  if (file.empty() || file.back() == '/') return {{jsonPath, found + "; expected a file name, not a folder"}};
  if (const std::string reason = unusablePathReason(file); !reason.empty())
    return {{jsonPath, "\"" + file + "\" " + reason + "; expected a usable file path"}};
  std::error_code error;
  if (fs::is_directory(file, error)) return {{jsonPath, found + ": that is a folder; expected a file name in it"}};
  const std::string name = fs::path(file).filename().string();
  if (name.size() > kMaxOutputNameBytes)
    return {{jsonPath, found + "; the file name has " + std::to_string(name.size()) + " bytes, at most " +
                           std::to_string(kMaxOutputNameBytes) + " are allowed (room for the temporary beside it)"}};
  const fs::path parent = fs::path(file).parent_path();
  return checkOutputFolder(parent.empty() ? "." : parent.string(), jsonPath);
}

std::vector<SceneProblem> checkVideoPath(const std::string& video, const std::string& jsonPath) {
  if (std::vector<SceneProblem> problems = checkOutputFile(video, jsonPath); !problems.empty()) return problems;
  const std::string found = "found \"" + video + "\"";
  if (!videoFormatOfPath(video)) {
    std::string formats;
    for (const VideoFormatTraits& format : kVideoFormats)
      formats += (formats.empty() ? "." : ", .") + std::string(format.name);
    return {{jsonPath, found + "; expected a file name ending in " + formats + " (the format follows the extension)"}};
  }
  std::error_code error;
  if (fs::exists(video, error) && !fs::is_regular_file(video, error))
    return {{jsonPath, found + ": it exists and is not a regular file; refusing to replace it"}};
  return {};
}

}  // namespace sl

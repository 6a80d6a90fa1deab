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

std::vector<SceneProblem> checkOutputFolder(const std::string& folder, const std::string& jsonPath) {
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

std::vector<SceneProblem> checkVideoPath(const std::string& video, const std::string& jsonPath) {
  const std::string found = "found \"" + video + "\"";
  std::string formats;
  for (const VideoFormatTraits& format : kVideoFormats) formats += (formats.empty() ? "." : ", .") + std::string(format.name);
  if (video.empty() || video.back() == '/') return {{jsonPath, found + "; expected a video file name, not a folder"}};
  if (video.find('\0') != std::string::npos) return {{jsonPath, "holds a NUL character; expected a file name"}};
  std::error_code error;
  if (fs::is_directory(video, error)) return {{jsonPath, found + ": that is a folder; expected a video file name in it"}};
  if (!videoFormatOfPath(video))
    return {{jsonPath, found + "; expected a file name ending in " + formats + " (the format follows the extension)"}};
  const std::string name = fs::path(video).filename().string();
  if (name.size() > kMaxOutputNameBytes)
    return {{jsonPath, found + "; the file name has " + std::to_string(name.size()) + " bytes, at most " +
                           std::to_string(kMaxOutputNameBytes) + " are allowed (room for the temporary beside it)"}};
  if (fs::exists(video, error) && !fs::is_regular_file(video, error))
    return {{jsonPath, found + ": it exists and is not a regular file; refusing to replace it"}};
  const fs::path parent = fs::path(video).parent_path();
  return checkOutputFolder(parent.empty() ? "." : parent.string(), jsonPath);
}

}  // namespace sl

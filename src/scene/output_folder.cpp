#include "scene/output_folder.hpp"

#include "contracts/registry.hpp"

#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace sl {

namespace fs = std::filesystem;

namespace {

// Creates and removes a uniquely named empty file in an existing directory.
bool canCreateFileIn(const fs::path& directory) {
  const fs::path probe = directory / (".linkage-write-probe-" + std::to_string(::getpid()));
  {
    std::ofstream stream(probe);
    if (!stream) return false;
  }
  std::error_code ignored;
  fs::remove(probe, ignored);
  return true;
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
  if (!canCreateFileIn(existing)) {
    return {{jsonPath, "cannot write " + found + ": no permission to create files in " + existing.string()}};
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

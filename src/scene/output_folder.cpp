#include "scene/output_folder.hpp"

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

}  // namespace sl

#include "output/distinct_files.hpp"

#include <sys/stat.h>

#include <filesystem>
#include <stdexcept>

#include "output/atomic_file.hpp"

namespace sl {

namespace {

// Where writing `path` would land: the end of its chain of links (outputTarget), made absolute and normal.
std::filesystem::path landing(const std::string& path) {
  std::string target = path;
  try {
    target = outputTarget(path);
  } catch (const std::invalid_argument&) {
    // Not a regular file: the writers refuse it themselves; compare the name as given.
  }
  std::error_code error;
  const std::filesystem::path resolved = std::filesystem::weakly_canonical(target, error);
  return (error ? std::filesystem::absolute(target) : resolved).lexically_normal();
}

}  // namespace

bool sameFile(const std::string& a, const std::string& b) {
  struct stat first{}, second{};
  if (::stat(a.c_str(), &first) == 0 && ::stat(b.c_str(), &second) == 0)
    return first.st_dev == second.st_dev && first.st_ino == second.st_ino;
  return landing(a) == landing(b);
}

void requireDistinctFiles(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs) {
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const NamedFile& output = outputs[k];
    if (output.path.empty()) continue;
    auto clash = [&](const NamedFile& other, const char* what) {
      throw std::invalid_argument(output.role + " " + output.path + " is the same file as " + other.role + " " +
                                  other.path + what);
    };
    for (const NamedFile& input : inputs)
      if (!input.path.empty() && sameFile(output.path, input.path))
        clash(input, ": an output never replaces an input; write it elsewhere");
    for (std::size_t j = 0; j < k; ++j)
      if (!outputs[j].path.empty() && sameFile(output.path, outputs[j].path))
        clash(outputs[j], ": two outputs of one command need two files");
  }
}

}  // namespace sl

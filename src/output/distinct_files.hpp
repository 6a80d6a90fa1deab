#pragma once
// No two outputs of one command, and no output and an input, may be the same file: the later write would
// replace the earlier one, or the input itself. Links are followed (as every writer here follows them), and
// two names of one existing file (a hard link, "a" and "./a") are the same file.

#include <string>
#include <vector>

namespace sl {

struct NamedFile {
  std::string role;  // how the command line or the scene names it: "--csv", "the scene", "output.video"
  std::string path;  // empty: not given (skipped)
};

// Throws std::invalid_argument naming both roles and paths if an output is an input or another output.
void requireDistinctFiles(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs);

// Whether two paths name the same file once links are followed (the same device and inode if both exist, the
// same absolute path otherwise).
bool sameFile(const std::string& a, const std::string& b);

}  // namespace sl

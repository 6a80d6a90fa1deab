#pragma once
// Running the `linkage` binary from tests: a fresh temporary folder per test, commands run in it
// through /bin/sh, exit status and both output streams captured.

#include <filesystem>
#include <map>
#include <string>

namespace sl::testing {

struct CommandResult {
  int status = -1;  // exit status, or 128 + signal
  std::string out, err;
};

class TempFolder {
 public:
  TempFolder();
  ~TempFolder();
  const std::filesystem::path& path() const { return path_; }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// `linkage ARGS` run in folder.
CommandResult runLinkage(const std::string& arguments, const std::filesystem::path& folder);
// Any shell command line run in folder.
CommandResult runShell(const std::string& commandLine, const std::filesystem::path& folder);

std::string shippedScene(const std::string& name);
std::string linkageBinary();
// 'path' for the shell (test paths contain no quotes).
std::string quoted(const std::string& path);
std::string readFile(const std::string& path);
// Every regular file under a folder, by relative path, with its bytes.
std::map<std::string, std::string> folderContents(const std::filesystem::path& folder);

}  // namespace sl::testing

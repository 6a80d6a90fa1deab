#include "cli_support.hpp"

#include <sys/wait.h>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>

namespace sl::testing {

namespace fs = std::filesystem;

TempFolder::TempFolder() {
  std::random_device random;
  path_ = fs::temp_directory_path() / ("linkage-cli-test-" + std::to_string(random()));
  fs::create_directories(path_);
}

TempFolder::~TempFolder() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

CommandResult runShell(const std::string& commandLine, const fs::path& folder) {
  const fs::path out = folder.parent_path() / (folder.filename().string() + ".out");
  const fs::path err = folder.parent_path() / (folder.filename().string() + ".err");
  const std::string line = "cd " + quoted(folder.string()) + " && " + commandLine + " >" + quoted(out.string()) +
                           " 2>" + quoted(err.string());
  const int raw = std::system(line.c_str());
  CommandResult result;
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  result.out = readFile(out.string());
  result.err = readFile(err.string());
  fs::remove(out);
  fs::remove(err);
  return result;
}

std::string linkageBinary() { return LINKAGE_BINARY; }

std::string quoted(const std::string& path) {
  std::string text;
  text.append(1, '\'').append(path).append(1, '\'');
  return text;
}

CommandResult runLinkage(const std::string& arguments, const fs::path& folder) {
  return runShell(quoted(linkageBinary()) + " " + arguments, folder);
}

std::string shippedScene(const std::string& name) { return std::string(SL_SOURCE_DIR) + "/scenes/" + name; }

std::map<std::string, std::string> folderContents(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) files[fs::relative(entry.path(), folder).string()] = readFile(entry.path().string());
  }
  return files;
}

}  // namespace sl::testing

#include "support/scene_files.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sl::testing {

std::string sourcePath(const std::string& relative) { return std::string(SL_SOURCE_DIR) + "/" + relative; }

std::string shippedScene(const std::string& name) { return sourcePath("scenes/" + name); }

std::string badSceneFolder() { return sourcePath("tests/data/scenes/bad/"); }

std::map<std::string, std::vector<BadSceneExpectation>> badSceneExpectations() {
  const std::string tablePath = badSceneFolder() + "expected.tsv";
  std::ifstream table(tablePath);
  if (!table) throw std::runtime_error("cannot read " + tablePath);
  std::map<std::string, std::vector<BadSceneExpectation>> byFile;
  std::string line;
  while (std::getline(table, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string file, jsonPath, fragment, stage;
    std::getline(fields, file, '\t');
    std::getline(fields, jsonPath, '\t');
    std::getline(fields, fragment, '\t');
    std::getline(fields, stage);
    byFile[file].push_back({jsonPath, fragment, stage == "start"});
  }
  return byFile;
}

}  // namespace sl::testing

// The layers of the program (cmake/Stages.cmake, written to build/layers.txt) checked on the sources: a
// file of stage S may include only headers of S and of the stages S uses. The build already refuses such
// includes through each stage's include path; this test also catches relative includes ("../x/y.hpp") and
// names the offending line.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

using Layers = std::map<std::string, std::set<std::string>>;  // stage -> stages it may use (itself included)

Layers readLayers() {
  std::ifstream in(SL_LAYERS_FILE);
  EXPECT_TRUE(in) << "cannot read " << SL_LAYERS_FILE;
  Layers layers;
  std::string line;
  while (std::getline(in, line)) {
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    const std::string stage = line.substr(0, colon);
    std::istringstream uses(line.substr(colon + 1));
    layers[stage].insert(stage);
    for (std::string used; uses >> used;) layers[stage].insert(used);
  }
  return layers;
}

// "stage/header.hpp" includes of a file, with their line numbers; "../" is resolved against the file.
std::vector<std::pair<int, std::string>> includedStages(const fs::path& file, const fs::path& src) {
  static const std::regex include(R"re(^\s*#\s*include\s*"([^"]+)")re");
  std::vector<std::pair<int, std::string>> found;
  std::ifstream in(file);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::smatch match;
    if (!std::regex_search(line, match, include)) continue;
    std::string target = match[1];
    if (target.find('/') == std::string::npos) continue;  // same folder
    if (target.starts_with("../") || target.starts_with("./")) {
      target = fs::relative(fs::weakly_canonical(file.parent_path() / target), src).generic_string();
    }
    found.emplace_back(number, target.substr(0, target.find('/')));
  }
  return found;
}

TEST(Layers, TableNamesEveryFolderOfSrc) {
  const Layers layers = readLayers();
  const fs::path src = fs::path(SL_SOURCE_DIR) / "src";
  for (const auto& entry : fs::directory_iterator(src)) {
    if (entry.is_directory()) {
      EXPECT_TRUE(layers.count(entry.path().filename().string())) << entry.path();
    }
  }
  for (const auto& [stage, uses] : layers) {
    for (const std::string& used : uses) EXPECT_TRUE(layers.count(used)) << stage << " uses unknown " << used;
  }
}

TEST(Layers, NoStageIncludesAStageItMayNotUse) {
  const Layers layers = readLayers();
  const fs::path src = fs::path(SL_SOURCE_DIR) / "src";
  int checked = 0;
  for (const auto& entry : fs::recursive_directory_iterator(src)) {
    if (!entry.is_regular_file()) continue;
    const std::string extension = entry.path().extension().string();
    if (extension != ".hpp" && extension != ".cpp") continue;
    const std::string stage = fs::relative(entry.path(), src).begin()->string();
    ASSERT_TRUE(layers.count(stage)) << entry.path();
    for (const auto& [line, included] : includedStages(entry.path(), src)) {
      ++checked;
      EXPECT_TRUE(layers.at(stage).count(included))
          << entry.path().string() << ":" << line << ": stage " << stage << " includes " << included;
    }
  }
  EXPECT_GT(checked, 100);  // the scan saw the sources
}

// Rendering knows nothing of integrators, numerics nothing of OpenGL (the rule the table encodes).
TEST(Layers, NumericsAndRenderingStayApart) {
  const Layers layers = readLayers();
  for (const std::string numeric : {"contracts", "linkage", "simulation", "analysis"})
    EXPECT_FALSE(layers.at(numeric).count("render")) << numeric;
  EXPECT_FALSE(layers.at("render").count("simulation"));
  EXPECT_FALSE(layers.at("render").count("scene"));
  EXPECT_FALSE(layers.at("output").count("render"));
}

}  // namespace

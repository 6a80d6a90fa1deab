// Every validation rule has a bad scene under tests/data/scenes/bad/ (listed in expected.tsv with the
// JSON path its message must name). The CLI tests run the same files through `linkage validate/render`.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "scene/output_folder.hpp"
#include "scene/scene_loader.hpp"
#include "scene_test_support.hpp"

namespace sl {
namespace {

struct Expectation {
  std::string path, fragment;
};

const std::string kBadDir = std::string(SL_SOURCE_DIR) + "/tests/data/scenes/bad/";

std::map<std::string, std::vector<Expectation>> expectations() {
  std::map<std::string, std::vector<Expectation>> byFile;
  std::ifstream table(kBadDir + "expected.tsv");
  std::string line;
  while (std::getline(table, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string file, path, fragment;
    std::getline(fields, file, '\t');
    std::getline(fields, path, '\t');
    std::getline(fields, fragment);
    byFile[file].push_back({path, fragment});
  }
  return byFile;
}

// All problems of a file: loading, then the output folder (checked by the commands before writing).
std::vector<SceneProblem> problemsOf(const std::string& file) {
  try {
    const Scene scene = loadScene(file, testing::testLimits());
    return checkOutputFolder(scene.output.folder, "output.folder");
  } catch (const SceneError& error) {
    return error.problems();
  }
}

TEST(BadScenes, TableCoversEveryFile) {
  const auto table = expectations();
  EXPECT_GE(table.size(), 30u);
  for (const auto& entry : std::filesystem::directory_iterator(kBadDir)) {
    if (entry.path().extension() != ".json") continue;
    EXPECT_TRUE(table.count(entry.path().filename().string())) << entry.path();
  }
}

TEST(BadScenes, EachNamesItsJsonPathAndWhatIsWrong) {
  for (const auto& [file, expected] : expectations()) {
    SCOPED_TRACE(file);
    const std::vector<SceneProblem> problems = problemsOf(kBadDir + file);
    ASSERT_FALSE(problems.empty());
    for (const Expectation& expectation : expected) {
      bool found = false;
      for (const SceneProblem& problem : problems) {
        found = found || (problem.jsonPath == expectation.path &&
                          problem.message.find(expectation.fragment) != std::string::npos);
      }
      EXPECT_TRUE(found) << "expected " << expectation.path << ": ..." << expectation.fragment << "...\ngot:\n"
                         << formatProblems(file, problems);
    }
  }
}

TEST(BadScenes, SeveralProblemsAreAllReported) { EXPECT_EQ(problemsOf(kBadDir + "several_problems.json").size(), 3u); }

TEST(BadScenes, MessageStartsWithTheFileName) {
  try {
    loadScene(kBadDir + "zero_fps.json", testing::testLimits());
    FAIL();
  } catch (const SceneError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(kBadDir + "zero_fps.json: output.fps: found 0", 0), 0u) << error.what();
  }
}

}  // namespace
}  // namespace sl

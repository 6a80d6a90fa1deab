// Every validation rule has a bad scene under tests/data/scenes/bad/ (listed in expected.tsv with the
// JSON path its message must name). The CLI tests run the same files through `linkage validate/render`.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/output_folder.hpp"
#include "scene/scene_loader.hpp"
#include "support/scene_files.hpp"

namespace sl {
namespace {

using testing::BadSceneExpectation;
using testing::badSceneExpectations;

const std::string kBadDir = testing::badSceneFolder();

// All problems of a file: loading, then the output folder (checked by the commands before writing).
std::vector<SceneProblem> problemsOf(const std::string& file) {
  try {
    const Scene scene = loadScene(file);
    return checkOutputFolder(scene.output.folder, "output.folder");
  } catch (const SceneError& error) {
    return error.problems();
  }
}

TEST(BadScenes, TableCoversEveryFile) {
  const auto table = badSceneExpectations();
  EXPECT_GE(table.size(), 30u);
  for (const auto& entry : std::filesystem::directory_iterator(kBadDir)) {
    if (entry.path().extension() != ".json") continue;
    EXPECT_TRUE(table.count(entry.path().filename().string())) << entry.path();
  }
}

TEST(BadScenes, EachNamesItsJsonPathAndWhatIsWrong) {
  for (const auto& [file, expected] : badSceneExpectations()) {
    SCOPED_TRACE(file);
    if (expected.front().atStart) continue;  // the start's problems: tests/cli/bad_scene_cli_test.cpp
    const std::vector<SceneProblem> problems = problemsOf(kBadDir + file);
    ASSERT_FALSE(problems.empty());
    for (const BadSceneExpectation& expectation : expected) {
      bool found = false;
      for (const SceneProblem& problem : problems) {
        found = found || (problem.jsonPath == expectation.jsonPath &&
                          problem.message.find(expectation.fragment) != std::string::npos);
      }
      EXPECT_TRUE(found) << "expected " << expectation.jsonPath << ": ..." << expectation.fragment << "...\ngot:\n"
                         << formatProblems(file, problems);
    }
  }
}

// An invalid "rods" is the only problem of a scene whose other sizes fit the n it meant; nothing is
// compared with a made-up n (masses, starts in every form, runs' linkages, families, Jacobi fields, the sphere).
TEST(BadScenes, AnInvalidRodCountIsNotMeasuredAgainstAMadeUpOne) {
  for (const char* file : {"rods_beyond_limit_sized_for_it.json", "rods_not_integer_sized_for_five.json"}) {
    const std::vector<SceneProblem> problems = problemsOf(kBadDir + file);
    ASSERT_EQ(problems.size(), 1u) << formatProblems(file, problems);
    EXPECT_EQ(problems[0].jsonPath, "linkage.rods");
  }
}

TEST(BadScenes, SeveralProblemsAreAllReported) { EXPECT_EQ(problemsOf(kBadDir + "several_problems.json").size(), 3u); }

TEST(BadScenes, MessageStartsWithTheFileName) {
  try {
    loadScene(kBadDir + "zero_fps.json");
    FAIL();
  } catch (const SceneError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(kBadDir + "zero_fps.json: output.fps: found 0", 0), 0u) << error.what();
  }
}

}  // namespace
}  // namespace sl

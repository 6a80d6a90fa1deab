// Every input in fuzz/regressions/ (each found a bug with scripts/fuzz.sh) goes through the scene loader
// again: it must give a clean SceneError naming at least one problem, or a scene whose start is finite.
// And the fuzzer's dictionary keeps up with the registry, so mutations reach every kind.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contracts/registry.hpp"
#include "scene/scene_loader.hpp"
#include "simulation/initial_state.hpp"
#include "support/files.hpp"
#include "support/scene_files.hpp"

namespace sl {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> regressionInputs() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(testing::sourcePath("fuzz/regressions"))) {
    if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(FuzzRegressions, EachInputIsAcceptedOrRefusedCleanly) {
  const std::vector<fs::path> inputs = regressionInputs();
  EXPECT_FALSE(inputs.empty()) << "fuzz/regressions/ holds the inputs that found bugs";
  for (const fs::path& input : inputs) {
    SCOPED_TRACE(input.filename().string());
    try {
      const Scene scene = loadScene(input.string());
      const InitialState start = initialStateFromSpec(scene.chain, scene.initial);
      EXPECT_TRUE(start.spherePoint.allFinite() && start.sphereVelocity.allFinite());
      // What the simulation would refuse, the loader must have refused (as scene_fuzzer.cpp checks).
      EXPECT_NO_THROW(validateInitialState(scene.chain, start));
    } catch (const SceneError& error) {
      ASSERT_FALSE(error.problems().empty());
      EXPECT_NE(std::string(error.what()).find(input.filename().string()), std::string::npos) << error.what();
    } catch (const std::invalid_argument& error) {
      EXPECT_FALSE(std::string(error.what()).empty());
    }
  }
}

TEST(FuzzDictionary, HoldsEveryNameOfTheRegistry) {
  const std::string dictionary = testing::readFile(testing::sourcePath("fuzz/scene.dict"));
  ASSERT_FALSE(dictionary.empty());
  std::vector<std::string> names;
  for (const std::vector<std::string>& table :
       {namesOf(kMethods), namesOf(kIntegrators), namesOf(kPanelKinds), namesOf(kPlotKinds), namesOf(kLinkageLayouts),
        namesOf(kFamilyKinds)})
    names.insert(names.end(), table.begin(), table.end());
  for (const std::string& name : names) {
    EXPECT_NE(dictionary.find("\"\\\"" + name + "\\\"\"\n"), std::string::npos) << name << " is not in fuzz/scene.dict";
  }
}

}  // namespace
}  // namespace sl

// Every input in fuzz/regressions/ (each found a bug with scripts/fuzz.sh) goes through the scene loader
// again: it must give a clean SceneError naming at least one problem, or a scene whose start is finite.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "frames/scene_start.hpp"
#include "scene/scene_loader.hpp"
#include "simulation/trajectory.hpp"

namespace sl {
namespace {

namespace fs = std::filesystem;

SceneLimits programLikeLimits() { return simulationSceneLimits(); }

std::vector<fs::path> regressionInputs() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(SL_SOURCE_DIR) / "fuzz" / "regressions")) {
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
      const Scene scene = loadScene(input.string(), programLikeLimits());
      const InitialState start = sceneStart(scene);
      EXPECT_TRUE(start.spherePoint.allFinite() && start.sphereVelocity.allFinite());
    } catch (const SceneError& error) {
      ASSERT_FALSE(error.problems().empty());
      EXPECT_NE(std::string(error.what()).find(input.filename().string()), std::string::npos) << error.what();
    } catch (const std::invalid_argument& error) {
      EXPECT_FALSE(std::string(error.what()).empty());
    }
  }
}

}  // namespace
}  // namespace sl

// The descriptions of scene keys (scene/scene_keys.hpp) are what the loader checks: every bound of every
// described number is accepted exactly at its boundary and refused just beyond it, on both sides, with the
// description's words; every described key is known to the loader, and nothing else is.
#include <cmath>
#include <limits>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "scene/scene_keys.hpp"
#include "scene/scene_loader.hpp"
#include "support/files.hpp"
#include "support/scene_files.hpp"

namespace sl {
namespace {

using nlohmann::json;

// The default scene with `value` at the key's path, and what the key needs around it (a family's kind, a start
// by hinges for a push).
json sceneWith(const SceneKey& key, const json& value) {
  json scene = json::parse(testing::readFile(testing::sourcePath("scenes/default.json")));
  const std::string path = std::regex_replace(key.path, std::regex("\\[i\\]"), "[0]");
  if (path.rfind("runs[0].family.", 0) == 0) {
    const bool cloud = key.path.ends_with("epsilon") || key.path.ends_with("seed");
    scene["runs"][0]["family"] = {{"kind", cloud ? "cloud" : "fan"}};
  }
  if (path.rfind("initial.push.", 0) == 0) {
    const bool random = key.path.ends_with("seed") || key.path.ends_with("size");
    scene["initial"] = {{"hinges", "arc"},
                        {"push", random ? json{{"seed", 1}} : json{{"hinge", 1}, {"velocity", {0, 1}}}}};
  }
  // A start on a found motion: connect between two chart points, or a periodic motion (a 4-rod chain).
  if (path.rfind("initial.connect.", 0) == 0) {
    json connect = json::object();
    connect["from"]["coords"] = {0.3, 0.2};
    connect["to"]["coords"] = {-0.6, 2.2};
    scene["initial"] = {{"connect", connect}};
  }
  if (path.rfind("initial.periodic.", 0) == 0) scene["initial"] = {{"periodic", json::object()}};
  if (path.rfind("view.panels[0].", 0) == 0) scene["view"]["panels"] = {{{"panel", "plot"}}};
  // A massless hinge needs a massive rod beside it (a rule between keys): give the rods mass.
  if (key.path == "linkage.hinge_masses") scene["linkage"]["rod_masses"] = {1, 1, 1, 1};
  json::json_pointer pointer(
      "/" + std::regex_replace(std::regex_replace(path, std::regex("\\[0\\]"), ".0"), std::regex("\\."), "/"));
  scene[pointer] = value;
  return scene;
}

// The problems at exactly `path` when the scene is loaded.
std::vector<SceneProblem> problemsAt(const json& scene, const std::string& path) {
  std::vector<SceneProblem> found;
  try {
    parseScene(scene.dump(), "keys.json");
  } catch (const SceneError& error) {
    for (const SceneProblem& problem : error.problems())
      if (problem.jsonPath == path) found.push_back(problem);
  }
  return found;
}

json valueOf(const SceneKey& key, double number) {
  const json one = key.type == KeyType::Integer ? json(static_cast<long>(number)) : json(number);
  if (key.type != KeyType::Numbers) return one;
  json list = json::array();
  // The default scene's chain has 4 rods: n = 4 rod masses, n-1 = 3 of anything else.
  const int size = key.count > 0 ? key.count : key.path.ends_with("rod_masses") ? 4 : 3;
  for (int i = 0; i < size; ++i) list.push_back(i == 0 ? one : json(std::clamp(1.0, key.minimum, key.maximum)));
  return list;
}

TEST(SceneKeys, EveryBoundIsAcceptedAtItsBoundaryAndRefusedBeyondItInTheDescriptionsWords) {
  int checked = 0;
  for (const SceneKey& key : sceneKeys()) {
    const bool bounded = key.type == KeyType::Number || key.type == KeyType::Integer || key.type == KeyType::Numbers;
    if (!bounded || key.expected.empty()) continue;
    SCOPED_TRACE(key.path);
    const std::string path = std::regex_replace(key.path, std::regex("\\[i\\]"), "[0]");
    const bool integer = key.type == KeyType::Integer;
    const auto beyond = [&](double bound, double direction) {
      return integer ? bound + direction : std::nextafter(bound, direction * std::numeric_limits<double>::infinity());
    };
    std::vector<std::pair<double, bool>> cases;  // value, accepted
    if (std::isfinite(key.minimum)) {
      cases.push_back({key.minimum, !key.exclusiveMinimum});
      cases.push_back({key.exclusiveMinimum ? beyond(key.minimum, +1) : beyond(key.minimum, -1), key.exclusiveMinimum});
    }
    // Integer bounds at the edge of long (a seed's) cannot be stepped beyond in JSON.
    if (std::isfinite(key.maximum) && !(integer && key.maximum >= 9e18)) {
      cases.push_back({key.maximum, true});
      cases.push_back({beyond(key.maximum, +1), false});
    }
    for (const auto& [value, accepted] : cases) {
      const std::vector<SceneProblem> problems = problemsAt(sceneWith(key, valueOf(key, value)), path);
      if (accepted) {
        EXPECT_TRUE(problems.empty()) << value << ": " << (problems.empty() ? "" : problems[0].message);
      } else {
        ASSERT_EQ(problems.size(), 1u) << value;
        // Zero for a key that must be positive is refused as such ("expected a positive number").
        const std::string words = key.exclusiveMinimum && value == 0 ? "a positive number" : expectedWords(key);
        EXPECT_NE(problems[0].message.find("expected " + words), std::string::npos)
            << value << ": " << problems[0].message;
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 60);
}

TEST(SceneKeys, RangeWordsComeFromTheBounds) {
  EXPECT_EQ(expectedWords(sceneKey("runs[3].tolerance")), "a tolerance from 1e-16 to 0.1");
  EXPECT_EQ(expectedWords(sceneKey("view.camera.orbit_degrees_per_second")), "degrees per second from -3600 to 3600");
  EXPECT_EQ(expectedWords(sceneKey("runs[0].linkage.rods")),
            "an integer from 3 to 1000 (fewer than 3 rods cannot move; above 12 the ambient method only)");
}

TEST(SceneKeys, EveryDescribedKeyIsKnownToTheLoaderAndNoOther) {
  // A key the loader does not know is reported as unknown; one that is described never is.
  for (const SceneKey& key : sceneKeys()) {
    if (key.path.empty() || key.path.back() == ']') continue;
    SCOPED_TRACE(key.path);
    const std::string path = std::regex_replace(key.path, std::regex("\\[i\\]"), "[0]");
    const json scene = sceneWith(key, json(nullptr));
    for (const SceneProblem& problem : problemsAt(scene, path))
      EXPECT_EQ(problem.message.find("unknown key"), std::string::npos) << problem.message;
  }
  SceneKey stranger{.path = "view.camera.zoom"};
  EXPECT_EQ(problemsAt(sceneWith(stranger, 1), "view.camera.zoom").at(0).message, "unknown key");
  EXPECT_THROW(sceneKey("view.camera.zoom"), std::logic_error);
}

}  // namespace
}  // namespace sl

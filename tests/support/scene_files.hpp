#pragma once
// Scene files the tests read from the repository (SL_SOURCE_DIR): the shipped scenes of scenes/ and the bad
// scenes of tests/data/scenes/bad/ with what each must report (its expected.tsv). The scene tests load them
// through the library, the CLI tests through `linkage validate` and `render`.

#include <map>
#include <string>
#include <vector>

namespace sl::testing {

// A path under the repository's root.
std::string sourcePath(const std::string& relative);
// scenes/<name>.
std::string shippedScene(const std::string& name);

// tests/data/scenes/bad/, with a trailing slash.
std::string badSceneFolder();

// One line of expected.tsv: a JSON path the file's messages must name, with a fragment of that message.
// A fourth column "start" marks problems found when the start is set up from the scene (the simulation's
// initial state: validate, render and simulate refuse them), which the scene loader alone cannot see.
struct BadSceneExpectation {
  std::string jsonPath, fragment;
  bool atStart = false;
};
// Every bad scene file named in expected.tsv, with all its expectations in the table's order.
std::map<std::string, std::vector<BadSceneExpectation>> badSceneExpectations();

}  // namespace sl::testing

#include "cli/scene_input.hpp"

#include <stdexcept>

#include "cli/exit_codes.hpp"
#include "simulation/initial_state.hpp"

namespace sl {

void failOnProblems(const std::string& file, const std::vector<SceneProblem>& problems) {
  if (!problems.empty()) throw CommandExit(kExitBadInput, formatProblems(file, problems));
}

Scene loadSceneForCommand(const std::string& file) {
  try {
    return loadScene(file);
  } catch (const SceneError& error) {
    throw CommandExit(kExitBadInput, error.what());
  }
}

InitialState sceneStart(const Scene& scene) {
  try {
    return initialStateFromSpec(scene.chain, scene.initial);
  } catch (const std::invalid_argument& error) {
    failOnProblems(scene.file, {{"initial", error.what()}});
    throw;
  }
}

std::vector<Trajectory> startRuns(const Scene& scene, const InitialState& start) {
  std::vector<Trajectory> runs;
  for (size_t i = 0; i < scene.runs.size(); ++i) {
    try {
      runs.emplace_back(scene.chain, start, scene.runs[i].config);
    } catch (const std::invalid_argument& error) {
      // The start is shared by every run: a zero or non-finite velocity is the start's problem.
      failOnProblems(scene.file, {{"runs[" + std::to_string(i) + "]", error.what()}});
      throw;
    }
  }
  return runs;
}

}  // namespace sl

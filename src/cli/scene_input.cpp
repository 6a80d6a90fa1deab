#include "cli/scene_input.hpp"

#include "cli/exit_codes.hpp"
#include "frames/scene_start.hpp"
#include "render/renderer.hpp"

namespace sl {

SceneLimits programLimits() {
  SceneLimits limits = simulationSceneLimits();
  limits.maxImageSize = Renderer::maxSize();
  return limits;
}

void failOnProblems(const std::string& file, const std::vector<SceneProblem>& problems) {
  if (!problems.empty()) throw CommandExit(kExitBadInput, formatProblems(file, problems));
}

Scene loadSceneForCommand(const std::string& file) {
  try {
    return loadScene(file, programLimits());
  } catch (const SceneError& error) {
    throw CommandExit(kExitBadInput, error.what());
  }
}

}  // namespace sl

#include "scene/scene_problems.hpp"

namespace sl {

std::string formatProblems(const std::string& file, const std::vector<SceneProblem>& problems) {
  std::string text;
  for (const SceneProblem& problem : problems) {
    if (!text.empty()) text += '\n';
    text += file + ": ";
    if (!problem.jsonPath.empty()) text += problem.jsonPath + ": ";
    text += problem.message;
  }
  return text;
}

SceneError::SceneError(std::string file, std::vector<SceneProblem> problems)
    : std::runtime_error(formatProblems(file, problems)), file_(std::move(file)), problems_(std::move(problems)) {}

}  // namespace sl

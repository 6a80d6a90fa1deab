#pragma once
// What is wrong with a scene: every problem found, each with its JSON path, so a user fixes them all
// in one pass. Thrown as SceneError once validation has looked at everything.

#include <stdexcept>
#include <string>
#include <vector>

namespace sl {

struct SceneProblem {
  std::string jsonPath;  // e.g. "runs[1].step"; empty for the whole file
  std::string message;   // what was found and what is allowed
};

class SceneError : public std::runtime_error {
 public:
  SceneError(std::string file, std::vector<SceneProblem> problems);
  const std::string& file() const { return file_; }
  const std::vector<SceneProblem>& problems() const { return problems_; }

 private:
  std::string file_;
  std::vector<SceneProblem> problems_;
};

// One line per problem: "FILE: PATH: MESSAGE".
std::string formatProblems(const std::string& file, const std::vector<SceneProblem>& problems);

}  // namespace sl

#include "cli/scene_input.hpp"

#include <stdexcept>

#include <CLI/CLI.hpp>

#include "cli/exit_codes.hpp"
#include "cli/interrupt.hpp"
#include "simulation/initial_state.hpp"

namespace sl {

void failOnProblems(const std::string& file, const std::vector<SceneProblem>& problems) {
  if (!problems.empty()) throw CommandExit(kExitBadInput, formatProblems(file, problems));
}

Scene loadSceneForCommand(const std::string& file, const std::vector<std::string>& overrides) {
  try {
    return loadScene(file, overrides);
  } catch (const SceneError& error) {
    throw CommandExit(kExitBadInput, error.what());
  }
}

void addSceneOverrideOption(CLI::App& command, std::vector<std::string>& overrides) {
  command
      .add_option("--set", overrides,
                  "override a scene key by its JSON path, e.g. --set linkage.L=3.2 --set output.fps=60 "
                  "--set runs[0].method=ambient (repeatable; checked like the file)")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);
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
      runs.back().setCancellation(interruptRequested);  // SIGINT/SIGTERM answered within one step
    } catch (const std::invalid_argument& error) {
      // The start is shared by every run: a zero or non-finite velocity is the start's problem.
      failOnProblems(scene.file, {{"runs[" + std::to_string(i) + "]", error.what()}});
      throw;
    }
  }
  return runs;
}

}  // namespace sl

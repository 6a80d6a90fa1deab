#include "scene/scene_cost.hpp"

#include <cstdio>
#include <string>

#include "contracts/limits.hpp"

namespace sl {

namespace {

std::string units(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

double hinges(const Scene& scene) { return static_cast<double>(scene.chain.rods - 1); }

}  // namespace

double runStepWork(const Scene& scene, const RunSpec& run) {
  const double fields = run.config.jacobi ? static_cast<double>(scene.chain.rods - 3) : 0.0;
  return hinges(scene) * (1.0 + fields) * (1.0 + fields);
}

double sceneWork(const Scene& scene) {
  const double samples = static_cast<double>(scene.frameCount()) * scene.view.pathSamplesPerFrame;
  double perSample = 0;
  for (const RunSpec& run : scene.runs)
    perSample += runStepWork(scene, run) + (run.family ? run.family->count * hinges(scene) : 0.0);
  return perSample * samples;
}

std::vector<SceneProblem> checkSceneCost(const Scene& scene) {
  std::vector<SceneProblem> problems;
  for (std::size_t i = 0; i < scene.runs.size(); ++i) {
    const double work = runStepWork(scene, scene.runs[i]);
    if (work > limits::kMaxStepWork)
      problems.push_back({"runs[" + std::to_string(i) + "].jacobi",
                          "Jacobi fields on " + std::to_string(scene.chain.rods) + " rods cost " + units(work) +
                              " units per step ((n-1) (n-2)^2), more than the " + units(limits::kMaxStepWork) +
                              " a step may take (about 250 rods); expected fewer rods or no Jacobi fields"});
  }
  if (!problems.empty()) return problems;
  const double work = sceneWork(scene);
  if (work > limits::kMaxSceneWork)
    problems.push_back({"duration", "the scene asks for " + units(work) + " units of work (rods x runs and family "
                                    "members x Jacobi fields x duration x fps x view.path_samples_per_frame), more "
                                    "than the " + units(limits::kMaxSceneWork) +
                                    " allowed (about a day of one core); expected a shorter duration, a lower fps, "
                                    "fewer path samples, members or rods"});
  return problems;
}

}  // namespace sl

#pragma once
// Scene files: read, check everything, report every problem (scene_problems.hpp) before any work.

#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_problems.hpp"

namespace sl {

// What the rest of the program accepts; passed in so that this stage needs neither the simulation
// nor the renderer library (the CLI fills it from methodNames(), integratorNames(), Renderer::maxSize()).
struct SceneLimits {
  std::vector<std::string> methods;
  std::vector<std::string> integrators;
  std::vector<std::string> adaptiveIntegrators;  // these use "tolerance", the others "step"
  int maxImageSize = 4096;                       // largest width or height
  long maxFrames = 1'000'000;                    // about 9 hours at 30 fps: anything longer is a typo
  int maxRods = 12;
};

// Throws SceneError listing every problem; the file is not touched otherwise.
Scene loadScene(const std::string& file, const SceneLimits& limits);
Scene parseScene(const std::string& text, const std::string& file, const SceneLimits& limits);

// The checks on an output size, shared by the scene's output.width/height and the --size option.
std::vector<SceneProblem> checkImageSize(int width, int height, bool forVideo, const SceneLimits& limits,
                                         const std::string& path);
// Refuses frame counts beyond limits.maxFrames, naming the numbers.
std::vector<SceneProblem> checkFrameCount(double duration, int fps, const SceneLimits& limits);

}  // namespace sl

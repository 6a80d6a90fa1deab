#pragma once
// Scenes as the commands read them: validated against what this build of the program accepts.

#include <string>

#include "scene/scene.hpp"
#include "scene/scene_loader.hpp"

namespace sl {

// Method and integrator names from the simulation, the largest image from the renderer.
SceneLimits programLimits();

// Loads and validates; on problems prints them all to stderr and throws CommandExit(kExitBadInput).
Scene loadSceneForCommand(const std::string& file);

// Throws CommandExit(kExitBadInput) listing the problems, if any.
void failOnProblems(const std::string& file, const std::vector<SceneProblem>& problems);

}  // namespace sl

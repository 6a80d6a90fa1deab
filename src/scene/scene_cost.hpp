#pragma once
// The cost of a scene, bounded up front: the work of one integration step of each run, and the whole scene's
// work over every run, family member and sphere-path sample (limits::kMaxStepWork, limits::kMaxSceneWork). What
// exceeds them is refused with the JSON path of the key that multiplies the work, before anything runs.

#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_problems.hpp"

namespace sl {

// Work units (limits.hpp) of one integration step of `run` on the scene's chain.
double runStepWork(const Scene& scene, const RunSpec& run);

// The whole scene's work units: every run and family member, one step per sphere-path sample.
double sceneWork(const Scene& scene);

// The problems of a scene whose cost exceeds the bounds (empty if it fits). Call only on an otherwise valid scene.
std::vector<SceneProblem> checkSceneCost(const Scene& scene);

}  // namespace sl

#pragma once
// The readers of each top-level section of a scene (internal to scene_loader.cpp and scene_view.cpp).

#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.hpp"
#include "scene/scene_loader.hpp"

namespace sl::detail {

// Reads "view" into scene.view; needs scene.runs and scene.chain already read.
void readView(const nlohmann::json& view, Scene& scene, std::vector<SceneProblem>& problems);

}  // namespace sl::detail

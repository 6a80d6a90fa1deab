#pragma once
// `--set KEY=VALUE`: any scene key by its JSON path, applied to the parsed document before it is checked, so
// an override gets the same checks and path-named messages as the file itself.
//   KEY    dot-separated keys with [i] for array elements: linkage.L, output.fps, runs[1].tolerance,
//          view.sphere.color_by. Missing objects on the way are created; array elements must exist.
//   VALUE  JSON if it parses as JSON (3.2, true, [1, 0.6, 0.5], {"a": 1}, "text"), a plain string otherwise
//          (--set runs[0].method=ambient).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_problems.hpp"

namespace sl {

// Applies every override in order; problems name "--set KEY" with what was wrong.
void applySceneOverrides(nlohmann::json& document, const std::vector<std::string>& overrides,
                         std::vector<SceneProblem>& problems);

}  // namespace sl

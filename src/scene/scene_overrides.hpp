#pragma once
// `--set KEY=VALUE`: any scene key by its JSON path, applied to the parsed document before it is checked, so
// an override gets the same checks and path-named messages as the file itself.
//   KEY    dot-separated keys with [i] for array elements: linkage.L, output.fps, runs[1].tolerance,
//          view.sphere.color_by. Missing objects on the way are created; array elements must exist, or be the
//          next one: runs[2]={...} on a scene of two runs appends a run.
//   VALUE  JSON if it parses as JSON (3.2, true, [1, 0.6, 0.5], {"a": 1}, "text"), a plain string otherwise
//          (--set runs[0].method=ambient).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_problems.hpp"

namespace sl {

// `--unset KEY` reaches applySceneOverrides as the entry kUnsetPrefix + KEY: it removes an object member or an
// array element the scene has (runs[0].tolerance before switching runs[0].integrator to rk4; a run).
inline constexpr const char* kUnsetPrefix = "--unset ";

// Applies every override in order; problems name "--set KEY" (or "--unset KEY") with what was wrong.
void applySceneOverrides(nlohmann::json& document, const std::vector<std::string>& overrides,
                         std::vector<SceneProblem>& problems);

}  // namespace sl

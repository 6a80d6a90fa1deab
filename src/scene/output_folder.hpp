#pragma once
// Can the frames be written? Checked before any work, without creating anything.

#include <string>
#include <vector>

#include "scene/scene_problems.hpp"

namespace sl {

// The folder (or its nearest existing ancestor, if it does not exist yet) must be a directory in
// which a file can be created: probed with a temporary file that is removed at once.
std::vector<SceneProblem> checkOutputFolder(const std::string& folder, const std::string& jsonPath);

}  // namespace sl

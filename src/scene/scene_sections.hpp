#pragma once
// What the readers of a scene's sections share (internal to scene_loader.cpp and scene_view.cpp).

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "contracts/registry.hpp"
#include "scene/json_fields.hpp"
#include "scene/scene.hpp"
#include "scene/scene_problems.hpp"

namespace sl::detail {

// Reads "view" into scene.view; needs scene.runs and scene.chain already read.
// `rodsKnown`: the scene's "rods" is valid, so rules by rod count apply (scene_loader.cpp, RodCount).
void readView(const nlohmann::json& view, Scene& scene, bool rodsKnown, std::vector<SceneProblem>& problems);

// A configuration named by "coords" (chart 0, n-2 numbers) or "hinges" (n-1 points), e.g. a connect start's
// "from" and "to" (`rods`: the scene's, if valid). Whether hinges lie on the rod constraints is decided when the
// commands resolve it (cli/motion_starts.hpp).
ConfigurationSpec readConfiguration(const JsonObject& parent, const std::string& key, std::optional<int> rods,
                                    std::vector<SceneProblem>& problems);
// The same from the configuration's own object (an element of a list).
ConfigurationSpec readConfigurationObject(const JsonObject& object, std::optional<int> rods);

// "found "word" (did you mean ...); expected one of a, b, c" at path.
void reportUnknownName(const std::string& path, const std::string& word, const std::vector<std::string>& names,
                       std::vector<SceneProblem>& problems);

// The kind a registry table names `word`, or a problem at path (with a suggestion) and nothing.
template <class Table>
auto pickKind(const std::string& path, const std::string& word, const Table& table,
              std::vector<SceneProblem>& problems) {
  const auto kind = parseKind(table, word);
  if (!kind) reportUnknownName(path, word, namesOf(table), problems);
  return kind;
}

}  // namespace sl::detail

#include "scene/scene_overrides.hpp"

#include <cctype>
#include <optional>

namespace sl {
namespace {

using nlohmann::json;

// One step of a key path: an object member or an array index.
struct Step {
  std::optional<std::string> key;
  std::size_t index = 0;
};

// "runs[1].tolerance" -> runs, [1], tolerance; nullopt if malformed.
std::optional<std::vector<Step>> parsePath(const std::string& path) {
  std::vector<Step> steps;
  std::size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string::npos || close == i + 1) return std::nullopt;
      std::size_t index = 0;
      for (std::size_t k = i + 1; k < close; ++k) {
        if (!std::isdigit(static_cast<unsigned char>(path[k])) || index > 1'000'000) return std::nullopt;
        index = index * 10 + static_cast<std::size_t>(path[k] - '0');
      }
      steps.push_back({std::nullopt, index});
      i = close + 1;
      if (i < path.size() && path[i] == '.') ++i;
      continue;
    }
    std::size_t end = i;
    while (end < path.size() && path[end] != '.' && path[end] != '[') ++end;
    if (end == i) return std::nullopt;
    steps.push_back({path.substr(i, end - i), 0});
    i = end;
    if (i < path.size() && path[i] == '.') {
      ++i;
      if (i == path.size()) return std::nullopt;
    }
  }
  if (steps.empty() || !steps.front().key) return std::nullopt;
  return steps;
}

}  // namespace

namespace {

// "--unset KEY": removes an object member or an array element (a run, say) the scene has.
void applyUnset(json& document, const std::string& key, std::vector<SceneProblem>& problems) {
  const std::string where = "--unset " + key;
  const std::optional<std::vector<Step>> steps = parsePath(key);
  if (!steps) {
    problems.push_back({where, "expected a JSON path such as runs[0].tolerance or view.sphere.orbit"});
    return;
  }
  json* node = &document;
  for (std::size_t s = 0; s < steps->size(); ++s) {
    const Step& step = (*steps)[s];
    const bool exists = step.key ? node->is_object() && node->contains(*step.key)
                                 : node->is_array() && step.index < node->size();
    if (!exists) {
      problems.push_back({where, "the scene has no such key (nothing to remove)"});
      return;
    }
    if (s + 1 == steps->size()) {
      if (step.key)
        node->erase(*step.key);
      else
        node->erase(step.index);
      return;
    }
    node = step.key ? &(*node)[*step.key] : &(*node)[step.index];
  }
}

// Whether `text` is well-formed UTF-8 (nlohmann's serializer checks it as a scene file's parser does).
bool isUtf8(const std::string& text) {
  try {
    (void)json(text).dump();
    return true;
  } catch (const json::type_error&) {
    return false;
  }
}

}  // namespace

void applySceneOverrides(json& document, const std::vector<std::string>& overrides,
                         std::vector<SceneProblem>& problems) {
  for (const std::string& assignment : overrides) {
    if (!document.is_object()) return;  // the file itself is reported by the loader
    if (assignment.rfind(kUnsetPrefix, 0) == 0) {
      applyUnset(document, assignment.substr(std::string(kUnsetPrefix).size()), problems);
      continue;
    }
    if (!isUtf8(assignment)) {  // a scene is UTF-8 JSON: bytes that are not would reach the scene, or an exception
      problems.push_back({"--set", "found " + json(assignment).dump(-1, ' ', false, json::error_handler_t::replace) +
                                       ", which is not UTF-8 text; expected KEY=VALUE in UTF-8"});
      continue;
    }
    const std::size_t equals = assignment.find('=');
    const std::string key = assignment.substr(0, equals);
    const std::string where = "--set " + key;
    const std::optional<std::vector<Step>> steps = equals == std::string::npos ? std::nullopt : parsePath(key);
    if (!steps) {
      problems.push_back({where, "found \"" + assignment +
                                     "\"; expected KEY=VALUE with KEY a JSON path such as linkage.L or runs[1].step"});
      continue;
    }
    const std::string text = assignment.substr(equals + 1);
    json value = json::parse(text, nullptr, false);
    if (value.is_discarded()) value = text;  // not JSON: a string, as a shell user would type it
    json* node = &document;
    bool reached = true;
    for (std::size_t s = 0; s < steps->size() && reached; ++s) {
      const Step& step = (*steps)[s];
      const bool last = s + 1 == steps->size();
      if (step.key) {
        if (node->is_null()) *node = json::object();
        if (!node->is_object()) {
          problems.push_back({where, "a step of the path is not an object in the scene; cannot set \"" + *step.key + "\""});
          reached = false;
          break;
        }
        node = &(*node)[*step.key];
      } else {
        // An element that exists, or the next one: [n] on an array of n elements appends.
        if (!node->is_array() || step.index > node->size()) {
          problems.push_back({where, "expected an existing array element [" + std::to_string(step.index) +
                                         "] or the next one (the scene has " +
                                         (node->is_array() ? std::to_string(node->size()) + " elements there"
                                                           : std::string("no array there")) +
                                         ")"});
          reached = false;
          break;
        }
        if (step.index == node->size()) node->push_back(nullptr);
        node = &(*node)[step.index];
      }
      if (last) *node = value;
    }
  }
}

}  // namespace sl

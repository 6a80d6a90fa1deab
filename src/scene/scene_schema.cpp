#include "scene/scene_schema.hpp"

#include <climits>
#include <cmath>
#include <string>

#include "scene/scene_keys.hpp"

namespace sl {
namespace {

using nlohmann::json;

std::string memberPath(const std::string& object, const std::string& name) {
  return object.empty() ? name : object + "." + name;
}

// The schema of the key at `path` (a run's linkage and start are the scene's, under their own descriptions).
json schemaOf(const std::string& path) {
  const SceneKey& key = sceneKey(path);
  json schema;
  const bool low = std::isfinite(key.minimum), high = std::isfinite(key.maximum);
  switch (key.type) {
    case KeyType::Object: {
      json properties = json::object(), required = json::array();
      // A run's own linkage and start leave out what they like (the scene's is the default).
      const bool runsOwn = path == "runs[i].linkage" || path == "runs[i].initial";
      for (const std::string& name : memberNames(path)) {
        properties[name] = schemaOf(memberPath(path, name));
        if (sceneKey(memberPath(path, name)).required && !runsOwn) required.push_back(name);
      }
      schema = {{"type", "object"}, {"properties", properties}, {"additionalProperties", false}};
      if (!required.empty()) schema["required"] = required;
      break;
    }
    case KeyType::Array: {
      schema = {{"type", "array"}};
      if (low) schema["minItems"] = static_cast<long>(key.minimum);
      const json items = schemaOf(path + "[i]");
      // Panels: a kind by name, or an object with options.
      if (!key.names.empty())
        schema["items"] = {{"oneOf", {{{"enum", key.names}, {"description", "a panel by kind"}}, items}}};
      else
        schema["items"] = items;
      break;
    }
    case KeyType::Number:
      schema = {{"type", "number"}};
      if (low) schema[key.exclusiveMinimum ? "exclusiveMinimum" : "minimum"] = key.minimum;
      if (high) schema["maximum"] = key.maximum;
      break;
    case KeyType::Integer:
      schema = {{"type", "integer"}};
      if (low) schema[key.exclusiveMinimum ? "exclusiveMinimum" : "minimum"] = static_cast<long>(key.minimum);
      if (high) schema["maximum"] = key.maximum >= double(LONG_MAX) ? LONG_MAX : static_cast<long>(key.maximum);
      break;
    case KeyType::String:
      schema = {{"type", "string"}};
      if (low) schema["minLength"] = static_cast<long>(key.minimum);
      if (high) schema["maxLength"] = static_cast<long>(key.maximum);
      break;
    case KeyType::Boolean:
      schema = {{"type", "boolean"}};
      break;
    case KeyType::Numbers: {
      json items{{"type", "number"}};
      if (low) items["minimum"] = key.minimum;
      if (high) items["maximum"] = key.maximum;
      schema = {{"type", "array"}, {"items", items}};
      if (key.count > 0) schema["minItems"] = schema["maxItems"] = key.count;
      break;
    }
    case KeyType::Choice:
      schema = {{"enum", key.names}};
      break;
    case KeyType::Custom:
      schema = json::object();
      break;
  }
  if (!key.schema.is_null()) schema.update(key.schema);
  if (!key.summary.empty()) schema["description"] = key.summary;
  if (!key.fallback.is_null()) schema["default"] = key.fallback;
  return schema;
}

}  // namespace

json sceneSchema() {
  json schema{{"$schema", "https://json-schema.org/draft/2020-12/schema"},
              {"$id", "https://github.com/sphere-linkages/sphere-linkages/scenes/scene.schema.json"},
              {"title", "sphere-linkages scene"}};
  schema.update(schemaOf(""));
  return schema;
}

}  // namespace sl

#pragma once
// A JSON Schema (draft 2020-12) of scene files, for editors that complete and check keys as one types
// (`linkage schema` prints it; scenes/scene.schema.json is a copy, checked equal by the tests). Names come
// from the registry and bounds from contracts/limits.hpp, so the schema follows them. It checks keys, types,
// names and fixed bounds; what depends on other values (L against n, vector sizes against n, a step against
// the duration, the published methods' chain) is left to `linkage validate`.

#include <nlohmann/json.hpp>

namespace sl {

nlohmann::json sceneSchema();

}  // namespace sl

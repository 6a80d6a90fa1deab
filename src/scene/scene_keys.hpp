#pragma once
// Every key of a scene file, described once: its type, its bounds (from contracts/limits.hpp), its default, what
// it means and which field it sets. From this table come the loader's known keys (unknown-key messages), its
// bound checks and their messages, the JSON Schema (`linkage schema`) and the key table of scenes/README.md
// (`linkage schema --markdown`). Rules that relate keys to each other (L against n, a step against the duration,
// which method moves which chain) stay code in the loader, each in one place.

#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sl {

enum class KeyType {
  Object,   // members described by the keys below it
  Array,    // of objects (runs) or of what the key's schema says
  Number,   // finite double
  Integer,  // bounds apply to the value
  String,   // bounds apply to the length in bytes
  Boolean,
  Numbers,  // array of finite doubles; bounds apply to each element, `count` (if > 0) to the size
  Choice,   // a name from a registry table (`names`)
  Custom,   // shape given by `schema` alone (checked by hand in the loader)
};

struct SceneKey {
  // The key's JSON path with [i] for any array index: "runs[i].tolerance".
  std::string path = {};
  KeyType type = KeyType::Number;
  double minimum = -std::numeric_limits<double>::infinity();
  double maximum = std::numeric_limits<double>::infinity();
  bool exclusiveMinimum = false;  // minimum itself is refused ("a positive number")
  int count = 0;                  // Numbers: exactly this many (0: any)
  // What the loader says is allowed when the value is out of bounds: "expected <these words>"; {min} and {max}
  // become the bounds (shortest decimals; integers as integers).
  std::string expected = {};
  nlohmann::json fallback = {};  // the default (null: none, or required, or one that depends on other keys)
  bool required = false;
  std::string summary = {};  // the schema's "description"
  std::string target = {};   // the field it sets
  // scenes/README.md: the row's meaning (empty: the key joins the previous row, e.g. width and height;
  // "-": no row, e.g. members explained in their object's row) and the allowed values; the default follows
  // in parentheses, from `fallback` or, where it is not a plain value, `defaultText`.
  std::string meaning = {};
  std::string allowed = {};
  std::string defaultText = {};
  std::vector<std::string> names = {};  // Choice: the allowed names
  nlohmann::json schema = {};           // further schema keywords (pattern, items, oneOf, ...)
};

// Every key, parents before their members, in the order of scenes/README.md.
const std::vector<SceneKey>& sceneKeys();

// The description of a key by its path, with array indices written [i] or as numbers ("runs[2].step"). A run's
// "linkage" and "initial" are described as the scene's. Throws std::logic_error for a path not described.
const SceneKey& sceneKey(const std::string& path);

// The names of the members of the object at `path` (any index form), in table order.
std::vector<std::string> memberNames(const std::string& path);

// "expected ..." words of a key, with its bounds in place of {min} and {max}.
std::string expectedWords(const SceneKey& key);

// Whether a value lies within a key's bounds.
bool withinBounds(const SceneKey& key, double value);

// The README's key table (markdown), generated from the descriptions.
std::string sceneKeyTable();

}  // namespace sl

#include "scene/json_fields.hpp"

#include <climits>

#include <cmath>
#include <sstream>

#include "scene/did_you_mean.hpp"
#include "scene/scene_keys.hpp"

namespace sl {

using nlohmann::json;

std::string describeJson(const json& value) {
  if (value.is_array()) return "an array of " + std::to_string(value.size());
  if (value.is_object()) return "an object";
  if (value.is_null()) return "null";
  std::string text = value.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return text;
}

std::string indexPath(const std::string& path, size_t index) { return path + "[" + std::to_string(index) + "]"; }

std::optional<double> readNumber(const json& value, const std::string& path, std::vector<SceneProblem>& problems) {
  if (!value.is_number()) {
    problems.push_back({path, "found " + describeJson(value) + "; expected a number"});
    return std::nullopt;
  }
  const double number = value.get<double>();
  if (!std::isfinite(number)) {
    problems.push_back({path, "found a non-finite number; expected a finite number"});
    return std::nullopt;
  }
  return number;
}

JsonObject::JsonObject(const json& value, std::string path, std::vector<SceneProblem>& problems,
                       const std::vector<std::string>& knownKeys)
    : path_(std::move(path)), problems_(&problems) {
  if (!value.is_object()) {
    problems.push_back({path_, "found " + describeJson(value) + "; expected an object"});
    return;
  }
  object_ = &value;
  for (const auto& [key, member] : value.items()) {
    bool known = false;
    for (const std::string& candidate : knownKeys) known = known || candidate == key;
    if (!known) problems.push_back({pathOf(key), "unknown key" + didYouMean(key, knownKeys)});
  }
}

JsonObject::JsonObject(const json& value, std::string path, std::vector<SceneProblem>& problems)
    : JsonObject(value, path, problems, memberNames(path)) {}

bool JsonObject::has(const std::string& key) const { return member(key) != nullptr; }

const json* JsonObject::member(const std::string& key) const {
  if (object_ == nullptr) return nullptr;
  const auto found = object_->find(key);
  return found == object_->end() ? nullptr : &*found;
}

std::string JsonObject::pathOf(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

void JsonObject::report(const std::string& key, const std::string& message) const {
  problems_->push_back({pathOf(key), message});
}

void JsonObject::reportMissing(const std::string& key, const std::string& expected) const {
  if (object_ != nullptr) report(key, "missing; expected " + expected);
}

std::optional<double> JsonObject::number(const std::string& key, bool required) const {
  const json* value = member(key);
  if (value == nullptr) {
    if (required) reportMissing(key, "a number");
    return std::nullopt;
  }
  return readNumber(*value, pathOf(key), *problems_);
}

std::optional<long> JsonObject::integer(const std::string& key, bool required) const {
  const json* value = member(key);
  if (value == nullptr) {
    if (required) reportMissing(key, "an integer");
    return std::nullopt;
  }
  if (!value->is_number_integer()) {
    report(key, "found " + describeJson(*value) + "; expected an integer");
    return std::nullopt;
  }
  // 2^63 .. 2^64 - 1 arrive as unsigned: never let them wrap into a negative long.
  if (value->is_number_unsigned() && value->get<unsigned long long>() > static_cast<unsigned long long>(LONG_MAX)) {
    report(key, "found " + std::to_string(value->get<unsigned long long>()) + "; far beyond any allowed value");
    return std::nullopt;
  }
  return value->get<long>();
}

std::optional<std::string> JsonObject::string(const std::string& key, bool required) const {
  const json* value = member(key);
  if (value == nullptr) {
    if (required) reportMissing(key, "a string");
    return std::nullopt;
  }
  if (!value->is_string()) {
    report(key, "found " + describeJson(*value) + "; expected a string");
    return std::nullopt;
  }
  return value->get<std::string>();
}

std::optional<bool> JsonObject::boolean(const std::string& key) const {
  const json* value = member(key);
  if (value == nullptr) return std::nullopt;
  if (!value->is_boolean()) {
    report(key, "found " + describeJson(*value) + "; expected true or false");
    return std::nullopt;
  }
  return value->get<bool>();
}

std::optional<Eigen::VectorXd> JsonObject::numbers(const std::string& key, bool required) const {
  const json* value = member(key);
  if (value == nullptr) {
    if (required) reportMissing(key, "an array of numbers");
    return std::nullopt;
  }
  if (!value->is_array()) {
    report(key, "found " + describeJson(*value) + "; expected an array of numbers");
    return std::nullopt;
  }
  Eigen::VectorXd result(static_cast<Eigen::Index>(value->size()));
  bool allRead = true;
  for (size_t i = 0; i < value->size(); ++i) {
    const std::optional<double> element = readNumber((*value)[i], indexPath(pathOf(key), i), *problems_);
    allRead = allRead && element.has_value();
    if (element) result(static_cast<Eigen::Index>(i)) = *element;
  }
  if (!allRead) return std::nullopt;
  return result;
}

bool JsonObject::checkPositive(const std::string& key, double value) const {
  if (value > 0) return true;
  std::ostringstream message;
  message << "found " << value << "; expected a positive number";
  report(key, message.str());
  return false;
}

bool JsonObject::checkBounds(const std::string& key, double value) const {
  std::ostringstream found;
  found << value;
  return checkBounds(key, value, found.str());
}

bool JsonObject::checkBounds(const std::string& key, long value) const {
  return checkBounds(key, static_cast<double>(value), std::to_string(value));
}

bool JsonObject::checkBounds(const std::string& key, double value, const std::string& found) const {
  const SceneKey& described = sceneKey(pathOf(key));
  if (withinBounds(described, value)) return true;
  report(key, "found " + found + "; expected " + expectedWords(described));
  return false;
}

bool JsonObject::checkElements(const std::string& key, const Eigen::VectorXd& value) const {
  const SceneKey& described = sceneKey(pathOf(key));
  for (const double element : value)
    if (!withinBounds(described, element)) {
      report(key, "expected " + expectedWords(described));
      return false;
    }
  return true;
}

bool JsonObject::checkSize(const std::string& key, const Eigen::VectorXd& value, long expected,
                           const std::string& what) const {
  if (value.size() == expected) return true;
  report(key, "found " + std::to_string(value.size()) + " numbers; expected " + std::to_string(expected) + " (" + what +
                  ")");
  return false;
}

}  // namespace sl

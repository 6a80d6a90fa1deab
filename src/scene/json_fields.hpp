#pragma once
// Typed reading of JSON values that records problems instead of throwing, so validation reports
// every problem in a scene at once. Each problem names the JSON path, what was found and what is allowed.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "scene/scene_problems.hpp"

namespace sl {

// A short description of a JSON value for messages: "-0.5", "\"rk5\"", "an array of 3", "null".
std::string describeJson(const nlohmann::json& value);

// The members of one JSON object. Construction reports a non-object and every unknown key (with a
// "did you mean" for near misses); reads are typed and report wrong types and non-finite numbers.
// A missing optional key leaves the default; a missing required key is reported.
class JsonObject {
 public:
  JsonObject(const nlohmann::json& value, std::string path, std::vector<SceneProblem>& problems,
             const std::vector<std::string>& knownKeys);
  // The known keys are those scene/scene_keys.cpp describes under `path`.
  JsonObject(const nlohmann::json& value, std::string path, std::vector<SceneProblem>& problems);

  bool isObject() const { return object_ != nullptr; }
  bool has(const std::string& key) const;
  const nlohmann::json* member(const std::string& key) const;
  std::string pathOf(const std::string& key) const;
  void report(const std::string& key, const std::string& message) const;
  void reportMissing(const std::string& key, const std::string& expected) const;

  // Each returns the value read, or nullopt (missing or wrong: a problem is then recorded if required).
  std::optional<double> number(const std::string& key, bool required = false) const;
  std::optional<long> integer(const std::string& key, bool required = false) const;
  std::optional<std::string> string(const std::string& key, bool required = false) const;
  std::optional<bool> boolean(const std::string& key) const;
  std::optional<Eigen::VectorXd> numbers(const std::string& key, bool required = false) const;

  // Checks that record a problem naming the key; they return whether the value passed.
  bool checkPositive(const std::string& key, double value) const;
  bool checkSize(const std::string& key, const Eigen::VectorXd& value, long expected, const std::string& what) const;
  // Against the bounds of the key's description (scene/scene_keys.hpp), in its words: "found 0; expected an
  // integer from 1 to 1000".
  bool checkBounds(const std::string& key, double value) const;
  bool checkBounds(const std::string& key, long value) const;  // integers: found as given
  // Every element within the description's bounds, or "expected <its words>".
  bool checkElements(const std::string& key, const Eigen::VectorXd& value) const;

 private:
  bool checkBounds(const std::string& key, double value, const std::string& found) const;

  const nlohmann::json* object_ = nullptr;
  std::string path_;
  std::vector<SceneProblem>* problems_;
};

// "runs[2]"
std::string indexPath(const std::string& path, size_t index);

// A finite JSON number, or a problem recorded under path.
std::optional<double> readNumber(const nlohmann::json& value, const std::string& path,
                                 std::vector<SceneProblem>& problems);

}  // namespace sl

// The JSON Schema of scene files (scene/scene_schema.hpp): the shipped copy is what `linkage schema` prints,
// it accepts every shipped scene and rejects the bad scenes the loader refuses for a key, type, name or fixed
// bound; checked by an independent validator (Debian's python3-jsonschema, draft 2020-12).
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scene/scene_schema.hpp"
#include "support/child_process.hpp"
#include "support/files.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

// "ok FILE" or "invalid FILE: message" per file, from python3-jsonschema.
std::string validateWithPython(const std::string& schema, const std::vector<std::string>& files) {
  TempFolder folder;
  writeFile(folder.path() / "schema.json", schema);
  writeFile(folder.path() / "check.py", R"(import json, sys
from jsonschema import Draft202012Validator
schema = json.load(open(sys.argv[1]))
Draft202012Validator.check_schema(schema)
validator = Draft202012Validator(schema)
for name in sys.argv[2:]:
    try:
        document = json.load(open(name))
    except ValueError as error:
        print("unreadable", name); continue
    errors = sorted(validator.iter_errors(document), key=lambda e: list(e.path))
    print(("invalid " + name + ": " + errors[0].message) if errors else ("ok " + name))
)");
  std::string command = "/usr/bin/python3 check.py schema.json";
  for (const std::string& file : files) command += " '" + file + "'";
  const ProcessResult result = runShell(command, folder.path());
  EXPECT_EQ(result.code, 0) << result.err;
  return result.out;
}

TEST(SceneSchema, ShippedCopyIsWhatTheProgramPrints) {
  EXPECT_EQ(readFile(sourcePath("scenes/scene.schema.json")), sceneSchema().dump(2) + "\n")
      << "regenerate it: build/linkage schema > scenes/scene.schema.json";
}

TEST(SceneSchema, AcceptsEveryShippedSceneAndRejectsBadKeysTypesNamesAndBounds) {
  std::vector<std::string> shipped;
  for (const auto& entry : fs::directory_iterator(sourcePath("scenes")))
    if (entry.path().extension() == ".json" && entry.path().filename() != "scene.schema.json")
      shipped.push_back(entry.path().string());
  ASSERT_GE(shipped.size(), 9u);
  const std::vector<std::string> bad{
      "unknown_key.json",     "unknown_nested_key.json", "wrong_type.json",         "wrong_type_array.json",
      "too_few_rods.json",    "rods_not_integer.json",   "empty_run_name.json",     "no_runs.json",
      "unknown_method.json",  "unknown_integrator.json", "negative_duration.json",  "zero_fps.json",
      "negative_step.json",   "zero_tolerance.json",     "size_too_large.json",     "unknown_panel.json",
      "unsafe_name.json",     "missing_runs.json",       "field_of_view_too_narrow.json",
      "hinge_mass_negative.json", "color_by_unknown.json"};
  std::vector<std::string> files = shipped;
  for (const std::string& name : bad) files.push_back(badSceneFolder() + name);
  const std::string report = validateWithPython(sceneSchema().dump(), files);
  for (const std::string& file : shipped) EXPECT_NE(report.find("ok " + file), std::string::npos) << report;
  for (const std::string& name : bad)
    EXPECT_NE(report.find("invalid " + badSceneFolder() + name), std::string::npos) << name << "\n" << report;
}

}  // namespace
}  // namespace sl::testing

// The JSON Schema of scene files (scene/scene_schema.hpp): the shipped copy is what `linkage schema` prints,
// it accepts every shipped scene and rejects the bad scenes the loader refuses for a key, type, name or fixed
// bound; checked by an independent validator (Debian's python3-jsonschema, draft 2020-12).
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contracts/output_settings.hpp"
#include "contracts/run_config.hpp"
#include "contracts/view_settings.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_schema.hpp"
#include "support/child_process.hpp"
#include "support/files.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

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

// The key table of scenes/README.md comes from the same descriptions as the schema.
TEST(SceneSchema, ReadmeKeyTableIsWhatTheProgramPrints) {
  const std::string readme = readFile(sourcePath("scenes/README.md"));
  const std::size_t start = readme.find("| key | meaning | allowed (default) |");
  ASSERT_NE(start, std::string::npos);
  const std::size_t end = readme.find("\n\n", start);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(readme.substr(start, end + 1 - start), sceneKeyTable())
      << "regenerate the table in scenes/README.md from: build/linkage schema --markdown";
}

// Defaults in the schema are the defaults the loader leaves in place: a scene that gives only what is
// required loads with exactly the defaults the schema states.
TEST(SceneSchema, DefaultsAreTheLoadersDefaults) {
  const json schema = sceneSchema();
  const json& run = schema["properties"]["runs"]["items"]["properties"];
  const RunConfig config;
  EXPECT_EQ(run["tolerance"]["default"], config.tolerance);
  EXPECT_EQ(run["step"]["default"], config.step);
  EXPECT_EQ(run["method"]["default"], nameOf(config.method));
  EXPECT_EQ(run["integrator"]["default"], nameOf(config.integrator));
  EXPECT_EQ(run["watchdog"]["properties"]["max_steps"]["default"], config.maxSteps);
  const json& view = schema["properties"]["view"]["properties"];
  EXPECT_EQ(view["camera"]["properties"]["field_of_view"]["default"], CameraSpec{}.fieldOfViewDegrees);
  EXPECT_EQ(view["background"]["default"], json::parse("[0.96, 0.95, 0.92]"));
  EXPECT_EQ(schema["properties"]["output"]["properties"]["fps"]["default"], OutputSettings{}.fps);
  // The JSON Schema validator reads them too: every default is a valid value of its key.
  json scene = json::parse(readFile(sourcePath("scenes/default.json")));
  scene["runs"][0]["tolerance"] = run["tolerance"]["default"];
  scene["view"]["background"] = view["background"]["default"];
  TempFolder folder;
  writeFile(folder.path() / "defaults.json", scene.dump());
  const std::string report = validateWithPython(schema.dump(), {(folder.path() / "defaults.json").string()});
  EXPECT_NE(report.find("ok "), std::string::npos) << report;
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

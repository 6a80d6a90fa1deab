// `linkage schema`: the JSON Schema of scene files on stdout (scene/scene_schema.hpp), for editors.

#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/summary.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_schema.hpp"

namespace sl {

void addSchemaCommand(CLI::App& app) {
  auto quiet = std::make_shared<bool>(false);
  CLI::App* command = app.add_subcommand("schema", "Print the JSON Schema of scene files (for editors)");
  static bool markdown = false;
  command->add_flag("--markdown", markdown,
                    "print the key table of scenes/README.md instead (from the same descriptions)");
  command->add_flag("--quiet", *quiet, "no summary line on stderr");
  command->footer(
      "A copy ships as scenes/scene.schema.json. In VS Code, for example, map it in settings.json:\n"
      "  \"json.schemas\": [{ \"fileMatch\": [\"scenes/*.json\"], \"url\": \"./scenes/scene.schema.json\" }]\n"
      "Example: linkage schema > my-scenes/scene.schema.json");
  command->callback([quiet] {
    const CommandSummary summary("schema", *quiet);
    std::cout << (markdown ? sceneKeyTable() : sceneSchema().dump(2) + "\n");
    summary.print(markdown ? "the key table of scene files -> standard output"
                           : "the JSON Schema of scene files -> standard output");
  });
}

}  // namespace sl

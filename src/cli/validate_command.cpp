// `linkage validate SCENE.json`: every check a render makes before working, and nothing else.

#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/scene_input.hpp"
#include "output/distinct_files.hpp"
#include "cli/summary.hpp"
#include "scene/output_folder.hpp"

namespace sl {

namespace {

struct ValidateArguments {
  std::string file;
  std::vector<std::string> overrides;
  bool quiet = false;
};

void runValidate(const ValidateArguments& args) {
  const std::string file = args.file == "-" ? kStandardInputName : args.file;
  const CommandSummary summary("validate", args.quiet);
  const Scene scene = loadSceneForCommand(args.file, args.overrides);
  std::vector<SceneProblem> problems = checkOutputFolder(scene.output.folder, "output.folder");
  if (!scene.output.video.empty())
    for (SceneProblem& problem : checkVideoPath(scene.output.video, "output.video")) problems.push_back(problem);
  if (!scene.output.video.empty() && sameFile(scene.output.video, file))
    problems.push_back({"output.video", "is the scene file itself; an output never replaces an input"});
  failOnProblems(file, problems);
  std::vector<std::string> notes;
  const std::vector<InitialState> starts = runStarts(scene, &notes);
  if (!args.quiet)
    for (const std::string& note : notes) std::cerr << "linkage validate: note: " << note << "\n";
  // Every start, run and family, as render and simulate set them up.
  startRuns(scene, starts);
  startFamilies(scene, starts);
  std::cout << file << ": ok: \"" << scene.name << "\", " << scene.chain.rods << " rods, L = " << scene.chain.baseLength
            << ", " << scene.frameCount() << " frames of " << scene.output.size.width << "x" << scene.output.size.height
            << " at " << scene.output.fps << " fps, runs:";
  for (const RunSpec& run : scene.runs)
    std::cout << " \"" << run.name << "\" (" << nameOf(run.config.method) << ", " << nameOf(run.config.integrator)
              << (run.family ? ", " + std::string(traitsOf(kFamilyKinds, run.family->kind).name) + " of " +
                                   std::to_string(run.family->count)
                             : std::string())
              << ")";
  std::cout << '\n';
  summary.print(file + " is valid");
}

}  // namespace

void addValidateCommand(CLI::App& app) {
  auto args = std::make_shared<ValidateArguments>();
  CLI::App* command = app.add_subcommand("validate", "Check a scene file and report every problem; writes nothing");
  command->add_option("scene", args->file, "scene file (JSON, see scenes/README.md; - reads standard input)")->required();
  addSceneOverrideOption(*command, args->overrides);
  command->add_flag("--quiet", args->quiet, "no notes or summary line on stderr (the report on stdout stays)");
  command->footer("Example: linkage validate scenes/default.json\nExit status 0 when the scene is valid, 2 when not.");
  command->callback([args] { runValidate(*args); });
}

}  // namespace sl

#include "cli/scene_input.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "cli/exit_codes.hpp"
#include "cli/interrupt.hpp"
#include "cli/motion_starts.hpp"
#include "contracts/limits.hpp"
#include "output/atomic_file.hpp"
#include "scene/json_fields.hpp"
#include "scene/output_folder.hpp"
#include "scene/scene_overrides.hpp"
#include "simulation/family.hpp"
#include "simulation/initial_state.hpp"

namespace sl {

void failOnProblems(const std::string& file, const std::vector<SceneProblem>& problems) {
  if (!problems.empty()) throw CommandExit(kExitBadInput, formatProblems(file, problems));
}

namespace {

// "-": the scene from standard input, read once and never more than a scene can sensibly be.
Scene loadSceneFromStandardInput(const std::vector<std::string>& overrides) {
  std::string text(limits::kMaxSceneBytes + 1, '\0');
  std::cin.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (std::cin.bad()) throw SceneError(kStandardInputName, {{"", "cannot read standard input"}});
  text.resize(static_cast<std::size_t>(std::cin.gcount()));
  if (text.size() > limits::kMaxSceneBytes)
    throw SceneError(kStandardInputName, {{"", "larger than " + std::to_string(limits::kMaxSceneBytes >> 20) +
                                                   " MiB; a scene file is a few kilobytes"}});
  return parseScene(text, kStandardInputName, overrides);
}

}  // namespace

Scene loadSceneForCommand(const std::string& file, const std::vector<std::string>& overrides) {
  Scene scene;
  try {
    scene = file == "-" ? loadSceneFromStandardInput(overrides) : loadScene(file, overrides);
  } catch (const SceneError& error) {
    throw CommandExit(kExitBadInput, error.what());
  }
  // Found motions are found here, once, before anything runs (every command sees the same starts); the searches
  // answer SIGINT and SIGTERM between their shots.
  try {
    failOnProblems(scene.file, resolveMotionStarts(scene));
  } catch (const RunCancelled&) {
    stopIfInterrupted("nothing was written");
    throw;
  }
  return scene;
}

void addSceneOverrideOption(CLI::App& command, std::vector<std::string>& overrides) {
  command
      .add_option("--set", overrides,
                  "override a scene key by its JSON path, e.g. --set linkage.L=3.2 --set output.fps=60 "
                  "--set runs[0].method=ambient, or append to an array: --set 'runs[2]={\"name\": \"b\"}' on a "
                  "scene of 2 runs (repeatable; checked like the file)")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);
  // After --set (CLI11 runs option callbacks in the order they were added, and --set assigns its whole list):
  // the removals join the list and are applied after the assignments.
  command
      .add_option_function<std::vector<std::string>>(
          "--unset",
          [&overrides](const std::vector<std::string>& keys) {
            for (const std::string& key : keys) overrides.push_back(kUnsetPrefix + key);
          },
          "remove a scene key or array element by its JSON path, e.g. --unset runs[0].tolerance --unset runs[1] "
          "(repeatable; applied after every --set)")
      ->type_name("KEY")
      ->allow_extra_args(false);
}

namespace {

// "runs[i]", or "runs[i].key": where a run's problem is written in the scene (the loader's indexPath).
std::string runPath(size_t i, const std::string& key = "") {
  return indexPath("runs", i) + (key.empty() ? "" : "." + key);
}

}  // namespace

std::vector<InitialState> runStarts(const Scene& scene, std::vector<std::string>* notes) {
  std::vector<InitialState> starts;
  for (size_t i = 0; i < scene.runs.size(); ++i) {
    const RunSpec& run = scene.runs[i];
    // A start the scene shares is reported once, where it is written.
    const std::string where = run.ownInitial ? runPath(i, "initial") : "initial";
    try {
      StartAdjustment moved;
      starts.push_back(initialStateFromSpec(run.chain, run.initial, &moved));
      requireCoverableMotion(run.chain, starts.back(), scene.duration);
      if (notes && (moved.positions > 1e-9 || moved.velocities > 1e-9)) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "the start of run \"%s\" (%s) was moved onto the rod constraints: hinges by up to %.3g, "
                      "velocities by up to %.3g of the largest",
                      run.name.c_str(), where.c_str(), moved.positions, moved.velocities);
        notes->push_back(text);
      }
    } catch (const std::invalid_argument& error) {
      failOnProblems(scene.file, {{where, error.what()}});
      throw;
    }
  }
  return starts;
}

std::vector<Trajectory> startRuns(const Scene& scene, const std::vector<InitialState>& starts) {
  std::vector<Trajectory> runs;
  for (size_t i = 0; i < scene.runs.size(); ++i) {
    try {
      runs.emplace_back(scene.runs[i].chain, starts.at(i), scene.runs[i].config);
      runs.back().setCancellation(interruptRequested);  // SIGINT/SIGTERM answered within one step
    } catch (const std::invalid_argument& error) {
      failOnProblems(scene.file, {{runPath(i), error.what()}});
      throw;
    }
  }
  return runs;
}

std::vector<std::vector<Trajectory>> startFamilies(const Scene& scene, const std::vector<InitialState>& starts) {
  std::vector<std::vector<Trajectory>> families(scene.runs.size());
  for (size_t i = 0; i < scene.runs.size(); ++i) {
    const RunSpec& run = scene.runs[i];
    if (!run.family) continue;
    try {
      families[i] = familyMembers(run.chain, starts.at(i), *run.family, run.config, interruptRequested);
    } catch (const std::invalid_argument& error) {
      failOnProblems(scene.file, {{runPath(i, "family"), error.what()}});
      throw;
    }
  }
  return families;
}

void requireOutputsBeforeWork(const std::string& command, const std::vector<NamedFile>& inputs,
                              const std::vector<NamedFile>& outputs) {
  const auto fail = [&](const std::string& message) { throw CommandExit(kExitBadInput, "linkage " + command + ": " + message); };
  for (const NamedFile& output : outputs) {
    if (output.path.empty()) continue;
    try {
      outputTarget(output.path);
    } catch (const std::invalid_argument& error) {
      fail(output.role + ": " + error.what());
    }
    for (const SceneProblem& problem : checkOutputFile(output.path, output.role))
      fail(problem.jsonPath + ": " + problem.message +
           (problem.message.find(output.path) == std::string::npos ? " (writing " + output.path + ")" : ""));
  }
  try {
    requireDistinctFiles(inputs, outputs);
  } catch (const std::invalid_argument& error) {
    fail(error.what());
  }
  for (const NamedFile& output : outputs)
    if (const auto parent = std::filesystem::path(output.path).parent_path(); !output.path.empty() && !parent.empty())
      std::filesystem::create_directories(parent);
}

void addNoClobberFlag(CLI::App& command, bool& noClobber) {
  command.add_flag("--no-clobber", noClobber, "never replace a file: an output that exists already is refused (exit 2)");
}

void refuseExistingOutputs(const std::string& command, const std::vector<NamedFile>& outputs) {
  for (const NamedFile& output : outputs)
    if (!output.path.empty() && std::filesystem::exists(output.path))
      throw CommandExit(kExitBadInput, "linkage " + command + ": " + output.role + ": " + output.path +
                                           " exists, and --no-clobber never replaces a file");
}

}  // namespace sl

#pragma once
// Scenes as the commands read them. Every command goes through these, so that what `validate` accepts,
// `render` and `simulate` accept too.

#include <string>
#include <vector>

#include "contracts/run_config.hpp"
#include "output/distinct_files.hpp"
#include "scene/scene.hpp"
#include "scene/scene_loader.hpp"
#include "simulation/trajectory.hpp"

namespace CLI {
class App;
}

namespace sl {

// How messages name a scene read from standard input.
inline constexpr const char* kStandardInputName = "(standard input)";

// Loads and validates, with the command line's --set KEY=VALUE overrides; on problems throws
// CommandExit(kExitBadInput) listing them all. File "-" is standard input.
Scene loadSceneForCommand(const std::string& file, const std::vector<std::string>& overrides = {});

// Adds `--set KEY=VALUE` (repeatable) to a command that reads a scene.
void addSceneOverrideOption(CLI::App& command, std::vector<std::string>& overrides);

// Throws CommandExit(kExitBadInput) listing the problems, if any.
void failOnProblems(const std::string& file, const std::vector<SceneProblem>& problems);

// A command's outputs checked before any work, the one rule of every command: each a usable file path in a place
// that can be written (checkOutputFile; not a folder, a device or a link to one), none an input or another output
// (requireDistinctFiles). A problem ends the command with exit 2 naming the option, before anything is computed
// or written; then the outputs' folders are created.
void requireOutputsBeforeWork(const std::string& command, const std::vector<NamedFile>& inputs,
                              const std::vector<NamedFile>& outputs);

// --no-clobber, the one flag and rule of the commands that write files: an output that exists already ends the
// command with exit 2 naming it, before any work.
void addNoClobberFlag(CLI::App& command, bool& noClobber);
void refuseExistingOutputs(const std::string& command, const std::vector<NamedFile>& outputs);

// Each run's start as an InitialState (the scene's "initial", or the run's own, on the run's own linkage), and
// one Trajectory per run from it. A start or run the simulation refuses is a problem of the scene:
// CommandExit(kExitBadInput) naming the file and the JSON path ("initial" or "runs[i].initial", "runs[i]").
// `notes` (if given) receives a line for each start by hinges that had to move onto the rod constraints.
std::vector<InitialState> runStarts(const Scene& scene, std::vector<std::string>* notes = nullptr);
std::vector<Trajectory> startRuns(const Scene& scene, const std::vector<InitialState>& starts);
// The members of each run's family (none for a run without one), from the run's start; a family that cannot
// start is a problem of runs[i].family.
std::vector<std::vector<Trajectory>> startFamilies(const Scene& scene, const std::vector<InitialState>& starts);

}  // namespace sl

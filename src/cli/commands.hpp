#pragma once
// The subcommands of `linkage`, one file each (<name>_command.cpp). Each adds itself to the app with
// its options and a callback that does the work and throws CommandExit (exit_codes.hpp) to fail.

namespace CLI {
class App;
}

namespace sl {

// Every command below, in the order `linkage --help` lists them (commands.cpp): main() and the tests that walk
// every command's options use this one list.
void addCommands(CLI::App& app);

void addValidateCommand(CLI::App& app);
void addSimulateCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addDiffCommand(CLI::App& app);
void addListMethodsCommand(CLI::App& app);
// `linkage bench`: work-precision sweeps, CSV, charts and the cheapest-setting table.
void addBenchCommand(CLI::App& app);
// `linkage stability`: stability maps over grids of starts, sharded and merged.
void addStabilityCommand(CLI::App& app);
// `linkage geometry`: curvature, bending and stiffness of the configuration sphere.
void addGeometryCommand(CLI::App& app);
// `linkage still`: the frame at one time, as a PNG file.
void addStillCommand(CLI::App& app);
// `linkage contact-sheet`: evenly spaced frames of a render in one picture.
void addContactSheetCommand(CLI::App& app);
// `linkage numbers`: what a scene computes (energy, drift, stops, conjugate points, curvature) as JSON.
void addNumbersCommand(CLI::App& app);
// `linkage connect`: the motions from the scene's start to a target shape (two routes).
void addConnectCommand(CLI::App& app);
// `linkage periodic`: closed geodesics of the scene's linkage (3 or 4 rods).
void addPeriodicCommand(CLI::App& app);
// `linkage schema`: the JSON Schema of scene files.
void addSchemaCommand(CLI::App& app);

}  // namespace sl

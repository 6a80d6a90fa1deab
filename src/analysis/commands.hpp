#pragma once
// The two analysis subcommands of `linkage`, defined in src/cli/bench_command.cpp and
// src/cli/stability_command.cpp (library sl_analysis_commands). Each adds its subcommand, with options and
// a callback that does the work, to the application.

namespace CLI {
class App;
}

namespace sl {

// `linkage bench`: work-precision sweeps, CSV, charts and the cheapest-setting table.
void addBenchCommand(CLI::App& app);

// `linkage stability`: stability maps over grids of starts, sharded and merged.
void addStabilityCommand(CLI::App& app);

}  // namespace sl

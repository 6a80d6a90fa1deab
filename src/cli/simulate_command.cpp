// `linkage simulate SCENE.json [--csv FILE] [--dt DT]`: the scene's runs as trajectory CSV, no rendering.

#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/interrupt.hpp"
#include "cli/run_report.hpp"
#include "cli/scene_input.hpp"
#include "contracts/time_grid.hpp"
#include "output/atomic_file.hpp"
#include "simulation/trajectory_csv.hpp"

namespace sl {

namespace {

struct SimulateArguments {
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::string scene;
  std::string csv;  // empty: stdout
  double dt = 0;    // 0: the frame times k / fps
};

// k / fps for every frame, or k * dt up to the duration.
std::vector<double> sampleTimes(const Scene& scene, double dt) {
  return dt <= 0 ? frameTimes(scene.duration, scene.output.fps) : uniformTimes(scene.duration, dt);
}

// Written in chunks so that SIGINT/SIGTERM is noticed within one chunk's work. A run that stops ends
// with one row at its stop time whose status is the reason (trajectory_csv.hpp); nothing follows it.
void writeRun(std::ostream& out, const std::string& name, Trajectory& trajectory, const std::vector<double>& times) {
  const size_t chunk = 256;
  for (size_t first = 0; first < times.size(); first += chunk) {
    stopIfInterrupted("no CSV was written");
    const std::vector<double> part(times.begin() + first, times.begin() + std::min(times.size(), first + chunk));
    writeTrajectoryCsv(out, name, trajectory, part, false);
    if (trajectory.stop() && trajectory.stop()->time < part.back()) return;
  }
}

void runSimulate(const SimulateArguments& args) {
  const Scene scene = loadSceneForCommand(args.scene, args.overrides);
  // The CSV for --csv is built in memory (then written atomically): keep it below about a gigabyte.
  if (args.dt > 0 && scene.duration / args.dt > 5e6) {
    throw CommandExit(kExitBadInput, "--dt " + std::to_string(args.dt) +
                                         " gives more than 5e6 samples per run; expected a larger step");
  }
  installInterruptHandlers();
  const std::vector<double> times = sampleTimes(scene, args.dt);
  std::vector<Trajectory> runs = startRuns(scene, sceneStart(scene));
  // To a file: the whole CSV is kept and written at once, so an interrupted run leaves no partial file.
  std::ostringstream buffer;
  std::ostream& out = args.csv.empty() ? std::cout : buffer;
  out << trajectoryCsvHeader(scene.chain.rods) << '\n';
  for (size_t i = 0; i < runs.size(); ++i) writeRun(out, scene.runs[i].name, runs[i], times);
  reportStops(scene, runs);
  if (!args.csv.empty()) output::writeFileAtomically(args.csv, buffer.str());
}

}  // namespace

void addSimulateCommand(CLI::App& app) {
  auto args = std::make_shared<SimulateArguments>();
  CLI::App* command =
      app.add_subcommand("simulate", "Integrate the scene's runs and write trajectory CSV (no rendering)");
  command->add_option("scene", args->scene, "scene file (JSON, see scenes/README.md)")->required();
  addSceneOverrideOption(*command, args->overrides);
  command->add_option("--csv", args->csv, "write the CSV here instead of stdout (written whole or not at all)");
  command->add_option("--dt", args->dt, "sample every DT time units (default: the frame times k / fps)")
      ->check(CLI::PositiveNumber);
  command->footer(
      "Columns: run,time,phi,t,phidot,tdot,energy,p1x,p1y,...,status (4 rods; chart coordinates c1.. and rates v1..\n"
      "for other n). A run that stops ends with one row at its stop time whose status is the reason.\n"
      "Example: linkage simulate scenes/comparison.json --dt 0.01 --csv comparison.csv");
  command->callback([args] { runSimulate(*args); });
}

}  // namespace sl

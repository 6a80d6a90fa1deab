// `linkage numbers SCENE.json`: what a scene computes, as one JSON document: per run its energy and the worst
// drift over the motion, how it ended (ran to the duration, or stopped: why and when), its conjugate points (runs
// with Jacobi fields); for 4 rods the curvature summary of the configuration sphere (K range, area,
// Gauss-Bonnet). One command instead of simulate, geometry and reading the CSVs.

#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/geometry_json.hpp"
#include "cli/interrupt.hpp"
#include "cli/run_report.hpp"
#include "cli/scene_input.hpp"
#include "cli/summary.hpp"
#include "output/atomic_file.hpp"

namespace sl {

namespace {

struct NumbersArguments {
  std::string scene, out;
  std::vector<std::string> overrides;
  bool quiet = false;
};

nlohmann::json runNumbers(const RunSpec& spec, Trajectory& run, double duration, std::size_t members) {
  const std::optional<Sample> start = run.sampleAt(0);
  nlohmann::json json{{"name", spec.name},
                      {"method", nameOf(spec.config.method)},
                      {"integrator", nameOf(spec.config.integrator)},
                      {"L", spec.chain.baseLength}};
  if (start) json["energy"] = start->energy;
  run.sampleAt(duration);  // the whole motion, or up to its stop
  const std::optional<StopInfo>& stop = run.stop();
  const bool stopped = stop && stop->time <= duration;
  json["outcome"] = stopped ? "stopped" : "ran";
  json["end_time"] = stopped ? stop->time : duration;
  if (stopped)
    json["stop"] = {{"reason", nameOf(stop->reason)}, {"time", stop->time}, {"detail", stop->detail()}};
  // Over every step integrated: beyond `duration` by at most the step in flight.
  json["max_relative_energy_drift"] = run.invariantExtremes().maxRelativeEnergyDrift;
  json["max_rod_length_error"] = run.invariantExtremes().maxRodLengthError;
  json["steps"] = run.steps();
  json["vector_field_evaluations"] = run.vectorFieldEvaluations();
  if (spec.config.jacobi) {
    nlohmann::json conjugate = nlohmann::json::array();
    for (const double t : run.conjugateTimes())
      if (t <= json["end_time"].get<double>()) conjugate.push_back(t);
    json["conjugate_points"] = conjugate;
  }
  if (members > 0) json["family_members"] = members;
  return json;
}

void runNumbersCommand(const NumbersArguments& args) {
  installInterruptHandlers();
  const CommandSummary summary("numbers", args.quiet);
  requireOutputsBeforeWork("numbers", {{"the scene", args.scene}}, {{"--out", args.out}});
  const Scene scene = loadSceneForCommand(args.scene, args.overrides);
  const std::vector<InitialState> starts = runStarts(scene);
  std::vector<Trajectory> runs = startRuns(scene, starts);
  const std::vector<std::vector<Trajectory>> families = startFamilies(scene, starts);
  nlohmann::json document{{"scene", scene.name},
                          {"rods", scene.chain.rods},
                          {"L", scene.chain.baseLength},
                          {"duration", scene.duration}};
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    runs[i].setCancellation(interruptRequested);
    try {
      list.push_back(runNumbers(scene.runs[i], runs[i], scene.duration, families[i].size()));
    } catch (const RunCancelled&) {
      stopIfInterrupted("nothing was written");
    }
  }
  document["runs"] = list;
  if (scene.chain.rods == 4 && !scene.chain.isSlack()) document["geometry"] = summaryJson(curvatureSummary(scene.chain));
  const std::string text = document.dump(2) + "\n";
  if (args.out.empty()) {
    std::cout << text;
  } else {
    writeFileAtomically(args.out, text);
  }
  reportStops(scene, runs, args.quiet);
  summary.print(std::to_string(runs.size()) + " run" + (runs.size() == 1 ? "" : "s") + " of \"" + scene.name + "\"" +
                    (document.contains("geometry") ? " and its curvature" : "") + " -> " +
                    (args.out.empty() ? "standard output" : args.out),
                "; " + runOutcomes(scene, runs, scene.duration));
}

}  // namespace

void addNumbersCommand(CLI::App& app) {
  auto args = std::make_shared<NumbersArguments>();
  CLI::App* command =
      app.add_subcommand("numbers", "Print what a scene computes as JSON: energy, drift, stops, conjugate points, K");
  command->add_option("scene", args->scene, "scene file (JSON, see scenes/README.md; - reads standard input)")
      ->required();
  addSceneOverrideOption(*command, args->overrides);
  command->add_option("--out", args->out, "write here instead of standard output (written whole or not at all)");
  command->add_flag("--quiet", args->quiet, "no run reports or summary line");
  command->footer(
      "Per run: energy, max_relative_energy_drift, max_rod_length_error, outcome (ran / stopped), end_time, stop\n"
      "{reason, time, detail}, steps, vector_field_evaluations, conjugate_points (runs with \"jacobi\": true).\n"
      "4 rods: geometry {area, total_curvature, K_min, K_max, ...} as `linkage geometry --summary` prints it.\n"
      "Examples:\n  linkage numbers scenes/jacobi.json\n  linkage numbers scenes/default.json --set linkage.L=3.2");
  command->callback([args] { runNumbersCommand(*args); });
}

}  // namespace sl

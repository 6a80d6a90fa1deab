// `linkage bench`: work-precision sweeps (src/analysis/work_precision.hpp) over the shipped starts,
// written as CSV, gnuplot charts and a table of the cheapest setting reaching each target error.

#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include <CLI/CLI.hpp>

#include "analysis/csv_table.hpp"
#include "analysis/gnuplot.hpp"
#include "analysis/option_checks.hpp"
#include "analysis/work_precision.hpp"
#include "analysis/work_precision_charts.hpp"
#include "cli/chart_formats.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "cli/summary.hpp"
#include "cli/number_options.hpp"
#include "contracts/limits.hpp"
#include "contracts/time_grid.hpp"
#include "contracts/registry.hpp"
#include "output/atomic_file.hpp"
#include "output/temporary_file.hpp"

namespace sl {

namespace {

struct BenchArguments {
  std::vector<std::string> starts;
  std::vector<std::string> methods, integrators;  // as given; parsed into options
  WorkPrecisionOptions options;
  std::vector<double> targets = {1e-6, 1e-9, 1e-10, 1e-12};
  std::string out = "renders/bench";
  bool quick = false;
  bool charts = true;
  bool quiet = false;
  std::string chartFormats;
};

std::vector<NamedStart> chosenStarts(const std::vector<std::string>& names) {
  const auto shipped = shippedStarts();
  if (names.empty()) return shipped;
  std::vector<NamedStart> chosen;
  for (const auto& name : names) {
    bool found = false;
    for (const auto& start : shipped)
      if (start.name == name) {
        chosen.push_back(start);
        found = true;
      }
    if (!found) {
      std::string known;
      for (const auto& start : shipped) known += (known.empty() ? "" : ", ") + start.name;
      throw CLI::ValidationError("--start", "unknown start '" + name + "' (shipped starts: " + known + ")");
    }
  }
  return chosen;
}

void runBench(BenchArguments& args) {
  const CommandSummary summary("bench", args.quiet);
  const std::vector<std::string> formats = chartFormats(args.chartFormats);
  if (args.quick) {
    args.options.steps = {0.1, 0.01, 0.001};
    args.options.tolerances = {1e-4, 1e-7, 1e-10, 1e-13};
    args.options.repeats = 3;
  }
  args.options.methods = parseKindsOption("--methods", "method", args.methods, kMethods);
  args.options.integrators = parseKindsOption("--integrators", "integrator", args.integrators, kIntegrators);
  requirePositive("--steps", args.options.steps);
  requireTolerances("--tolerances", args.options.tolerances);
  requirePositive("--targets", args.targets);
  for (const NamedStart& start : chosenStarts(args.starts)) {  // the error grids, checked before any work
    try {
      gridTimesThrough(start.duration, args.options.sampleInterval);
    } catch (const std::invalid_argument& error) {
      throw CLI::ValidationError("--interval", error.what());
    }
  }
  const auto starts = chosenStarts(args.starts);
  if (args.charts && !gnuplotAvailable())
    throw std::runtime_error("charts need gnuplot with pngcairo: apt-get install gnuplot-nox (or pass --no-charts)");
  std::filesystem::create_directories(args.out);
  removeStaleTemporaries(args.out);  // what a killed run of this command left (docs/hardening.md)
  long total = 0;  // points: every start x method x integrator x its settings
  for (const Integrator integrator : args.options.integrators.empty() ? kindsOf(kIntegrators) : args.options.integrators)
    total += long((traits(integrator).adaptive ? args.options.tolerances : args.options.steps).size());
  total *= long(starts.size() * (args.options.methods.empty() ? kindsOf(kMethods).size() : args.options.methods.size()));
  long done = 0;
  std::optional<Progress> progress(std::in_place, total, args.quiet, "bench", "point");
  const auto points = runWorkPrecision(starts, args.options, [&](const WorkPrecisionPoint&) { progress->update(++done); });
  progress.reset();

  const std::string csvPath = (std::filesystem::path(args.out) / "work-precision.csv").string();
  writeFileAtomically(csvPath, csvText(workPrecisionTable(points)));
  const std::string table = cheapestSettingsText(cheapestSettings(points, args.targets), args.targets);
  writeFileAtomically((std::filesystem::path(args.out) / "cheapest-settings.txt").string(), table);
  std::cout << "Cheapest setting reaching each max position error on every start: fewest field evaluations (worst "
               "start), then its median wall time:\n"
            << table << "wrote " << csvPath << "\n";
  if (args.charts) {
    const std::vector<std::string> pngs = writeWorkPrecisionCharts(points, args.out);
    for (const auto& png : pngs) std::cout << "wrote " << png << "\n";
    writeChartFormats(pngs, formats);
  }
  summary.print(std::to_string(points.size()) + " points on " + std::to_string(starts.size()) + " start" +
                (starts.size() == 1 ? "" : "s") + " -> " + args.out);
}

}  // namespace

void addBenchCommand(CLI::App& app) {
  auto args = std::make_shared<BenchArguments>();
  CLI::App* bench = app.add_subcommand("bench", "Work-precision charts: every method x integrator against a reference");
  bench->footer(
      "Each point runs one method x integrator at one step (rk4) or tolerance (adaptive) from a start and compares\n"
      "its hinge positions every --interval time units with a reference from a different method at tolerance 1e-13\n"
      "(ambient checks the intrinsic methods; embedded checks ambient).\n"
      "Writes DIR/work-precision.csv, DIR/cheapest-settings.txt and DIR/wp-<start>-<chart>.png, each chart with its\n"
      "gnuplot script beside it (.gp: `gnuplot FILE.gp` redraws it; --chart-formats svg,pdf adds .svg and .pdf).\n"
      "Example: linkage bench --quick --start generic --start through-pole --out renders/bench");
  bench->add_option("--start", args->starts,
                    "shipped start to run (repeatable; default all: generic, seam-crossing, near-pole, through-pole, "
                    "L-near-2, L-near-4)");
  bench->add_option("--methods", args->methods, "methods (default all)")->delimiter(',');
  bench->add_option("--integrators", args->integrators, "integrators (default all)")->delimiter(',');
  bench->add_option("--steps", args->options.steps, "rk4 steps to sweep")->delimiter(',')->check(finitePositive());
  bench->add_option("--tolerances", args->options.tolerances, "adaptive tolerances to sweep")
      ->delimiter(',')
      ->check(finiteRange(limits::kMinTolerance, limits::kMaxTolerance));
  bench->add_option("--targets", args->targets, "errors for the cheapest-setting table")
      ->delimiter(',')
      ->check(finitePositive());
  bench->add_option("--repeats", args->options.repeats, "runs per point; wall time is their median")
      ->check(CLI::Range(1, 1000));
  bench->add_option("--interval", args->options.sampleInterval, "error grid spacing in time units")
      ->check(finitePositive());
  bench->add_flag("--quick", args->quick, "3 steps, 4 tolerances, 3 repeats");
  bench->add_flag("!--no-charts", args->charts, "skip the gnuplot charts");
  bench->add_option("--out", args->out, "output folder")->capture_default_str();
  bench->add_flag("--quiet", args->quiet, "no progress or summary line on stderr");
  addChartFormatsOption(*bench, args->chartFormats);
  bench->callback([args] { runBench(*args); });
}

}  // namespace sl

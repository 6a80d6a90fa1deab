// `linkage stability`: where each method fails. Runs a sweep kind over a grid of starts on all cores,
// writes its CSV, summary and heat maps; splits into shards that merge into the same bytes.

#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include <CLI/CLI.hpp>

#include "analysis/gnuplot.hpp"
#include "analysis/option_checks.hpp"
#include "analysis/stability_charts.hpp"
#include "analysis/stability_sweep.hpp"
#include "cli/chart_formats.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "cli/summary.hpp"
#include "cli/exit_codes.hpp"
#include "cli/number_options.hpp"
#include "contracts/time_grid.hpp"
#include "contracts/registry.hpp"
#include "output/atomic_file.hpp"
#include "output/temporary_file.hpp"

namespace sl {

namespace {

// A word for a POSIX shell: as it is when it is safe, else in single quotes.
std::string shellWord(const std::string& word) {
  const bool safe = !word.empty() && word.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                            "0123456789-_./,:=+") == std::string::npos;
  if (safe) return word;
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

struct StabilityArguments {
  std::vector<std::string> methods;  // as given; parsed into options
  std::string integrator;            // as given, empty: each method's sweep default
  StabilityOptions options;
  std::string shard;
  double duration = 0;  // 0: the kind's default
  bool merge = false;
  bool charts = true;
  std::string chartFormats;
  bool quiet = false;
  std::string out = "renders/stability";
  int plan = 0;                 // --plan N: print the N shard jobs instead of running
  std::string givenOptions;     // the options as given, for the plan's command lines (set by the callback)
};

// A sweep planned as N independent shard jobs writing into one shared --out: the job array, the same as plain
// commands (any scheduler, GNU parallel), the merge, and how the cells divide.
void printPlan(const StabilityArguments& args) {
  const long cells = static_cast<long>(args.options.grid) * args.options.grid;
  const int shards = args.plan;
  const std::string options = args.givenOptions;
  std::cout << "# " << shards << " shards of " << cells << " cells (" << cells / shards << " to " << (cells + shards - 1) / shards
            << " each: shard K takes the cells c with c mod " << shards << " = K - 1), into " << args.out << "\n"
            << "# on Slurm (scripts/slurm/stability-array.sbatch; a failed shard: SHARDS=" << shards
            << " sbatch --array=K ...):\n"
            << "sbatch --array=1-" << shards << " scripts/slurm/stability-array.sbatch" << options << "\n"
            << "# anywhere else, one command per shard (each writes only its own "
            << "stability-" << args.options.kind << ".shard-K-of-" << shards << ".csv):\n";
  for (int k = 1; k <= shards; ++k) std::cout << "linkage stability" << options << " --shard " << k << "/" << shards << "\n";
  std::cout << "# when all are done (the last shard merges by itself; this names any shard still missing):\n"
            << "linkage stability" << options << " --merge\n";
}

// The full sweep's files: CSV, summary (also printed) and charts.
void writeSweepOutputs(const std::vector<StabilityRow>& sweep, const StabilityArguments& args) {
  const std::string& kind = args.options.kind;
  const std::string csvPath = stabilityCsvPath(args.out, kind);
  const CsvTable rows = stabilityTable(sweep);
  writeFileAtomically(csvPath, csvText(rows));
  const CsvTable summary = stabilitySummary(sweep);
  const std::string summaryText = csvText(summary);
  writeFileAtomically((std::filesystem::path(args.out) / ("stability-" + kind + "-summary.csv")).string(),
                              summaryText);
  std::cout << alignedText(summary) << "wrote " << csvPath << "\n";
  if (args.charts) {
    const std::vector<std::string> pngs = writeStabilityCharts(rows, kind, args.out);
    for (const auto& png : pngs) std::cout << "wrote " << png << "\n";
    writeChartFormats(pngs, chartFormats(args.chartFormats));
  }
}

int detectShardCount(const StabilityArguments& args) {
  const auto counts = stabilityShardCounts(args.out, args.options.kind);
  if (counts.size() != 1)
    throw CommandExit(kExitBadInput, "linkage stability --merge: " + args.out + ": expected shard files stability-" +
                                         args.options.kind + ".shard-K-of-N.csv for exactly one N, found " +
                                         std::to_string(counts.size()) + " values of N");
  return counts.front();
}

// Returns what was done, for the summary line.
std::string runStability(StabilityArguments& args) {
  StabilityOptions& options = args.options;
  if (!isStabilityKind(options.kind)) {
    std::string kinds;
    for (const auto& k : stabilityKindNames()) kinds += (kinds.empty() ? "" : ", ") + k;
    throw CLI::ValidationError("--kind", "unknown sweep kind '" + options.kind + "' (expected one of " + kinds + ")");
  }
  chartFormats(args.chartFormats);  // checked before any work
  requireTolerances("--tolerance", {options.tolerance});  // what a run accepts, as bench's --tolerances
  options.methods = parseKindsOption("--methods", "method", args.methods, kMethods);
  if (!args.integrator.empty())
    options.integrator = parseKindOption("--integrator", "integrator", args.integrator, kIntegrators);
  options.duration = args.duration > 0 ? args.duration : defaultStabilityDuration(options.kind);
  try {  // the error grid, checked before any work: finite, and of a size that fits
    gridTimesThrough(options.duration, options.sampleInterval);
  } catch (const std::invalid_argument& error) {
    throw CLI::ValidationError("--interval", error.what());
  }
  if (args.plan > 0) {
    if (args.plan > static_cast<long>(options.grid) * options.grid)
      throw CommandExit(kExitBadInput, "linkage stability --plan: found " + std::to_string(args.plan) +
                                           "; expected at most one shard per cell (" +
                                           std::to_string(options.grid * options.grid) + ")");
    printPlan(args);
    return "a plan of " + std::to_string(args.plan) + " shards";
  }
  if (args.charts && !gnuplotAvailable())
    throw std::runtime_error("charts need gnuplot with pngcairo: apt-get install gnuplot-nox (or pass --no-charts)");
  std::filesystem::create_directories(args.out);
  removeStaleTemporaries(args.out);  // what a killed run of this command left (docs/hardening.md)

  if (args.merge) {
    std::vector<StabilityRow> merged;
    const int count = detectShardCount(args);
    if (!mergeStabilityShards(args.out, options.kind, count, merged)) {
      std::string missing;
      for (int k = 1; k <= count; ++k) {
        const std::string path = stabilityShardPath(args.out, options.kind, {k, count});
        if (!std::filesystem::exists(path)) missing += (missing.empty() ? "" : ", ") + path;
      }
      throw CommandExit(kExitBadInput, "linkage stability --merge: missing shards: " + missing);
    }
    writeSweepOutputs(merged, args);
    return "merged " + std::to_string(count) + " shards of the " + options.kind + " sweep -> " + args.out;
  }
  if (!args.shard.empty()) options.shard = parseShard(args.shard);

  std::optional<Progress> progress;
  const std::vector<StabilityRow> rows = runStabilitySweep(options, [&](long done, long total) {
    if (!progress) progress.emplace(total, args.quiet, "stability", "cell");
    progress->update(done);
  });
  progress.reset();

  const std::string sweep = options.kind + " sweep, " + std::to_string(options.grid) + " x " +
                            std::to_string(options.grid) + " grid";
  if (options.shard.count == 1) {
    writeSweepOutputs(rows, args);
    return sweep + " -> " + args.out;
  }
  const std::string shardPath = stabilityShardPath(args.out, options.kind, options.shard);
  writeFileAtomically(shardPath, stabilityShardText(options, rows));
  std::cout << "wrote " << shardPath << "\n";
  std::vector<StabilityRow> merged;  // the last shard to finish merges them all
  const std::string shard = sweep + ", shard " + std::to_string(options.shard.index) + "/" +
                            std::to_string(options.shard.count) + " -> " + shardPath;
  if (!mergeStabilityShards(args.out, options.kind, options.shard.count, merged)) return shard;
  writeSweepOutputs(merged, args);
  return shard + " (the last: merged into " + args.out + ")";
}

}  // namespace

void addStabilityCommand(CLI::App& app) {
  auto args = std::make_shared<StabilityArguments>();
  CLI::App* stability =
      app.add_subcommand("stability", "Stability maps: where each method fails over a grid of starts");
  stability->footer(
      "Sweep kinds (x by y, 4 rods):\n"
      "  launch     launch point over the sphere (t0 by phi0), fixed heading\n"
      "  direction  heading by phi0\n"
      "  pole       closest approach to the pole phi = pi/2, 1e-10 down to exactly through it, by azimuth\n"
      "  seam       offset of t0 from the seam t = pi/2 (down to 0) by heading\n"
      "  length     L from 2 + 1e-6 to 4 - 1e-6 by heading\n"
      "  drift      launch grid over a long span (default --duration 1000)\n"
      "Each cell's run is compared with a different method at tolerance 1e-13 every --interval time units\n"
      "(ambient checks the others; embedded checks ambient), unless --no-reference. Energy drift and rod-length\n"
      "error are the worst over every step; without a reference only the start and the end are sampled.\n"
      "Writes DIR/stability-<kind>.csv, -summary.csv and stability-<kind>-<method>.png, each chart with its gnuplot\n"
      "script beside it (.gp; --chart-formats svg,pdf adds .svg and .pdf).\n"
      "Sharding: run `--shard K/N` for K = 1..N (any machines, same options, same --out); the last to finish\n"
      "merges, or run `--merge` afterwards. The merged files equal a single run's byte for byte.\n"
      "Example: linkage stability --kind pole --grid 32 --methods christoffel-fd,embedded,ambient");
  stability->add_option("--kind", args->options.kind, "sweep kind")->capture_default_str();
  stability->add_option("--grid", args->options.grid, "cells per axis (grid x grid)")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  stability->add_option("--duration", args->duration, "time span of each run (default 20; drift 1000)")
      ->check(finitePositive());
  stability->add_option("--interval", args->options.sampleInterval, "error grid spacing in time units")
      ->check(finitePositive())
      ->capture_default_str();
  stability->add_option("--methods", args->methods, "methods (default all)")->delimiter(',');
  stability->add_option(
      "--integrator", args->integrator,
      "integrator for every method (default: rk4 for the published -fd methods, the default run's otherwise)");
  stability->add_option("--tolerance", args->options.tolerance, "adaptive tolerance (default: the default run's)")
      ->check(finitePositive())
      ->capture_default_str();
  stability->add_option("--step", args->options.step, "rk4 step")->check(finitePositive())->capture_default_str();
  stability->add_option("--threads", args->options.threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  stability->add_option("--shard", args->shard, "run only shard K of N (cells c with c mod N = K-1)");
  stability->add_flag("!--no-reference", args->options.checkAgainstReference,
                      "skip the reference runs: failure modes and invariants only (much faster)");
  stability->add_flag("--merge", args->merge, "merge the shard files in --out instead of running");
  stability->add_flag("!--no-charts", args->charts, "skip the gnuplot heat maps");
  stability->add_flag("--quiet", args->quiet, "no progress or summary line on stderr");
  addChartFormatsOption(*stability, args->chartFormats);
  stability->add_option("--out", args->out, "output folder")->capture_default_str();
  stability->add_option("--plan", args->plan, "print the sweep as N shard jobs (a job array, plain commands, the merge)")
      ->check(CLI::Range(1, 1 << 20))
      ->type_name("N");
  stability->callback([args, stability] {
    // The options as given (but --plan, --shard, --merge), quoted for a shell: the plan's command lines.
    args->givenOptions.clear();
    for (const CLI::Option* option : stability->get_options()) {
      const std::string name = option->get_name();
      if (option->count() == 0 || name == "--plan" || name == "--shard" || name == "--merge" || name == "--help")
        continue;
      args->givenOptions += " " + name;
      if (option->get_items_expected_max() == 0) continue;  // a flag: its name says it all
      std::string values;  // a list option (--methods) as one comma-separated word
      for (const std::string& value : option->results()) values += (values.empty() ? "" : ",") + value;
      args->givenOptions += " " + shellWord(values);
    }
    if (stability->get_option("--out")->count() == 0) args->givenOptions += " --out " + shellWord(args->out);
    const CommandSummary summary("stability", args->quiet);
    summary.print(runStability(*args));
  });
}

}  // namespace sl

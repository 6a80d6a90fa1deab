// `linkage simulate SCENE.json [--csv FILE] [--dt DT]`: the scene's runs as trajectory CSV, no rendering.

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/interrupt.hpp"
#include "cli/number_options.hpp"
#include "cli/run_report.hpp"
#include "cli/scene_input.hpp"
#include "cli/summary.hpp"
#include "contracts/time_grid.hpp"
#include "output/atomic_file.hpp"
#include "output/distinct_files.hpp"
#include "scene/output_folder.hpp"
#include "contracts/csv_format.hpp"
#include "simulation/trajectory_csv.hpp"

namespace sl {

namespace {

struct SimulateArguments {
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::string scene;
  std::string csv;     // empty: stdout
  std::string events;  // --events: run,member,event,time rows (conjugate points and stops)
  double dt = 0;    // 0: the frame times k / fps
  bool quiet = false;
};

// Where the rows go: a file that appears whole or not at all, or standard output, whose every write is checked
// (a full disk or a closed pipe is an error, not a silent short CSV).
class CsvOutput {
 public:
  explicit CsvOutput(const std::string& path) {
    if (!path.empty()) file_.emplace(path);
  }
  void write(const std::string& text) {
    if (file_) return file_->write(text);
    if (text.empty()) return;
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) failOnStdout();
    wroteToStdout_ = true;
  }
  void finish() {
    if (file_) return file_->commit();
    if (std::fflush(stdout) != 0 || (::fsync(STDOUT_FILENO) != 0 && errno != EINVAL && errno != EROFS)) failOnStdout();
  }
  // What an interruption leaves behind, for its message.
  std::string whatWasWritten() const {
    if (file_) return "no CSV was written";
    return wroteToStdout_ ? "the CSV on standard output is incomplete" : "no CSV was written";
  }

 private:
  [[noreturn]] void failOnStdout() {
    throw CommandExit(kExitFailure,
                      std::string("linkage simulate: cannot write the CSV to standard output: ") + std::strerror(errno) +
                          (wroteToStdout_ ? " (what went out is incomplete)" : ""));
  }
  std::optional<AtomicFileWriter> file_;
  bool wroteToStdout_ = false;
};

// Rows in chunks, each written out at once: memory stays bounded whatever the duration, the sampling and the
// number of runs. A run that stops ends with one row at its stop time whose status is the reason
// (trajectory_csv.hpp); nothing follows it. SIGINT/SIGTERM are noticed within one integration step.
void writeRun(CsvOutput& out, const std::string& name, Trajectory& trajectory, const std::vector<double>& times,
              const TrajectoryCsvLayout& layout, int member) {
  const size_t chunk = 256;
  for (size_t first = 0; first < times.size(); first += chunk) {
    stopIfInterrupted(out.whatWasWritten().c_str());
    const std::vector<double> part(times.begin() + first, times.begin() + std::min(times.size(), first + chunk));
    std::ostringstream rows;
    try {
      writeTrajectoryCsv(rows, name, trajectory, part, false, layout, member);
    } catch (const RunCancelled&) {
      stopIfInterrupted(out.whatWasWritten().c_str());
      throw;
    }
    out.write(rows.str());
    if (trajectory.stop() && trajectory.stop()->time < part.back()) return;
  }
}

void runSimulate(const SimulateArguments& args) {
  installInterruptHandlers();
  const CommandSummary summary("simulate", args.quiet);
  const Scene scene = loadSceneForCommand(args.scene, args.overrides);
  std::vector<double> times;
  try {
    times = args.dt > 0 ? uniformTimes(scene.duration, args.dt) : frameTimes(scene.duration, scene.output.fps);
  } catch (const std::invalid_argument& error) {
    throw CommandExit(kExitBadInput, "--dt: " + std::string(error.what()));
  }
  // Checked before any work, like render's outputs: a writable place that is not a folder or a device, and not
  // the scene or the other output.
  requireOutputsBeforeWork("simulate", {{"the scene", args.scene}}, {{"--csv", args.csv}, {"--events", args.events}});
  std::vector<std::string> notes;
  const std::vector<InitialState> starts = runStarts(scene, &notes);
  if (!args.quiet)
    for (const std::string& note : notes) std::cerr << "linkage simulate: note: " << note << "\n";
  std::vector<Trajectory> runs = startRuns(scene, starts);
  std::vector<std::vector<Trajectory>> families;
  try {
    families = startFamilies(scene, starts);
  } catch (const RunCancelled&) {  // a signal while a large family was set up
    stopIfInterrupted("no CSV was written");
    throw;
  }
  TrajectoryCsvLayout layout{scene.chain.rods, false, false};
  for (const RunSpec& run : scene.runs) {
    layout.memberColumn = layout.memberColumn || run.family.has_value();
    layout.jacobiColumn = layout.jacobiColumn || run.config.jacobi;
    layout.chartColumns = layout.chartColumns && !run.chain.isSlack();
  }
  CsvOutput out(args.csv);
  out.write(trajectoryCsvHeader(layout) + "\n");
  // Each run, then its family's members, one row group each.
  for (size_t i = 0; i < runs.size(); ++i) {
    writeRun(out, scene.runs[i].name, runs[i], times, layout, 0);
    for (size_t m = 0; m < families[i].size(); ++m)
      writeRun(out, scene.runs[i].name, families[i][m], times, layout, static_cast<int>(m + 1));
  }
  out.finish();
  if (!args.events.empty()) {
    // Every event up to the last time written: conjugate points (runs with Jacobi fields), then stops.
    const double last = times.empty() ? 0.0 : times.back();
    std::string text = "run,member,event,time\n";
    auto add = [&](const std::string& run, size_t member, const std::string& event, double time) {
      text += csvField(run) + "," + std::to_string(member) + "," + event + ",";
      appendShortest(text, time);
      text += "\n";
    };
    for (size_t i = 0; i < runs.size(); ++i) {
      for (size_t m = 0; m <= families[i].size(); ++m) {
        const Trajectory& run = m == 0 ? runs[i] : families[i][m - 1];
        for (const double t : run.conjugateTimes())
          if (t <= last) add(scene.runs[i].name, m, "conjugate-point", t);
        if (run.stop() && run.stop()->time <= last) add(scene.runs[i].name, m, nameOf(run.stop()->reason), run.stop()->time);
      }
    }
    writeFileAtomically(args.events, text);
  }
  reportStops(scene, runs, args.quiet);
  summary.print(std::to_string(runs.size()) + " run" + (runs.size() == 1 ? "" : "s") + " x " +
                    std::to_string(times.size()) + " times -> " + (args.csv.empty() ? "standard output" : args.csv),
                "; " + runOutcomes(scene, runs, times.empty() ? 0.0 : times.back()));
}

}  // namespace

void addSimulateCommand(CLI::App& app) {
  auto args = std::make_shared<SimulateArguments>();
  CLI::App* command =
      app.add_subcommand("simulate", "Integrate the scene's runs and write trajectory CSV (no rendering)");
  command->add_option("scene", args->scene, "scene file (JSON, see scenes/README.md; - reads standard input)")->required();
  addSceneOverrideOption(*command, args->overrides);
  command->add_option("--csv", args->csv, "write the CSV here instead of stdout (written whole or not at all)");
  command->add_option("--events", args->events,
                      "write run,member,event,time rows: conjugate points (runs with \"jacobi\": true) and stops");
  command->add_option("--dt", args->dt, "sample every DT time units (default: the frame times k / fps)")
      ->check(finitePositive());
  command->add_flag("--quiet", args->quiet, "errors only: no run reports or summary line");
  command->footer(
      "Columns: run,time,phi,t,phidot,tdot,energy,p1x,p1y,...,status (4 rods; chart coordinates c1.. and rates v1..\n"
      "for other n). A run that stops ends with one row at its stop time whose status is the reason.\n"
      "Scenes with families add a member column after run (0: the run, 1..: its members, a row group each);\n"
      "scenes with Jacobi fields add a jacobi column before status (|J_perp|; empty for runs without).\n"
      "Run names are quoted as RFC 4180 says when they hold a comma, a quote or a line break.\n"
      "Example: linkage simulate scenes/comparison.json --dt 0.01 --csv renders/comparison.csv");
  command->callback([args] { runSimulate(*args); });
}

}  // namespace sl

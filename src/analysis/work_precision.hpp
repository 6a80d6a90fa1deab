#pragma once
// Work-precision sweeps (SciML practice): every method x integrator over a ladder of settings (steps for
// fixed-step integrators, tolerances for adaptive ones), each point measured against a reference from a
// different method at its tightest setting.

#include <functional>
#include <string>
#include <vector>

#include "analysis/csv_table.hpp"
#include "analysis/measurement.hpp"
#include "analysis/starts.hpp"
#include "contracts/registry.hpp"

namespace sl {

struct WorkPrecisionPoint {
  std::string start;
  Method method = Method::Ambient;
  Integrator integrator = Integrator::Rkf78;
  double setting = 0;  // the step (fixed-step integrators) or the tolerance (adaptive ones)
  Method referenceMethod = Method::Embedded;
  Measurement measurement;
};

struct WorkPrecisionOptions {
  std::vector<Method> methods;          // empty: every method of the registry (kMethods)
  std::vector<Integrator> integrators;  // empty: every integrator of the registry (kIntegrators)
  std::vector<double> steps = {0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001};
  std::vector<double> tolerances = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14};
  double sampleInterval = 0.1;  // the grid on which errors are taken
  int repeats = 5;              // wall time: the median of this many runs
};

// The settings swept for one integrator: options.steps or options.tolerances.
const std::vector<double>& settingsFor(Integrator integrator, const WorkPrecisionOptions& options);

// "h" for fixed-step integrators, "tol" for adaptive ones.
std::string settingKind(Integrator integrator);

using ProgressCallback = std::function<void(const WorkPrecisionPoint&)>;

std::vector<WorkPrecisionPoint> runWorkPrecision(const std::vector<NamedStart>& starts,
                                                 const WorkPrecisionOptions& options,
                                                 const ProgressCallback& progress = {});

// === CSV: one row per point, named columns (docs/analysis.md lists them)
std::vector<std::string> workPrecisionColumns();
CsvTable workPrecisionTable(const std::vector<WorkPrecisionPoint>& points);
// Throws std::invalid_argument naming the row and column of a name that is no method, integrator or status.
std::vector<WorkPrecisionPoint> workPrecisionPointsFromTable(const CsvTable& table);

// === The summary: the cheapest setting of each method x integrator that reaches a target
struct CheapestSetting {
  Method method = Method::Ambient;
  Integrator integrator = Integrator::Rkf78;
  double target = 0;
  bool reached = false;
  double setting = 0;           // valid when reached
  double worstError = 0;        // max over the starts of the max position error at that setting
  long worstEvaluations = 0;    // max over the starts
  double worstWallSeconds = 0;  // max over the starts of the median wall time
  double worstCpuSeconds = 0;   // max over the starts of the median CPU time
};

// For each method x integrator (in first-appearance order) and each target: among the settings at which
// every start finished (status ok) with max position error <= target, the one with the fewest vector-field
// evaluations on its worst start (deterministic, unlike wall time). Starts absent at a setting count as
// failures.
std::vector<CheapestSetting> cheapestSettings(const std::vector<WorkPrecisionPoint>& points,
                                              const std::vector<double>& targets);

// A plain-text table: one row per method x integrator, one column per target: the setting, its evaluations (what
// it was chosen by) and its wall time, or "never" where unreached.
std::string cheapestSettingsText(const std::vector<CheapestSetting>& cheapest, const std::vector<double>& targets);

}  // namespace sl

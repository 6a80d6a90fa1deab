#include "analysis/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

#include "analysis/option_checks.hpp"
#include "contracts/time_grid.hpp"

namespace sl {

const std::vector<double>& settingsFor(Integrator integrator, const WorkPrecisionOptions& options) {
  return traits(integrator).adaptive ? options.tolerances : options.steps;
}

std::string settingKind(Integrator integrator) { return traits(integrator).adaptive ? "tol" : "h"; }

namespace {

RunConfig configFor(Method method, Integrator integrator, double setting, double duration) {
  RunConfig config;
  config.method = method;
  config.integrator = integrator;
  if (traits(integrator).adaptive)
    config.tolerance = setting;
  else
    config.step = setting;
  config.maxSteps = stepBudget(config, duration);
  return config;
}

}  // namespace

std::vector<WorkPrecisionPoint> runWorkPrecision(const std::vector<NamedStart>& starts,
                                                 const WorkPrecisionOptions& options,
                                                 const ProgressCallback& progress) {
  const auto methods = options.methods.empty() ? kindsOf(kMethods) : options.methods;
  const auto integrators = options.integrators.empty() ? kindsOf(kIntegrators) : options.integrators;
  std::vector<WorkPrecisionPoint> points;
  for (const auto& start : starts) {
    const auto times = gridTimesThrough(start.duration, options.sampleInterval);
    std::map<Method, ReferencePath> references;  // by reference method
    for (const Method method : methods) {
      const Method referenceMethod = referenceMethodFor(method);
      if (!references.count(referenceMethod))
        references[referenceMethod] = computeReferencePath(start.chain, start.state, times, referenceConfig(method));
      const ReferencePath& reference = references[referenceMethod];
      for (const Integrator integrator : integrators) {
        for (double setting : settingsFor(integrator, options)) {
          WorkPrecisionPoint point{start.name, method, integrator, setting, referenceMethod, {}};
          point.measurement =
              measureRunTimed(start.chain, start.state, configFor(method, integrator, setting, start.duration),
                              reference, options.repeats);
          if (progress) progress(point);
          points.push_back(std::move(point));
        }
      }
    }
  }
  return points;
}

std::vector<std::string> workPrecisionColumns() {
  return {"start",
          "method",
          "integrator",
          "setting_kind",
          "setting",
          "status",
          "wall_seconds",
          "cpu_seconds",
          "evaluations",
          "steps",
          "final_error",
          "max_error",
          "max_energy_drift",
          "max_rod_length_error",
          "stop_time",
          "reference_method",
          "stop_detail"};
}

CsvTable workPrecisionTable(const std::vector<WorkPrecisionPoint>& points) {
  CsvTable table{workPrecisionColumns(), {}};
  for (const auto& p : points) {
    const Measurement& m = p.measurement;
    table.rows.push_back(
        {p.start, nameOf(p.method), nameOf(p.integrator), settingKind(p.integrator), formatNumber(p.setting),
         statusName(m.status), formatNumber(m.wallSeconds), formatNumber(m.cpuSeconds), std::to_string(m.evaluations),
         std::to_string(m.steps), formatNumber(m.finalError), formatNumber(m.maxError), formatNumber(m.maxEnergyDrift),
         formatNumber(m.maxRodLengthError), formatNumber(m.stopTime), nameOf(p.referenceMethod), m.stopDetail});
  }
  return table;
}

namespace {

// The kind a table's field names; throws std::invalid_argument naming the row and column.
template <class Table>
auto kindIn(const CsvTable& table, size_t row, const std::string& column, const Table& kinds) {
  const std::string& name = table.text(row, column);
  if (const auto kind = parseKind(kinds, name)) return *kind;
  throw std::invalid_argument("row " + std::to_string(row + 1) + ": unknown " + column + " '" + name + "'");
}

RunStatus statusIn(const CsvTable& table, size_t row) {
  const std::string& name = table.text(row, "status");
  if (const auto status = parseStatus(name)) return *status;
  throw std::invalid_argument("row " + std::to_string(row + 1) + ": unknown status '" + name + "'");
}

}  // namespace

std::vector<WorkPrecisionPoint> workPrecisionPointsFromTable(const CsvTable& table) {
  std::vector<WorkPrecisionPoint> points;
  for (size_t r = 0; r < table.rows.size(); ++r) {
    WorkPrecisionPoint p{table.text(r, "start"),
                         kindIn(table, r, "method", kMethods),
                         kindIn(table, r, "integrator", kIntegrators),
                         table.number(r, "setting"),
                         kindIn(table, r, "reference_method", kMethods),
                         {}};
    Measurement& m = p.measurement;
    m.status = statusIn(table, r);
    m.wallSeconds = table.number(r, "wall_seconds");
    m.cpuSeconds = table.number(r, "cpu_seconds");
    m.evaluations = std::stol(table.text(r, "evaluations"));
    m.steps = std::stol(table.text(r, "steps"));
    m.finalError = table.number(r, "final_error");
    m.maxError = table.number(r, "max_error");
    m.maxEnergyDrift = table.number(r, "max_energy_drift");
    m.maxRodLengthError = table.number(r, "max_rod_length_error");
    m.stopTime = table.number(r, "stop_time");
    m.stopDetail = table.text(r, "stop_detail");
    points.push_back(std::move(p));
  }
  return points;
}

namespace {

// The worst case over the starts of one setting of one series.
struct SettingSummary {
  int starts = 0;
  bool anyFailed = false;
  double worstError = 0;
  long worstEvaluations = 0;
  double worstWallSeconds = 0;
  double worstCpuSeconds = 0;
};

}  // namespace

std::vector<CheapestSetting> cheapestSettings(const std::vector<WorkPrecisionPoint>& points,
                                              const std::vector<double>& targets) {
  using SeriesKey = std::pair<Method, Integrator>;
  std::vector<SeriesKey> order;
  std::set<std::string> allStarts;
  std::map<SeriesKey, std::map<double, SettingSummary>> summaries;
  for (const auto& p : points) {
    const SeriesKey key{p.method, p.integrator};
    if (!summaries.count(key)) order.push_back(key);
    allStarts.insert(p.start);
    SettingSummary& s = summaries[key][p.setting];
    const Measurement& m = p.measurement;
    s.starts += 1;
    s.anyFailed = s.anyFailed || m.failed() || !std::isfinite(m.maxError);
    if (!(m.maxError <= s.worstError)) s.worstError = m.maxError;
    s.worstEvaluations = std::max(s.worstEvaluations, m.evaluations);
    s.worstWallSeconds = std::max(s.worstWallSeconds, m.wallSeconds);
    s.worstCpuSeconds = std::max(s.worstCpuSeconds, m.cpuSeconds);
  }
  std::vector<CheapestSetting> result;
  for (const auto& key : order) {
    for (double target : targets) {
      CheapestSetting best{key.first, key.second, target, false, 0, 0, 0, 0, 0};
      for (const auto& [setting, s] : summaries[key]) {
        const bool qualifies = s.starts == static_cast<int>(allStarts.size()) && !s.anyFailed && s.worstError <= target;
        if (!qualifies) continue;
        // Fewest evaluations; on a tie the looser (larger) setting, which is the cheaper to choose.
        if (!best.reached || s.worstEvaluations < best.worstEvaluations ||
            (s.worstEvaluations == best.worstEvaluations && setting > best.setting))
          best = {key.first,          key.second,         target,           true, setting, s.worstError,
                  s.worstEvaluations, s.worstWallSeconds, s.worstCpuSeconds};
      }
      result.push_back(best);
    }
  }
  return result;
}

std::string cheapestSettingsText(const std::vector<CheapestSetting>& cheapest, const std::vector<double>& targets) {
  auto cell = [](const CheapestSetting& c) -> std::string {
    if (!c.reached) return "never";
    // The cost that chose the setting, field evaluations (the same on every machine and run), first; the time
    // as measured beside it (noisy: a looser target's pick can take longer on the clock than a tighter one's).
    char text[112];
    std::snprintf(text, sizeof text, "%s=%g  %ld evals  %.2f ms", settingKind(c.integrator).c_str(), c.setting,
                  c.worstEvaluations, c.worstWallSeconds * 1e3);
    return text;
  };
  CsvTable table;
  table.columns = {"method", "integrator"};
  for (double target : targets) table.columns.push_back("| error <= " + formatNumber(target));
  for (size_t i = 0; i < cheapest.size(); i += targets.size()) {
    std::vector<std::string> row = {nameOf(cheapest[i].method), nameOf(cheapest[i].integrator)};
    for (size_t t = 0; t < targets.size(); ++t) row.push_back("| " + cell(cheapest[i + t]));
    table.rows.push_back(std::move(row));
  }
  return alignedText(table, " ");
}

}  // namespace sl

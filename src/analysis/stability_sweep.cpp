#include "analysis/stability_sweep.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <regex>
#include <set>
#include <stdexcept>

#include "analysis/measurement.hpp"
#include "analysis/option_checks.hpp"
#include "contracts/parallel_for.hpp"
#include "contracts/time_grid.hpp"

namespace sl {

Shard parseShard(const std::string& text) {
  const std::regex pattern(R"(\s*(\d{1,9})\s*/\s*(\d{1,9})\s*)");  // nine digits: never past int's range
  std::smatch match;
  if (std::regex_match(text, match, pattern)) {
    const Shard shard{std::stoi(match[1]), std::stoi(match[2])};
    if (shard.count >= 1 && shard.count <= kMaxShards && shard.index >= 1 && shard.index <= shard.count) return shard;
  }
  throw std::invalid_argument("--shard: expected K/N with 1 <= K <= N <= " + std::to_string(kMaxShards) +
                              " (e.g. 2/4), found '" + text + "'");
}

Integrator sweepIntegratorFor(Method method) {
  return traits(method).published ? Integrator::Rk4 : RunConfig().integrator;
}

std::vector<std::string> stabilityColumns() {
  return {"cell",
          "i",
          "j",
          "x",
          "y",
          "method",
          "integrator",
          "setting",
          "status",
          "stop_time",
          "final_error",
          "max_error",
          "max_energy_drift",
          "max_rod_length_error",
          "evaluations",
          "reference_method",
          "stop_detail"};
}

namespace {

RunConfig sweepConfig(const StabilityOptions& options, Method method) {
  RunConfig config;
  config.method = method;
  config.integrator = options.integrator.value_or(sweepIntegratorFor(method));
  config.tolerance = options.tolerance;
  config.step = options.step;
  config.maxSteps = stepBudget(config, options.duration);
  return config;
}

// The rows of one cell: each method against its reference (computed once per reference method).
std::vector<std::vector<std::string>> cellRows(const StabilityOptions& options, const std::vector<Method>& methods,
                                               long cellIndex) {
  const int i = static_cast<int>(cellIndex % options.grid), j = static_cast<int>(cellIndex / options.grid);
  std::vector<std::vector<std::string>> rows;
  // By reference method; the one entry without a reference is keyed by no method.
  std::map<std::optional<Method>, ReferencePath> references;
  // Without a reference the samples would only feed the invariants, which the run tracks at every step:
  // the start and the end suffice (dense samples cost an extra step each, as much as the run itself).
  const auto times =
      gridTimesThrough(options.duration, options.checkAgainstReference ? options.sampleInterval : options.duration);
  try {
    const StabilityCell cell = stabilityCell(options.kind, options.grid, i, j, options.duration);
    for (const Method method : methods) {
      const std::optional<Method> referenceMethod =
          options.checkAgainstReference ? std::optional(referenceMethodFor(method)) : std::nullopt;
      if (!references.count(referenceMethod))
        references[referenceMethod] = referenceMethod
                                          ? computeReferencePath(cell.chain, cell.start, times, referenceConfig(method))
                                          : noReference(times);
      const ReferencePath& reference = references[referenceMethod];
      const RunConfig config = sweepConfig(options, method);
      const Measurement m = measureRun(cell.chain, cell.start, config, reference);
      rows.push_back({std::to_string(cellIndex), std::to_string(i), std::to_string(j), formatNumber(cell.x),
                      formatNumber(cell.y), nameOf(method), nameOf(config.integrator),
                      formatNumber(config.accuracySetting()), statusName(m.status), formatNumber(m.stopTime),
                      formatNumber(m.finalError), formatNumber(m.maxError), formatNumber(m.maxEnergyDrift),
                      formatNumber(m.maxRodLengthError), std::to_string(m.evaluations), referenceMethodName(reference),
                      m.stopDetail});
    }
  } catch (const std::exception& error) {
    // A start the reference cannot construct (e.g. the backward run of a pole cell stopped) is a result too.
    rows.clear();
    for (const Method method : methods) {
      const RunConfig config = sweepConfig(options, method);
      // Empty fields: no value (the cell's start could not be made, so neither its point nor any error).
      rows.push_back({std::to_string(cellIndex), std::to_string(i), std::to_string(j), "", "", nameOf(method),
                      nameOf(config.integrator), formatNumber(config.accuracySetting()),
                      nameOf(Verdict::ReferenceStopped), "0", "", "", "", "", "0",
                      nameOf(referenceMethodFor(method)), error.what()});
    }
  }
  return rows;
}

}  // namespace

CsvTable runStabilitySweep(const StabilityOptions& options, const CellProgress& progress) {
  if (!isStabilityKind(options.kind))
    throw std::invalid_argument("unknown stability sweep kind '" + options.kind + "'");
  if (options.grid < 1) throw std::invalid_argument("--grid must be at least 1");
  const auto methods = options.methods.empty() ? kindsOf(kMethods) : options.methods;
  std::vector<long> cells;
  for (long c = options.shard.index - 1; c < static_cast<long>(options.grid) * options.grid; c += options.shard.count)
    cells.push_back(c);

  std::vector<std::vector<std::vector<std::string>>> results(cells.size());
  std::atomic<long> done{0};
  std::mutex progressMutex;
  parallelFor(cells.size(), static_cast<std::size_t>(std::max(0, options.threads)), [&](std::size_t k) {
    results[k] = cellRows(options, methods, cells[k]);
    const long finished = ++done;
    if (progress) {
      std::lock_guard lock(progressMutex);
      progress(finished, static_cast<long>(cells.size()));
    }
  });

  CsvTable table{stabilityColumns(), {}};
  for (auto& cellRowsOfOne : results)
    for (auto& row : cellRowsOfOne) table.rows.push_back(std::move(row));
  return table;
}

std::string stabilityCsvPath(const std::string& outDir, const std::string& kind) {
  return (std::filesystem::path(outDir) / ("stability-" + kind + ".csv")).string();
}

std::string stabilityShardPath(const std::string& outDir, const std::string& kind, const Shard& shard) {
  return (std::filesystem::path(outDir) / ("stability-" + kind + ".shard-" + std::to_string(shard.index) + "-of-" +
                                           std::to_string(shard.count) + ".csv"))
      .string();
}

std::vector<int> stabilityShardCounts(const std::string& outDir, const std::string& kind) {
  std::set<int> counts;
  const std::regex pattern("stability-" + kind + R"(\.shard-(\d+)-of-(\d+)\.csv)");
  if (!std::filesystem::is_directory(outDir)) return {};
  for (const auto& entry : std::filesystem::directory_iterator(outDir)) {
    std::smatch match;
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, match, pattern) && match[2].length() <= 9) counts.insert(std::stoi(match[2]));
  }
  return {counts.begin(), counts.end()};
}

bool mergeStabilityShards(const std::string& outDir, const std::string& kind, int shardCount, CsvTable& merged) {
  std::vector<std::string> paths;
  for (int k = 1; k <= shardCount; ++k) {
    paths.push_back(stabilityShardPath(outDir, kind, {k, shardCount}));
    if (!std::filesystem::exists(paths.back())) return false;
  }
  CsvTable table{stabilityColumns(), {}};
  // A shard file is input: anything wrong in it is std::invalid_argument naming the file and the row.
  for (const auto& path : paths) {
    CsvTable shard;
    try {
      shard = readCsvFile(path);
    } catch (const std::exception& error) {
      throw std::invalid_argument(path + ": not a readable stability shard (" + error.what() + ")");
    }
    if (shard.columns != table.columns)
      throw std::invalid_argument(path + ": not a stability shard (columns differ from " +
                                  stabilityColumns().front() + ",...)");
    const size_t cell = shard.column("cell"), row = shard.column("i");
    for (size_t r = 0; r < shard.rows.size(); ++r) {
      for (size_t column : {cell, row}) {
        const std::string& text = shard.rows[r][column];
        if (text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos)
          throw std::invalid_argument(path + ": row " + std::to_string(r + 2) + ": column " + shard.columns[column] +
                                      " is '" + text + "', expected a cell index");
      }
    }
    for (auto& row : shard.rows) table.rows.push_back(std::move(row));
  }
  const size_t cellColumn = table.column("cell");
  // Stable: the rows of one cell come from one shard, already in method order.
  std::stable_sort(table.rows.begin(), table.rows.end(), [cellColumn](const auto& a, const auto& b) {
    return std::stol(a[cellColumn]) < std::stol(b[cellColumn]);
  });
  std::set<long> cells;
  long gridSize = 0;
  for (size_t r = 0; r < table.rows.size(); ++r) {
    cells.insert(std::stol(table.rows[r][cellColumn]));
    gridSize = std::max(gridSize, std::stol(table.text(r, "i")) + 1);
  }
  if (static_cast<long>(cells.size()) != gridSize * gridSize ||
      (!cells.empty() && *cells.rbegin() != gridSize * gridSize - 1))
    throw std::invalid_argument(outDir + ": the " + std::to_string(shardCount) + " shards of the '" + kind +
                             "' sweep hold " + std::to_string(cells.size()) + " cells, expected " +
                             std::to_string(gridSize * gridSize) + " (were they run with the same --grid?)");
  merged = std::move(table);
  return true;
}

std::vector<std::string> stabilityStatusNames() {
  // The summary's columns and the maps' colours follow this order, so it is kept fixed: the single chart's own
  // failures (what these maps are about) before the other stop reasons.
  std::vector<std::string> names = {nameOf(Verdict::Ok), nameOf(Verdict::WrongPath), nameOf(StopReason::PoleFoldBack),
                                    nameOf(StopReason::FieldBlowUp)};
  for (const StopReasonTraits& reason : kStopReasons)
    if (reason.kind != StopReason::PoleFoldBack && reason.kind != StopReason::FieldBlowUp)
      names.emplace_back(reason.name);
  names.push_back(nameOf(Verdict::ReferenceStopped));
  names.push_back("other");
  return names;
}

int stabilityStatusCode(const std::string& status) {
  const auto names = stabilityStatusNames();
  const auto found = std::find(names.begin(), names.end(), status);
  return static_cast<int>(found == names.end() ? names.size() - 1 : found - names.begin());
}

std::vector<std::string> stabilitySummaryColumns() {
  std::vector<std::string> columns = {"method",      "integrator",  "setting",         "cells",
                                      "within_1e-6", "within_1e-9", "median_max_error"};
  for (const auto& status : stabilityStatusNames()) columns.push_back(status);
  return columns;
}

CsvTable stabilitySummary(const CsvTable& rows) {
  struct Tally {
    std::string integrator, setting;
    long cells = 0, within6 = 0, within9 = 0;
    bool checked = false;  // some row has a reference
    std::vector<double> errors;
    std::vector<long> statusCounts = std::vector<long>(stabilityStatusNames().size(), 0);
  };
  std::vector<std::string> order;
  std::map<std::string, Tally> tallies;
  for (size_t r = 0; r < rows.rows.size(); ++r) {
    const std::string& method = rows.text(r, "method");
    if (!tallies.count(method)) order.push_back(method);
    Tally& t = tallies[method];
    t.integrator = rows.text(r, "integrator");
    t.setting = rows.text(r, "setting");
    const bool ok = rows.text(r, "status") == nameOf(Verdict::Ok);
    const double error = rows.number(r, "max_error");
    t.cells += 1;
    t.checked = t.checked || rows.text(r, "reference_method") != kNoReferenceName;
    t.within6 += ok && error <= 1e-6;
    t.within9 += ok && error <= 1e-9;
    t.errors.push_back(ok ? error : INFINITY);
    t.statusCounts[stabilityStatusCode(rows.text(r, "status"))] += 1;
  }
  CsvTable summary{stabilitySummaryColumns(), {}};
  for (const auto& method : order) {
    Tally& t = tallies[method];
    double median = NAN;
    if (t.checked) {
      std::nth_element(t.errors.begin(), t.errors.begin() + t.errors.size() / 2, t.errors.end());
      median = t.errors[t.errors.size() / 2];
    }
    auto fraction = [&](long count) { return formatNumber(t.checked ? static_cast<double>(count) / t.cells : NAN); };
    std::vector<std::string> row = {method,
                                    t.integrator,
                                    t.setting,
                                    std::to_string(t.cells),
                                    fraction(t.within6),
                                    fraction(t.within9),
                                    formatNumber(median)};
    for (long count : t.statusCounts) row.push_back(std::to_string(count));
    summary.rows.push_back(std::move(row));
  }
  return summary;
}

}  // namespace sl

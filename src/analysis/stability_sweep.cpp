#include "analysis/stability_sweep.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
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
std::vector<StabilityRow> cellRows(const StabilityOptions& options, const std::vector<Method>& methods,
                                   long cellIndex) {
  const int i = static_cast<int>(cellIndex % options.grid), j = static_cast<int>(cellIndex / options.grid);
  std::vector<StabilityRow> rows;
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
      rows.push_back({cellIndex, i, j, cell.x, cell.y, method, config.integrator, config.accuracySetting(), m.status,
                      m.stopTime, m.finalError, m.maxError, m.maxEnergyDrift, m.maxRodLengthError, m.evaluations,
                      referenceMethodName(reference), m.stopDetail});
    }
  } catch (const std::exception& error) {
    // A start the reference cannot construct (e.g. the backward run of a pole cell stopped) is a result too.
    rows.clear();
    for (const Method method : methods) {
      const RunConfig config = sweepConfig(options, method);
      // No value (the cell's start could not be made, so neither its point nor any error).
      rows.push_back({cellIndex, i, j, NAN, NAN, method, config.integrator, config.accuracySetting(),
                      Verdict::ReferenceStopped, 0, NAN, NAN, NAN, NAN, 0, nameOf(referenceMethodFor(method)),
                      error.what()});
    }
  }
  return rows;
}

std::vector<Method> sweepMethods(const StabilityOptions& options) {
  return options.methods.empty() ? kindsOf(kMethods) : options.methods;
}

}  // namespace

std::vector<StabilityRow> runStabilitySweep(const StabilityOptions& options, const CellProgress& progress) {
  if (!isStabilityKind(options.kind))
    throw std::invalid_argument("unknown stability sweep kind '" + options.kind + "'");
  if (options.grid < 1) throw std::invalid_argument("--grid must be at least 1");
  const auto methods = sweepMethods(options);
  std::vector<long> cells;
  for (long c = options.shard.index - 1; c < static_cast<long>(options.grid) * options.grid; c += options.shard.count)
    cells.push_back(c);

  std::vector<std::vector<StabilityRow>> results(cells.size());
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

  std::vector<StabilityRow> rows;
  for (auto& cellRowsOfOne : results)
    for (auto& row : cellRowsOfOne) rows.push_back(std::move(row));
  return rows;
}

CsvTable stabilityTable(const std::vector<StabilityRow>& rows) {
  CsvTable table{stabilityColumns(), {}};
  table.rows.reserve(rows.size());
  for (const StabilityRow& r : rows)
    table.rows.push_back({std::to_string(r.cell), std::to_string(r.i), std::to_string(r.j), formatNumber(r.x),
                          formatNumber(r.y), nameOf(r.method), nameOf(r.integrator), formatNumber(r.setting),
                          statusName(r.status), formatNumber(r.stopTime), formatNumber(r.finalError),
                          formatNumber(r.maxError), formatNumber(r.maxEnergyDrift), formatNumber(r.maxRodLengthError),
                          std::to_string(r.evaluations), r.referenceMethod, r.stopDetail});
  return table;
}

std::vector<std::pair<std::string, std::string>> stabilityIdentity(const StabilityOptions& options) {
  std::string methods, integrators, references;
  for (const Method method : sweepMethods(options)) {
    const char* space = methods.empty() ? "" : " ";
    methods += space + std::string(nameOf(method));
    integrators += space + std::string(nameOf(sweepConfig(options, method).integrator));
    references += space + (options.checkAgainstReference ? std::string(nameOf(referenceMethodFor(method)))
                                                         : std::string(kNoReferenceName));
  }
  return {{"kind", options.kind},
          {"grid", std::to_string(options.grid)},
          {"duration", formatNumber(options.duration)},
          {"interval", formatNumber(options.sampleInterval)},
          {"methods", methods},
          {"integrators", integrators},
          {"tolerance", formatNumber(options.tolerance)},
          {"step", formatNumber(options.step)},
          {"references", references}};
}

namespace {

constexpr std::string_view kShardIdentityPrefix = "# linkage stability shard: ";

std::string identityLine(const std::vector<std::pair<std::string, std::string>>& identity) {
  std::string line(kShardIdentityPrefix);
  for (size_t k = 0; k < identity.size(); ++k)
    line += (k ? "; " : "") + identity[k].first + "=" + identity[k].second;
  return line;
}

using Identity = std::vector<std::pair<std::string, std::string>>;

Identity parseIdentityLine(const std::string& line, const std::string& path) {
  if (line.rfind(kShardIdentityPrefix, 0) != 0)
    throw std::invalid_argument(path + ": not a stability shard of this version (its first line should be \"" +
                                std::string(kShardIdentityPrefix) + "...\", the sweep it belongs to; run it again)");
  Identity identity;
  std::string rest = line.substr(kShardIdentityPrefix.size());
  for (size_t at = 0; at <= rest.size();) {
    const size_t end = std::min(rest.find("; ", at), rest.size());
    const std::string pair = rest.substr(at, end - at);
    const size_t equals = pair.find('=');
    if (equals == std::string::npos)
      throw std::invalid_argument(path + ": line 1: expected key=value pairs, found '" + pair + "'");
    identity.emplace_back(pair.substr(0, equals), pair.substr(equals + 1));
    at = end + 2;
  }
  return identity;
}

// The value of `key`, or throws naming the file.
const std::string& identityValue(const Identity& identity, const std::string& key, const std::string& path) {
  for (const auto& [k, v] : identity)
    if (k == key) return v;
  throw std::invalid_argument(path + ": line 1: the shard's identity has no " + key);
}

long parseIndex(const std::string& text, const std::string& where, const char* column) {
  if (text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos)
    throw std::invalid_argument(where + ": column " + column + " is '" + text + "', expected a count or index");
  return std::stol(text);
}

double parseField(const std::string& text, const std::string& where, const char* column) {
  try {
    return parseNumber(text);
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument(where + ": column " + column + " is '" + text + "', expected a number or no value");
  }
}

template <class Table>
auto parseKindField(const Table& table, const std::string& text, const std::string& where, const char* column) {
  if (const auto kind = parseKind(table, text)) return *kind;
  throw std::invalid_argument(where + ": column " + column + " is '" + text + "', not a known name");
}

StabilityRow parseRow(const std::vector<std::string>& f, const std::string& where) {
  StabilityRow r;
  r.cell = parseIndex(f[0], where, "cell");
  r.i = static_cast<int>(parseIndex(f[1], where, "i"));
  r.j = static_cast<int>(parseIndex(f[2], where, "j"));
  r.x = parseField(f[3], where, "x");
  r.y = parseField(f[4], where, "y");
  r.method = parseKindField(kMethods, f[5], where, "method");
  r.integrator = parseKindField(kIntegrators, f[6], where, "integrator");
  r.setting = parseField(f[7], where, "setting");
  const auto status = parseStatus(f[8]);
  if (!status) throw std::invalid_argument(where + ": column status is '" + f[8] + "', not a known status");
  r.status = *status;
  r.stopTime = parseField(f[9], where, "stop_time");
  r.finalError = parseField(f[10], where, "final_error");
  r.maxError = parseField(f[11], where, "max_error");
  r.maxEnergyDrift = parseField(f[12], where, "max_energy_drift");
  r.maxRodLengthError = parseField(f[13], where, "max_rod_length_error");
  r.evaluations = parseIndex(f[14], where, "evaluations");
  if (f[15] != kNoReferenceName) parseKindField(kMethods, f[15], where, "reference_method");
  r.referenceMethod = f[15];
  r.stopDetail = f[16];
  return r;
}

// Reads shard K of N: its identity line and its rows, checked to be exactly its cells with every method.
std::vector<StabilityRow> readShard(const std::string& path, const Shard& shard, Identity& identity) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open the stability shard for reading");
  std::string first;
  std::getline(in, first);
  identity = parseIdentityLine(first, path);
  CsvTable table;
  try {
    table = readCsv(in, path + " (after line 1)");
  } catch (const std::exception& error) {
    throw std::invalid_argument(path + ": not a readable stability shard (" + error.what() + ")");
  }
  if (table.columns != stabilityColumns())
    throw std::invalid_argument(path + ": not a stability shard (columns differ from " + stabilityColumns().front() +
                                ",...)");
  const long grid = parseIndex(identityValue(identity, "grid", path), path + ": line 1", "grid");
  std::vector<std::string> methods;
  const std::string& names = identityValue(identity, "methods", path);
  for (size_t at = 0; at < names.size();) {
    const size_t end = std::min(names.find(' ', at), names.size());
    methods.push_back(names.substr(at, end - at));
    at = end + 1;
  }
  if (grid < 1 || grid > 4096 || methods.empty())
    throw std::invalid_argument(path + ": line 1: expected a grid of 1 to 4096 cells per axis and some methods");
  std::vector<StabilityRow> rows;
  long expectedCell = shard.index - 1;
  size_t method = 0;
  for (size_t k = 0; k < table.rows.size(); ++k) {
    const std::string where = path + ": row " + std::to_string(k + 3);
    StabilityRow row = parseRow(table.rows[k], where);
    if (expectedCell >= grid * grid)
      throw std::invalid_argument(where + ": a row beyond the last cell of the " + std::to_string(grid) + " x " +
                                  std::to_string(grid) + " grid");
    if (row.cell != expectedCell || row.i != row.cell % grid || row.j != row.cell / grid ||
        nameOf(row.method) != methods[method])
      throw std::invalid_argument(where + ": expected cell " + std::to_string(expectedCell) + " (i " +
                                  std::to_string(expectedCell % grid) + ", j " + std::to_string(expectedCell / grid) +
                                  ") of method " + methods[method] + ", found cell " + std::to_string(row.cell) +
                                  " of method " + nameOf(row.method) + " (a shard holds cells c with c mod " +
                                  std::to_string(shard.count) + " = " + std::to_string(shard.index - 1) + ")");
    rows.push_back(std::move(row));
    if (++method == methods.size()) {
      method = 0;
      expectedCell += shard.count;
    }
  }
  if (method != 0 || expectedCell < grid * grid)
    throw std::invalid_argument(path + ": ends before cell " + std::to_string(expectedCell) + " of the " +
                                std::to_string(grid) + " x " + std::to_string(grid) + " grid (a cut shard?)");
  return rows;
}

}  // namespace

std::string stabilityShardText(const StabilityOptions& options, const std::vector<StabilityRow>& rows) {
  return identityLine(stabilityIdentity(options)) + "\n" + csvText(stabilityTable(rows));
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

bool mergeStabilityShards(const std::string& outDir, const std::string& kind, int shardCount,
                          std::vector<StabilityRow>& merged) {
  std::vector<std::string> paths;
  for (int k = 1; k <= shardCount; ++k) {
    paths.push_back(stabilityShardPath(outDir, kind, {k, shardCount}));
    if (!std::filesystem::exists(paths.back())) return false;
  }
  std::vector<std::vector<StabilityRow>> shards;
  Identity first;
  for (int k = 1; k <= shardCount; ++k) {
    const std::string& path = paths[static_cast<size_t>(k - 1)];
    Identity identity;
    shards.push_back(readShard(path, {k, shardCount}, identity));
    if (identityValue(identity, "kind", path) != kind)
      throw std::invalid_argument(path + ": line 1: a shard of the '" + identityValue(identity, "kind", path) +
                                  "' sweep, not of '" + kind + "'");
    if (k == 1) {
      first = identity;
      continue;
    }
    std::string differences;
    for (const auto& [key, value] : first) {
      const std::string& other = identityValue(identity, key, path);
      if (other != value)
        differences += (differences.empty() ? "" : "; ") + key + " " + other + " here, " + value + " in shard 1";
    }
    if (!differences.empty())
      throw std::invalid_argument(path + ": a shard of another sweep than " + paths.front() + " (" + differences +
                                  "); run every shard with the same options, or remove the stale ones");
  }
  // Cell c is in shard c mod N + 1, at position c / N there: the rows in cell order, methods kept in order.
  const std::string& names = identityValue(first, "methods", paths.front());
  const size_t methods = static_cast<size_t>(std::count(names.begin(), names.end(), ' ')) + 1;
  std::vector<StabilityRow> rows;
  size_t total = 0;
  for (const auto& shard : shards) total += shard.size();
  rows.reserve(total);
  for (size_t position = 0; rows.size() < total; ++position)
    for (auto& shard : shards)
      for (size_t m = 0; m < methods && position * methods + m < shard.size(); ++m)
        rows.push_back(std::move(shard[position * methods + m]));
  merged = std::move(rows);
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

CsvTable stabilitySummary(const std::vector<StabilityRow>& rows) {
  struct Tally {
    std::string integrator, setting;
    long cells = 0, within6 = 0, within9 = 0;
    bool checked = false;  // some row has a reference
    std::vector<double> errors;
    std::vector<long> statusCounts = std::vector<long>(stabilityStatusNames().size(), 0);
  };
  std::vector<std::string> order;
  std::map<std::string, Tally> tallies;
  for (const StabilityRow& row : rows) {
    const std::string method(nameOf(row.method));
    if (!tallies.count(method)) order.push_back(method);
    Tally& t = tallies[method];
    t.integrator = nameOf(row.integrator);
    t.setting = formatNumber(row.setting);
    const bool ok = statusName(row.status) == nameOf(Verdict::Ok);
    const double error = row.maxError;
    t.cells += 1;
    t.checked = t.checked || row.referenceMethod != kNoReferenceName;
    t.within6 += ok && error <= 1e-6;
    t.within9 += ok && error <= 1e-9;
    t.errors.push_back(ok ? error : INFINITY);
    t.statusCounts[stabilityStatusCode(statusName(row.status))] += 1;
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

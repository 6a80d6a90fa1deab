#include "cli/csv_diff.hpp"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <map>
#include <ostream>

namespace sl {

namespace {

using Row = TrajectoryCsv::Row;

// Rows by run; a family's members (the optional member column, trajectory_csv.hpp) each count as a run of their
// own, "name [member k]".
std::map<std::string, std::vector<const Row*>> rowsByRun(const TrajectoryCsv& csv) {
  std::map<std::string, std::vector<const Row*>> runs;
  const int member = csv.valueIndex("member");
  for (const Row& row : csv.rows) {
    const double k = member < 0 ? 0.0 : row.values[size_t(member)];
    runs[k > 0 ? row.run + " [member " + std::to_string(long(k)) + "]" : row.run].push_back(&row);
  }
  return runs;
}

// Indices into Row::values of (p1x, p1y), (p2x, p2y), ...
std::vector<std::pair<int, int>> hingeColumns(const TrajectoryCsv& csv) {
  std::vector<std::pair<int, int>> columns;
  for (int k = 1;; ++k) {
    const int x = csv.valueIndex("p" + std::to_string(k) + "x"), y = csv.valueIndex("p" + std::to_string(k) + "y");
    if (x < 0 || y < 0) return columns;
    columns.push_back({x, y});
  }
}

// 3 as "3", 0.1 as "0.1" (std::to_string gives "3.000000").
std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

// The same value, or both non-finite in the same way (a file compared with itself matches, NaN included).
bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// One coordinate's difference: 0 for the same value, infinite where only one side is finite (a NaN against a
// number is as different as can be, and never hides behind a later row's small difference).
double difference(double a, double b) {
  if (same(a, b)) return 0;
  if (!std::isfinite(a) || !std::isfinite(b)) return INFINITY;
  return std::abs(a - b);
}

double hingeDistance(const Row& a, const Row& b, const std::vector<std::pair<int, int>>& columns) {
  double worst = 0;
  for (const auto& [x, y] : columns)
    worst = std::max(worst, std::hypot(difference(a.values[size_t(x)], b.values[size_t(x)]),
                                       difference(a.values[size_t(y)], b.values[size_t(y)])));
  return worst;
}

RunDifference compareRun(const std::string& name, const std::vector<const Row*>& before,
                         const std::vector<const Row*>& after, const std::vector<std::pair<int, int>>& columns,
                         std::size_t time, double tolerance) {
  RunDifference result;
  result.run = name;
  const size_t common = std::min(before.size(), after.size());
  for (size_t i = 0; i < common; ++i) {
    const Row& a = *before[i];
    const Row& b = *after[i];
    if (!same(a.values[time], b.values[time])) {
      result.structure = "sample times differ from row " + std::to_string(i + 1) + " of the run on";
      result.comparedRows = 0;  // sampled at other times: no figure compares like with like
      return result;
    }
    const double distance = hingeDistance(a, b, columns);
    result.comparedRows = i + 1;
    if (distance > result.worstDistance) {
      result.worstDistance = distance;
      result.worstTime = a.values[time];
    }
    if (distance > tolerance && !result.firstExceedsAt) result.firstExceedsAt = a.values[time];
    if (a.status != b.status) {
      result.structure =
          "status at t = " + shortNumber(a.values[time]) + ": \"" + a.status + "\" vs \"" + b.status + "\"";
      return result;
    }
  }
  if (before.size() != after.size()) {
    result.structure = std::to_string(before.size()) + " rows vs " + std::to_string(after.size());
  }
  return result;
}

}  // namespace

std::vector<RunDifference> compareTrajectories(const TrajectoryCsv& before, const TrajectoryCsv& after,
                                               double tolerance) {
  std::vector<RunDifference> differences;
  if (before.columns != after.columns) {
    differences.push_back({"(all)", 0, 0, std::nullopt, "the columns differ (different numbers of rods?)"});
    return differences;
  }
  const auto columns = hingeColumns(before);
  const std::size_t time = static_cast<std::size_t>(std::max(0, before.valueIndex("time")));
  const auto runsBefore = rowsByRun(before), runsAfter = rowsByRun(after);
  for (const auto& [name, rows] : runsBefore) {
    const auto other = runsAfter.find(name);
    if (other == runsAfter.end()) {
      differences.push_back({name, 0, 0, std::nullopt, "missing from the second file"});
      continue;
    }
    differences.push_back(compareRun(name, rows, other->second, columns, time, tolerance));
  }
  for (const auto& [name, rows] : runsAfter) {
    if (!runsBefore.count(name)) differences.push_back({name, 0, 0, std::nullopt, "missing from the first file"});
  }
  return differences;
}

bool printTrajectoryDifferences(std::ostream& out, const std::vector<RunDifference>& differences, double tolerance) {
  bool allMatch = true;
  for (const RunDifference& run : differences) {
    allMatch = allMatch && run.matches();
    out << "run \"" << run.run << "\": ";
    if (run.comparedRows == 0 && !run.structure.empty()) {
      out << "not compared: " << run.structure << '\n';
      continue;
    }
    if (!run.structure.empty()) out << "over its first " << run.comparedRows << " rows: ";
    out << "worst hinge difference " << run.worstDistance << " at t = " << run.worstTime;
    if (run.firstExceedsAt)
      out << "; first exceeds --tol " << tolerance << " at t = " << *run.firstExceedsAt;
    else
      out << "; within --tol " << tolerance;
    if (!run.structure.empty()) out << "; then not comparable row by row: " << run.structure;
    out << '\n';
  }
  return allMatch;
}

}  // namespace sl

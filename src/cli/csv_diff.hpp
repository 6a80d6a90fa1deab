#pragma once
// Comparing two trajectory CSVs (simulation/trajectory_csv.hpp) run by run: the worst hinge position
// difference and the first time it exceeds a tolerance.

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "simulation/trajectory_csv.hpp"

namespace sl {

struct RunDifference {
  std::string run;
  double worstDistance = 0;  // max over common sample times of max over hinges |p_old - p_new|
  double worstTime = 0;
  std::optional<double> firstExceedsAt;  // first time the distance exceeds the tolerance
  std::string structure;  // non-empty when the runs cannot be compared row by row (times, stops, missing)
  std::size_t comparedRows = 0;  // rows compared before `structure` stopped the comparison (all, if it is empty)
  bool matches() const { return structure.empty() && !firstExceedsAt; }
};

std::vector<RunDifference> compareTrajectories(const TrajectoryCsv& before, const TrajectoryCsv& after,
                                               double tolerance);

// One line per run; returns whether all match. A run of which no row could be compared (missing from one side,
// other sample times from the first row on) is reported as not compared, with no figure.
bool printTrajectoryDifferences(std::ostream& out, const std::vector<RunDifference>& differences, double tolerance);

}  // namespace sl

#pragma once
// Work-precision charts (gnuplot, log-log): position error against wall time, position error against
// vector-field evaluations and energy drift against wall time, one line per method x integrator, per start
// and for the worst case over all starts. Failed points (a watchdog stop or a wrong path) are marked with
// crosses on a "failed" band above the chart's data.

#include <string>
#include <vector>

#include "analysis/work_precision.hpp"

namespace sl {

// Writes the charts into outDir and returns their paths (PNG; a .gp script beside each).
std::vector<std::string> writeWorkPrecisionCharts(const std::vector<WorkPrecisionPoint>& points,
                                                  const std::string& outDir);

}  // namespace sl

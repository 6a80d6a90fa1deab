#pragma once
// Work-precision charts (gnuplot, log-log): position error against wall time, position error against
// vector-field evaluations and energy drift against wall time, one line per method x integrator, per start
// and for the worst case over all starts (small multiples, one panel per integrator, when a chart would hold
// more than 8 lines). Failed points (a watchdog stop or a wrong path) are crosses in their method's colour on
// a "failed" band above the chart's data, one legend entry per method that failed.

#include <string>
#include <vector>

#include "analysis/work_precision.hpp"

namespace sl {

// How one method x integrator is drawn: colour and marker by method, dash and width by integrator.
struct SeriesStyle {
  std::string color;  // "#rrggbb"
  int pointType = 1;  // gnuplot's pt
  int dashType = 1;   // gnuplot's dt
  double lineWidth = 1.5;
};
SeriesStyle workPrecisionStyle(Method method, Integrator integrator);

// Writes the charts into outDir and returns their paths (PNG; a .gp script beside each).
std::vector<std::string> writeWorkPrecisionCharts(const std::vector<WorkPrecisionPoint>& points,
                                                  const std::string& outDir);

}  // namespace sl

#pragma once
// Stability maps (gnuplot heat maps): for each method of a sweep, one PNG with two panels, the max
// position error against the reference (log10, failed cells dark grey) and the failure mode of each cell.
// Drawn from the sweep's CSV rows only, so a merged sweep draws the same bytes as a single run.

#include <string>
#include <vector>

#include "analysis/csv_table.hpp"

namespace sl {

// Writes DIR/stability-<kind>-<method>.png (and .gp) per method; returns the PNG paths.
std::vector<std::string> writeStabilityCharts(const CsvTable& rows, const std::string& kind, const std::string& outDir);

}  // namespace sl

#pragma once
// `--chart-formats svg,pdf` on the commands that draw charts (bench, stability, geometry): each chart is also
// written as SVG and/or PDF beside its PNG (and its gnuplot script, CHART.gp, which redraws it by hand).

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace sl {

// Adds the option; `formats` receives the text as given.
void addChartFormatsOption(CLI::App& command, std::string& formats);

// The formats, checked: throws CLI::ValidationError naming --chart-formats. Call before any work.
std::vector<std::string> chartFormats(const std::string& text);

// Renders the chart behind each PNG in the other formats and prints "wrote FILE" for each file written.
void writeChartFormats(const std::vector<std::string>& pngs, const std::vector<std::string>& formats);

}  // namespace sl

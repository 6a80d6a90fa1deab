#include "cli/chart_formats.hpp"

#include <iostream>
#include <stdexcept>

#include <CLI/CLI.hpp>

#include "analysis/gnuplot.hpp"

namespace sl {

void addChartFormatsOption(CLI::App& command, std::string& formats) {
  command.add_option("--chart-formats", formats,
                     "also write each chart as svg and/or pdf (e.g. svg,pdf), beside its PNG, for papers");
}

std::vector<std::string> chartFormats(const std::string& text) {
  try {
    return parseChartFormats(text);
  } catch (const std::invalid_argument& error) {
    throw CLI::ValidationError("--chart-formats", error.what());
  }
}

void writeChartFormats(const std::vector<std::string>& pngs, const std::vector<std::string>& formats) {
  if (formats.empty()) return;
  for (const std::string& png : pngs)
    for (const std::string& file : renderChartAs(png, formats)) std::cout << "wrote " << file << "\n";
}

}  // namespace sl

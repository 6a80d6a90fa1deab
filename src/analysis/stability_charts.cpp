#include "analysis/stability_charts.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "analysis/gnuplot.hpp"
#include "analysis/measurement.hpp"
#include "analysis/reference_path.hpp"
#include "analysis/stability_grid.hpp"
#include "analysis/stability_sweep.hpp"

namespace sl {

namespace {

// One colour per status, in stabilityStatusNames() order; a status beyond the list is drawn grey.
std::string statusColor(size_t code) {
  static const std::vector<std::string> colors = {"#1a9850", "#fdae61", "#d73027", "#f46d43", "#000000", "#7b3294",
                                                  "#2c7bb6", "#abd9e9", "#bababa", "#8c510a", "#ffffbf", "#878787"};
  return code < colors.size() ? colors[code] : "#878787";
}

std::string failurePalette() {
  const auto names = stabilityStatusNames();
  // Band k spans palette positions [k, k+1], which cbrange maps onto [k - 1/2, k + 1/2]: one flat colour each.
  std::string palette = "set palette defined (";
  std::string tics = "set cbtics (";
  for (size_t k = 0; k < names.size(); ++k) {
    const std::string color = " '" + statusColor(k) + "'";
    palette += (k ? ", " : "") + std::to_string(k) + color + ", " + std::to_string(k + 1) + color;
    tics += (k ? ", " : "") + gnuplotQuote(names[k]) + " " + std::to_string(k);
  }
  return palette + ")\n" + tics + ")\nset cbrange [-0.5:" + std::to_string(names.size() - 0.5) + "]\n";
}

std::string mapScript(const CsvTable& rows, const std::string& kind, const std::string& method,
                      const std::string& png) {
  std::vector<std::string> lines;
  std::string integrator, setting;
  long cells = 0, within9 = 0;
  double lowest = INFINITY, highest = -INFINITY;  // the successful cells' log10 values: the colour bar's range
  bool checked = false;  // errors against a reference; without one the left panel shows the energy drift
  for (size_t r = 0; r < rows.rows.size(); ++r)
    if (rows.text(r, "method") == method) checked = checked || rows.text(r, "reference_method") != kNoReferenceName;
  const std::string valueColumn = checked ? "max_error" : "max_energy_drift";
  for (size_t r = 0; r < rows.rows.size(); ++r) {
    if (rows.text(r, "method") != method) continue;
    integrator = rows.text(r, "integrator");
    setting = rows.text(r, "setting");
    const std::string status = rows.text(r, "status");
    const double value = rows.number(r, valueColumn), error = rows.number(r, "max_error");
    const bool ok = status == nameOf(Verdict::Ok);
    const double logError = ok ? std::clamp(std::log10(std::max(value, 1e-300)), -16.0, 0.0) : NAN;
    if (ok) lowest = std::min(lowest, logError), highest = std::max(highest, logError);
    lines.push_back(gnuplotNumber(rows.number(r, "x")) + " " + gnuplotNumber(rows.number(r, "y")) + " " +
                    gnuplotNumber(logError) + " " +
                    std::to_string(stabilityStatusCode(status)));
    cells += 1;
    within9 += ok && error <= 1e-9;
  }
  const auto [xLabel, yLabel] = stabilityAxisLabels(kind);
  std::string script = gnuplotPngPreamble(png, 1400, 620);
  script += gnuplotDatablock("cells", lines);
  script += "set multiplot layout 1,2 title " +
            gnuplotQuote("stability sweep '" + kind + "': " + method + " " + integrator + " (setting " + setting + ")" +
                         (checked ? ", " + std::to_string(100.0 * within9 / std::max(cells, 1L)).substr(0, 5) +
                                        "% of cells within 1e-9 of the reference"
                                  : ", no reference")) +
            " noenhanced\n";
  script += "set xlabel " + gnuplotQuote(xLabel) + "\nset ylabel " + gnuplotQuote(yLabel) + "\n";
  script += "set autoscale xfix\nset autoscale yfix\nset tics out\nunset key\n";
  // Failed cells are left out of the error image and show a light grey background, a colour the sequential map
  // below never takes (and unlike the failure-mode key's black, which means non-finite there).
  script +=
      "set object 1 rectangle from graph 0,0 to graph 1,1 behind fillcolor rgb '#d9d9d9' fillstyle solid noborder\n";
  script += std::string("set title '") +
            (checked ? "log_{10} max position error" : "log_{10} max relative energy drift") + " (grey: failed)'\n";
  // A sequential, colour-blind-safe map (viridis) over the whole decades the data reach: no pale middle suggesting
  // a meaningful midpoint, and no range left empty.
  if (!std::isfinite(lowest)) lowest = -16, highest = 0;  // no cell succeeded: the whole scale
  lowest = std::floor(lowest);
  highest = std::max(std::ceil(highest), lowest + 1);
  script += "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')\n";
  script += "set cbrange [" + gnuplotNumber(lowest) + ":" + gnuplotNumber(highest) + "]\nset cbtics " +
            (highest - lowest > 8 ? "2" : "1") + "\n";
  script += "plot $cells using 1:2:3 with image\n";
  script += "unset object 1\nset title 'failure mode'\nset rmargin 20\n" + failurePalette();
  script += "plot $cells using 1:2:4 with image\nunset multiplot\n";
  return script;
}

}  // namespace

std::vector<std::string> writeStabilityCharts(const CsvTable& rows, const std::string& kind,
                                              const std::string& outDir) {
  std::vector<std::string> methods;
  for (size_t r = 0; r < rows.rows.size(); ++r)
    if (std::find(methods.begin(), methods.end(), rows.text(r, "method")) == methods.end())
      methods.push_back(rows.text(r, "method"));
  std::filesystem::create_directories(outDir);
  std::vector<std::string> written;
  for (const auto& method : methods) {
    const std::string png = (std::filesystem::path(outDir) / ("stability-" + kind + "-" + method + ".png")).string();
    renderGnuplotChart(mapScript(rows, kind, method, png), png);
    written.push_back(png);
  }
  return written;
}

}  // namespace sl

#include "analysis/work_precision_charts.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>

#include "analysis/gnuplot.hpp"

namespace sl {

namespace {

constexpr double kFailedBand = 30;  // where failed points are drawn (the y axis ends at 1e2)
constexpr double kFloor = 1e-17;    // zero drift or error is drawn here on the log axis

// The published methods in browns, the exact chart-based ones in blue and green, the chart-free one in purple.
std::string methodColor(Method method) {
  switch (method) {
    case Method::ChristoffelFd:
      return "#d95f02";
    case Method::EmbeddedFd:
      return "#a6761d";
    case Method::Christoffel:
      return "#1f78b4";
    case Method::Embedded:
      return "#33a02c";
    case Method::Ambient:
      return "#6a3d9a";
  }
  return "#444444";  // unreachable: the switch names every method, and -Wswitch flags a new one
}

// Dash, point type and width by integrator: fixed step dashed, adaptive solid (rkf78 thick), others dash-dot.
std::string integratorStyle(Integrator integrator) {
  if (!traits(integrator).adaptive) return "dt 2 pt 6 lw 1.5";
  switch (integrator) {
    case Integrator::Dopri5:
      return "dt 1 pt 8 lw 1.5";
    case Integrator::Rkf78:
      return "dt 1 pt 4 lw 2.5";
    default:
      return "dt 4 pt 12 lw 2";  // bulirsch-stoer and any other: dash-dot, diamonds
  }
}

struct Axis {
  std::string label;
  double (*value)(const Measurement&);
};

double wallMilliseconds(const Measurement& m) { return m.wallSeconds * 1e3; }
double evaluations(const Measurement& m) { return static_cast<double>(m.evaluations); }
double positionError(const Measurement& m) { return std::max(m.maxError, kFloor); }
double energyDrift(const Measurement& m) { return std::max(m.maxEnergyDrift, kFloor); }

struct ChartSpec {
  std::string fileSuffix, title;
  Axis x, y;
};

std::vector<ChartSpec> chartSpecs() {
  return {{"error-time",
           "max position error against wall time",
           {"wall time per run [ms] (median)", wallMilliseconds},
           {"max hinge position error over the run", positionError}},
          {"error-evaluations",
           "max position error against vector-field evaluations",
           {"vector-field evaluations", evaluations},
           {"max hinge position error over the run", positionError}},
          {"energy-time",
           "max relative energy drift against wall time",
           {"wall time per run [ms] (median)", wallMilliseconds},
           {"max |E - E_0| / E_0", energyDrift}}};
}

// One series: the points of one method x integrator at increasing cost.
using Series = std::vector<const WorkPrecisionPoint*>;

std::string chartScript(const std::string& title, const ChartSpec& spec, const std::vector<Series>& series,
                        const std::string& pngPath) {
  std::string script = gnuplotPngPreamble(pngPath, 1100, 720);
  script += "set title " + gnuplotQuote(title + ": " + spec.title) + " noenhanced\n";
  script +=
      "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset grid xtics ytics mxtics mytics lc rgb "
      "'#dddddd'\n";
  script += "set xlabel " + gnuplotQuote(spec.x.label) + "\nset ylabel " + gnuplotQuote(spec.y.label) + "\n";
  script += "set yrange [1e-17:1e2]\nset key outside right top noenhanced\n";
  script += "set arrow from graph 0, first 10 to graph 1, first 10 nohead lc rgb '#bbbbbb' dt 3\n";
  script += "set label 'failed' at graph 0.01, first 45 tc rgb '#cc0000'\n";
  std::vector<std::string> failed;
  std::string plot = "plot ";
  for (size_t i = 0; i < series.size(); ++i) {
    std::vector<std::string> lines;
    for (const auto* p : series[i]) {
      const Measurement& m = p->measurement;
      const std::string x = formatNumber(spec.x.value(m));
      if (m.failed())
        failed.push_back(x + " " + formatNumber(kFailedBand) + " 0x" + methodColor(p->method).substr(1));
      else
        lines.push_back(x + " " + formatNumber(spec.y.value(m)));
    }
    if (lines.empty()) lines.push_back("NaN NaN");
    const std::string block = "s" + std::to_string(i);
    script += gnuplotDatablock(block, lines);
    const auto& first = *series[i].front();
    plot += "$" + block + " using 1:2 with linespoints lc rgb '" + methodColor(first.method) + "' " +
            integratorStyle(first.integrator) + " title " +
            gnuplotQuote(nameOf(first.method) + " " + nameOf(first.integrator)) + ", ";
  }
  if (failed.empty()) failed.push_back("NaN NaN 0");
  script += gnuplotDatablock("failed", failed);
  plot += "$failed using 1:2:3 with points pt 2 ps 2 lw 2 lc rgb variable title 'failed'\n";
  return script + plot;
}

// Series in first-appearance order, points by decreasing setting (increasing cost).
std::vector<Series> seriesOf(const std::vector<const WorkPrecisionPoint*>& points) {
  std::vector<Series> series;
  std::map<std::pair<Method, Integrator>, size_t> index;
  for (const auto* p : points) {
    const auto key = std::make_pair(p->method, p->integrator);
    if (!index.count(key)) {
      index[key] = series.size();
      series.emplace_back();
    }
    series[index[key]].push_back(p);
  }
  for (auto& s : series) std::stable_sort(s.begin(), s.end(), [](auto* a, auto* b) { return a->setting > b->setting; });
  return series;
}

// The worst case over the starts at each setting: max error and drift, max time and evaluations, failed
// if any start failed.
std::vector<WorkPrecisionPoint> worstOverStarts(const std::vector<WorkPrecisionPoint>& points) {
  std::vector<WorkPrecisionPoint> worst;
  std::map<std::tuple<Method, Integrator, double>, size_t> index;
  for (const auto& p : points) {
    const auto key = std::make_tuple(p.method, p.integrator, p.setting);
    if (!index.count(key)) {
      index[key] = worst.size();
      worst.push_back(p);
      worst.back().start = "worst over starts";
      continue;
    }
    Measurement& w = worst[index[key]].measurement;
    const Measurement& m = p.measurement;
    if (m.failed()) w.status = m.status;
    if (!(m.maxError <= w.maxError)) w.maxError = m.maxError;
    w.maxEnergyDrift = std::max(w.maxEnergyDrift, m.maxEnergyDrift);
    w.wallSeconds = std::max(w.wallSeconds, m.wallSeconds);
    w.evaluations = std::max(w.evaluations, m.evaluations);
  }
  return worst;
}

}  // namespace

std::vector<std::string> writeWorkPrecisionCharts(const std::vector<WorkPrecisionPoint>& points,
                                                  const std::string& outDir) {
  std::filesystem::create_directories(outDir);
  std::vector<std::string> starts;
  for (const auto& p : points)
    if (std::find(starts.begin(), starts.end(), p.start) == starts.end()) starts.push_back(p.start);
  const std::vector<WorkPrecisionPoint> worst = worstOverStarts(points);

  std::vector<std::string> written;
  auto chartsFor = [&](const std::string& name, const std::vector<const WorkPrecisionPoint*>& chosen) {
    const auto series = seriesOf(chosen);
    for (const auto& spec : chartSpecs()) {
      const std::string png =
          (std::filesystem::path(outDir) / ("wp-" + name + "-" + spec.fileSuffix + ".png")).string();
      renderGnuplotChart(chartScript(name, spec, series, png), png);
      written.push_back(png);
    }
  };
  std::vector<const WorkPrecisionPoint*> all;
  for (const auto& p : worst) all.push_back(&p);
  chartsFor("all-starts-worst-case", all);
  for (const auto& start : starts) {
    std::vector<const WorkPrecisionPoint*> chosen;
    for (const auto& p : points)
      if (p.start == start) chosen.push_back(&p);
    chartsFor(start, chosen);
  }
  return written;
}

}  // namespace sl

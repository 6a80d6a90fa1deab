#include "analysis/work_precision_charts.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>

#include "analysis/gnuplot.hpp"

namespace sl {

namespace {

constexpr double kFailedBand = 30;  // where failed points are drawn, above a rule at 10 (the y axis ends at 60)
constexpr double kFloor = 1e-17;    // zero drift or error is drawn here on the log axis
constexpr size_t kMaxSeriesPerPanel = 8;  // beyond this a chart becomes small multiples, one panel per integrator

}  // namespace

// Okabe-Ito colours (distinguishable with the common colour-vision deficiencies) and a marker per method, so
// that a method reads by its shape too: the published methods in vermillion and reddish purple with triangles,
// the exact chart-based ones in blue and green with circles and squares, the chart-free one black diamonds.
// The integrator sets the dash: rkf78 solid and thicker, dopri5 long dashes, bulirsch-stoer dash-dot, rk4
// (fixed step) dots.
SeriesStyle workPrecisionStyle(Method method, Integrator integrator) {
  SeriesStyle style;
  switch (method) {
    case Method::ChristoffelFd:
      style.color = "#D55E00", style.pointType = 9;  // filled triangle up
      break;
    case Method::EmbeddedFd:
      style.color = "#CC79A7", style.pointType = 11;  // filled triangle down
      break;
    case Method::Christoffel:
      style.color = "#0072B2", style.pointType = 6;  // open circle
      break;
    case Method::Embedded:
      style.color = "#009E73", style.pointType = 4;  // open square
      break;
    case Method::Ambient:
      style.color = "#000000", style.pointType = 12;  // open diamond
      break;
  }
  switch (integrator) {
    case Integrator::Rk4:
      style.dashType = 3, style.lineWidth = 1.5;
      break;
    case Integrator::Dopri5:
      style.dashType = 2, style.lineWidth = 1.5;
      break;
    case Integrator::Rkf78:
      style.dashType = 1, style.lineWidth = 2.5;
      break;
    case Integrator::BulirschStoer:
      style.dashType = 4, style.lineWidth = 1.5;
      break;
  }
  return style;
}

namespace {

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

// Powers of ten around [low, high] (positive values), for axes trimmed to the data.
std::pair<double, double> decadesAround(double low, double high) {
  return {std::pow(10.0, std::floor(std::log10(low))), std::pow(10.0, std::ceil(std::log10(high)))};
}

// The plot commands of one panel: a line per series, then a "failed" entry per method that failed there
// (crosses in the method's colour on the band above the rule).
std::string panelPlot(const ChartSpec& spec, const std::vector<const Series*>& series, const std::string& tag,
                      std::string& datablocks) {
  std::string plot = "plot ";
  std::vector<std::pair<Method, std::vector<std::string>>> failed;  // per method, first-appearance order
  for (size_t i = 0; i < series.size(); ++i) {
    std::vector<std::string> lines;
    for (const auto* p : *series[i]) {
      const Measurement& m = p->measurement;
      const std::string x = gnuplotNumber(spec.x.value(m));
      if (!m.failed()) {
        lines.push_back(x + " " + gnuplotNumber(spec.y.value(m)));
        continue;
      }
      auto it = std::find_if(failed.begin(), failed.end(), [&](const auto& f) { return f.first == p->method; });
      if (it == failed.end()) it = failed.insert(failed.end(), {p->method, {}});
      it->second.push_back(x + " " + formatNumber(kFailedBand));
    }
    if (lines.empty()) continue;  // every point failed: its crosses below stand for it, no empty legend entry
    const std::string block = tag + "s" + std::to_string(i);
    datablocks += gnuplotDatablock(block, lines);
    const auto& first = *series[i]->front();
    const SeriesStyle style = workPrecisionStyle(first.method, first.integrator);
    plot += "$" + block + " using 1:2 with linespoints lc rgb '" + style.color + "' pt " +
            std::to_string(style.pointType) + " dt " + std::to_string(style.dashType) + " lw " +
            formatNumber(style.lineWidth) + " title " +
            gnuplotQuote(nameOf(first.method) + " " + nameOf(first.integrator)) + ", ";
  }
  for (size_t k = 0; k < failed.size(); ++k) {
    const std::string block = tag + "f" + std::to_string(k);
    datablocks += gnuplotDatablock(block, failed[k].second);
    plot += "$" + block + " using 1:2 with points pt 2 ps 1.8 lw 2 lc rgb '" +
            workPrecisionStyle(failed[k].first, Integrator::Rkf78).color + "' title " +
            gnuplotQuote("failed: " + nameOf(failed[k].first)) + ", ";
  }
  if (plot == "plot ") return "plot NaN notitle\n";  // nothing at all to draw (no measurement in this panel)
  plot.resize(plot.size() - 2);
  return plot + "\n";
}

// One chart: a single panel, or with more than kMaxSeriesPerPanel series one panel per integrator on shared
// axes. Both axes are trimmed to whole decades around the data; failures sit on a band above the rule at 10,
// named on the y axis.
std::string chartScript(const std::string& title, const ChartSpec& spec, const std::vector<Series>& series,
                        const std::string& pngPath) {
  std::vector<std::vector<const Series*>> panels;
  std::vector<std::string> panelTitles;
  if (series.size() <= kMaxSeriesPerPanel) {
    panels.emplace_back();
    for (const auto& s : series) panels.back().push_back(&s);
    panelTitles.push_back("");
  } else {
    for (const auto& integrator : kIntegrators) {
      std::vector<const Series*> chosen;
      for (const auto& s : series)
        if (s.front()->integrator == integrator.kind) chosen.push_back(&s);
      if (chosen.empty()) continue;
      panels.push_back(chosen);
      panelTitles.push_back(std::string(integrator.name));
    }
  }
  double xLow = INFINITY, xHigh = 0, yLow = INFINITY;
  for (const auto& s : series)
    for (const auto* p : s) {
      const double x = spec.x.value(p->measurement);
      if (x > 0) xLow = std::min(xLow, x), xHigh = std::max(xHigh, x);
      if (!p->measurement.failed()) yLow = std::min(yLow, spec.y.value(p->measurement));
    }
  if (!(xHigh > 0)) xLow = 1, xHigh = 10;
  const auto [xFrom, xTo] = decadesAround(xLow, xHigh * 1.0001);
  const double yFrom = std::isfinite(yLow) ? std::min(decadesAround(yLow, yLow).first, 1e-2) : 1e-2;

  const int columns = panels.size() > 1 ? 2 : 1, rows = static_cast<int>((panels.size() + 1) / 2);
  std::string script = gnuplotPngPreamble(pngPath, panels.size() > 1 ? 1600 : 1100, panels.size() > 1 ? 460 * rows + 60 : 720);
  std::string datablocks, body;
  const std::string heading = title + ": " + spec.title;
  if (panels.size() > 1)
    body += "set multiplot layout " + std::to_string(rows) + "," + std::to_string(columns) + " title " +
            gnuplotQuote(heading + " (one panel per integrator)") + " noenhanced\n";
  else
    body += "set title " + gnuplotQuote(heading) + " noenhanced\n";
  body +=
      "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset grid xtics ytics lc rgb '#dddddd'\n";
  body += "set xlabel " + gnuplotQuote(spec.x.label) + "\nset ylabel " + gnuplotQuote(spec.y.label) + "\n";
  // The y axis ends just above the failure band; its labels are the decades up to 1 (at most eight of them) and
  // 'failed' at the band, so no decade label crowds it.
  body += "set xrange [" + formatNumber(xFrom) + ":" + formatNumber(xTo) + "]\nset yrange [" + formatNumber(yFrom) +
          ":" + formatNumber(2 * kFailedBand) + "]\n";
  const int lowestDecade = static_cast<int>(std::lround(std::log10(yFrom)));
  const int stride = std::max(1, (-lowestDecade + 7) / 8);
  std::string tics = "set ytics (";
  for (int e = 0; e >= lowestDecade; e -= stride) tics += "'10^{" + std::to_string(e) + "}' 1e" + std::to_string(e) + ", ";
  body += tics + "'failed' " + formatNumber(kFailedBand) + ")\nset key outside right top noenhanced\n";
  body += "set arrow from graph 0, first 10 to graph 1, first 10 nohead lc rgb '#bbbbbb' dt 3\n";
  for (size_t k = 0; k < panels.size(); ++k) {
    if (panels.size() > 1) body += "set title " + gnuplotQuote(panelTitles[k]) + " noenhanced\n";
    body += panelPlot(spec, panels[k], "p" + std::to_string(k), datablocks);
  }
  if (panels.size() > 1) body += "unset multiplot\n";
  return script + datablocks + body;
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

// `linkage geometry SCENE.json`: the shape of the scene's configuration sphere (4 rods, the scene's L and masses):
// exact Gaussian curvature, bending and stiffness on a grid or at given points, a summary with the Gauss-Bonnet
// integral and the extrema, and a sweep over L (docs/geometry.md).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "analysis/gnuplot.hpp"
#include "cli/chart_formats.hpp"
#include "cli/commands.hpp"
#include "cli/curvature_output.hpp"
#include "cli/distance_map_output.hpp"
#include "cli/exit_codes.hpp"
#include "cli/geometry_json.hpp"
#include "cli/progress.hpp"
#include "cli/scene_input.hpp"
#include "cli/summary.hpp"
#include "contracts/csv_format.hpp"
#include "geometry/curvature_grid.hpp"
#include "output/atomic_file.hpp"
#include "output/distinct_files.hpp"

namespace sl {

namespace {

constexpr int kMaxGrid = 4096;  // 16.7 million samples, about 20 s on 2 cores
constexpr int kMaxSweepCount = 1000;
constexpr int kDefaultMapGrid = 181;  // one degree of phi per row
constexpr int kDefaultDistanceGrid = 256;
constexpr int kMaxDistanceGrid = 1024;  // the fan and the raster grow with N: about a minute at 1024

struct GeometryArguments {
  std::vector<std::string> overrides;  // --set KEY=VALUE
  std::string scene;
  int grid = 0;
  std::string points;
  bool summary = false;
  std::string sweep;  // A:B:N
  std::string csv;    // empty: stdout
  std::string chart;  // sweep chart PNG
  std::string maps;   // folder for PNG maps of K, bending, stiffness
  bool quiet = false;
  std::string chartFormats;
  std::string distanceFrom;  // a configuration, or "start"
  bool json = false;         // with --distance-from
  std::string holonomy;      // LOOP: JSON text or file
  std::string sectional;     // POINTS: JSON text or file
};

const char* kSampleColumns = "phi,t,K,bending,stiffness_max,stiffness_min,stiffness_angle";

std::string sampleRow(const CurvatureSample& s) {
  std::string row;
  for (double v : {s.phi, s.t, s.gaussianCurvature, s.bending, s.stiffnessMax, s.stiffnessMin, s.stiffnessAngle}) {
    if (!row.empty()) row += ',';
    appendCsvNumber(row, v);
  }
  return row;
}

std::string samplesCsv(const std::vector<CurvatureSample>& samples) {
  std::string text = std::string(kSampleColumns) + "\n";
  for (const CurvatureSample& s : samples) text += sampleRow(s) + "\n";
  return text;
}

// Rows "phi,t" after a header line; names the file, line and field of the first problem.
std::vector<Eigen::Vector2d> readPoints(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw CommandExit(kExitBadInput, file + ": cannot open for reading");
  std::vector<Eigen::Vector2d> points;
  std::string line;
  if (!std::getline(in, line) || line.rfind("phi,t", 0) != 0)
    throw CommandExit(kExitBadInput, file + ":1: expected the header 'phi,t'");
  for (long number = 2; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::istringstream fields(line);
    std::string phi, t;
    std::getline(fields, phi, ',');
    std::getline(fields, t, ',');
    try {
      std::size_t usedPhi = 0, usedT = 0;
      const Eigen::Vector2d p(std::stod(phi, &usedPhi), std::stod(t, &usedT));
      if (usedPhi != phi.size() || usedT != t.size() || !p.allFinite()) throw std::invalid_argument("");
      points.push_back(p);
    } catch (const std::exception&) {
      throw CommandExit(kExitBadInput, file + ":" + std::to_string(number) +
                                           ": expected two finite numbers phi,t, got '" + line + "'");
    }
  }
  return points;
}

void writeOrPrint(const std::string& file, const std::string& text) {
  if (file.empty()) {
    std::cout << text << std::flush;
    if (!std::cout) throw CommandExit(kExitFailure, "linkage geometry: cannot write to standard output");
  } else {
    writeFileAtomically(file, text);
  }
}

// The grid's CSV in blocks of rows, each computed, formatted and written before the next: memory holds one
// block whatever N (a 4096 x 4096 grid held every sample and the whole text, over 4 GB). The same bytes as
// samplesCsv of the whole grid: each sample depends on its (phi, t) alone.
void writeGridCsv(const std::string& file, const ConfigurationSurface& surface, const ChartGrid& grid,
                  Progress& progress) {
  std::optional<AtomicFileWriter> writer;
  if (!file.empty()) writer.emplace(file);
  auto emit = [&](const std::string& text) {
    if (writer) {
      writer->write(text);
    } else if (!(std::cout << text)) {
      throw CommandExit(kExitFailure, "linkage geometry: cannot write to standard output");
    }
  };
  emit(std::string(kSampleColumns) + "\n");
  // At most 16 rows held at once, and at least 20 blocks, so progress has a line at every tenth.
  const std::size_t rowsPerBlock = std::clamp<std::size_t>(grid.phis.size() / 20, 1, 16);
  for (std::size_t first = 0; first < grid.phis.size(); first += rowsPerBlock) {
    const std::vector<double> phis(grid.phis.begin() + static_cast<std::ptrdiff_t>(first),
                                   grid.phis.begin() +
                                       static_cast<std::ptrdiff_t>(std::min(grid.phis.size(), first + rowsPerBlock)));
    std::string text;
    for (const CurvatureSample& sample : curvatureGrid(surface, phis, grid.ts)) text += sampleRow(sample) + "\n";
    emit(text);
    progress.update(long(first + phis.size()));
  }
  if (writer) {
    writer->commit();
  } else if (!(std::cout << std::flush)) {
    throw CommandExit(kExitFailure, "linkage geometry: cannot write to standard output");
  }
}

struct SweepRange {
  double first = 0, last = 0;
  int count = 0;
};

SweepRange parseSweep(const std::string& text, const Chain& chain) {
  const std::string expected = "expected --sweep-L A:B:N with " + std::to_string(chain.rods - 2) + " < A <= B < " +
                               std::to_string(chain.rods) + " and N from 1 to " + std::to_string(kMaxSweepCount);
  std::istringstream in(text);
  std::string a, b, n;
  std::getline(in, a, ':');
  std::getline(in, b, ':');
  std::getline(in, n);
  SweepRange range;
  try {
    std::size_t ua = 0, ub = 0, un = 0;
    range.first = std::stod(a, &ua);
    range.last = std::stod(b, &ub);
    range.count = std::stoi(n, &un);
    if (ua != a.size() || ub != b.size() || un != n.size()) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw CommandExit(kExitBadInput, "--sweep-L: found '" + text + "'; " + expected);
  }
  const double lo = chain.rods - 2, hi = chain.rods;
  if (!(range.first > lo && range.last < hi && range.first <= range.last) || range.count < 1 ||
      range.count > kMaxSweepCount || (range.count == 1 && range.first != range.last))
    throw CommandExit(kExitBadInput, "--sweep-L: found '" + text + "'; " + expected);
  return range;
}

std::string sweepCsv(const std::vector<CurvatureSummary>& sweep) {
  std::string text = "L,area,total_curvature,K_min,K_min_phi,K_min_t,K_max,K_max_phi,K_max_t,bending_max\n";
  for (const CurvatureSummary& s : sweep) {
    std::string row;
    for (double v : {s.baseLength, s.area, s.totalCurvature, s.curvatureMin.value, s.curvatureMin.phi, s.curvatureMin.t,
                     s.curvatureMax.value, s.curvatureMax.phi, s.curvatureMax.t, s.bendingMax.value}) {
      if (!row.empty()) row += ',';
      appendCsvNumber(row, v);
    }
    text += row + "\n";
  }
  return text;
}

// min K and max K (left axis, symmetric log-free linear) and the area (right axis) against L; the L where
// min K crosses zero, if it does in the range, marked.
void renderSweepChart(const std::vector<CurvatureSummary>& sweep, const std::string& png) {
  std::vector<std::string> lines;
  for (const CurvatureSummary& s : sweep)
    lines.push_back(shortest(s.baseLength) + " " + shortest(s.curvatureMin.value) + " " +
                    shortest(s.curvatureMax.value) + " " + shortest(s.area));
  std::string script = gnuplotPngPreamble(png, 1200, 700) + gnuplotDatablock("sweep", lines);
  script +=
      "set title 'Curvature of the configuration sphere against L' noenhanced\n"
      "set xlabel 'L (distance between the pins)'\nset ylabel 'Gaussian curvature K'\n"
      "set y2label 'area'\nset ytics nomirror\nset y2tics\nset grid\nset key top center horizontal\n"
      "set logscale y2\nset xzeroaxis lt -1\n";
  for (std::size_t i = 1; i < sweep.size(); ++i) {
    const double a = sweep[i - 1].curvatureMin.value, b = sweep[i].curvatureMin.value;
    if (a < 0 && b >= 0) {
      const double l = sweep[i - 1].baseLength + (sweep[i].baseLength - sweep[i - 1].baseLength) * (-a) / (b - a);
      script += "set arrow from " + shortest(l) + ", graph 0 to " + shortest(l) +
                ", graph 1 nohead dt 2 lc rgb '#555555'\n" + "set label " +
                gnuplotQuote("K > 0 everywhere for L > " + shortest(std::round(l * 1000) / 1000)) + " at " +
                shortest(l) + ", graph 0.93 offset 1,0\n";
    }
  }
  script +=
      "plot $sweep using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb '#0072b2' title 'min K', "
      "$sweep using 1:3 with linespoints lw 2 pt 5 ps 0.6 lc rgb '#d55e00' title 'max K', "
      "$sweep using 1:4 axes x1y2 with lines lw 2 dt 3 lc rgb '#009e73' title 'area (right axis)'\n";
  renderGnuplotChart(script, png);
}

// An equirectangular map (t across, phi up) of one column of a grid, with its colour bar. K gets a diverging
// palette with white at zero and each sign stretched over its own range, so small negative regions stay visible
// beside large positive ones (the bar gives the values); the others a sequential, colour-blind-safe palette.
void renderMap(const ChartGrid& grid, const std::vector<CurvatureSample>& samples, int column, const std::string& title,
               const std::string& png) {
  std::vector<std::string> lines;
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t i = 0; i < grid.phis.size(); ++i) {
    for (std::size_t j = 0; j < grid.ts.size(); ++j) {
      const CurvatureSample& s = samples[i * grid.ts.size() + j];
      const double v = column == 0 ? s.gaussianCurvature : column == 1 ? s.bending : s.stiffnessMax;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      lines.push_back(shortest(grid.ts[j]) + " " + shortest(grid.phis[i]) + " " + shortest(v));
    }
    lines.emplace_back();  // a blank line ends a scan line for gnuplot's image style
  }
  std::string palette;
  if (column == 0 && lo < 0 && hi > 0) {
    palette = "set palette defined (" + shortest(lo) + " '#2166ac', " + shortest(lo / 2) + " '#92c5de', 0 '#f7f7f7', " +
              shortest(hi / 2) + " '#f4a582', " + shortest(hi) + " '#b2182b')\nset cbrange [" + shortest(lo) + ":" +
              shortest(hi) + "]\nset cbtics add ('0' 0)\n";
  } else {  // viridis: sequential and colour-blind safe
    palette = "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')\n";
  }
  std::string script = gnuplotPngPreamble(png, 1200, 640) + gnuplotDatablock("map", lines);
  script += "set title " + gnuplotQuote(title) +
            " noenhanced\nset xlabel 't'\nset ylabel 'phi'\nset xrange [-pi:pi]\nset yrange [-pi/2:pi/2]\n"
            "set xtics ('-pi' -pi, '-pi/2' -pi/2, '0' 0, 'pi/2' pi/2, 'pi' pi)\n"
            "set ytics ('-pi/2' -pi/2, '-pi/4' -pi/4, '0' 0, 'pi/4' pi/4, 'pi/2' pi/2)\n" +
            palette + "plot $map using 1:2:3 with image notitle\n";
  renderGnuplotChart(script, png);
}

void runGeometry(const GeometryArguments& args) {
  const CommandSummary summary("geometry", args.quiet);
  const bool distance = !args.distanceFrom.empty();
  const int modes = (!distance && (args.grid > 0 || !args.maps.empty())) + (!distance && !args.points.empty()) +
                    args.summary + !args.sweep.empty() + distance + !args.holonomy.empty() + !args.sectional.empty();
  if (modes != 1)
    throw CommandExit(
        kExitBadInput,
        "linkage geometry: expected exactly one of --grid N (with --csv and/or --maps DIR), "
        "--points FILE, --summary, --sweep-L A:B:N, --distance-from POINT (with --grid, --csv, --maps, --points), "
        "--holonomy LOOP, --sectional POINTS");
  if (args.json && !distance) throw CommandExit(kExitBadInput, "--json: goes with --distance-from POINT");
  if (!args.chart.empty() && args.sweep.empty())
    throw CommandExit(kExitBadInput, "--chart: draws the L sweep; expected --sweep-L A:B:N with it");
  const std::vector<std::string> formats = chartFormats(args.chartFormats);
  // Every file written, each chart with its script and other formats: the CSV and the chart where they are named,
  // the maps in a folder this command creates.
  std::vector<NamedFile> outputs = {{"--csv", args.csv}};
  if (!args.chart.empty())
    for (const std::string& file : chartFiles(args.chart, formats)) outputs.push_back({"--chart", file});
  requireOutputsBeforeWork("geometry", {{"the scene", args.scene}, {"--points", args.points}}, outputs);
  std::vector<std::string> maps;
  if (!args.maps.empty() && distance) maps.push_back("/distance.png");
  if (!args.maps.empty() && !distance) maps = {"/curvature.png", "/bending.png", "/stiffness.png"};
  for (const std::string& map : maps)
    for (const std::string& file : chartFiles(args.maps + map, formats)) outputs.push_back({"--maps", file});
  try {
    requireDistinctFiles({{"the scene", args.scene}, {"--points", args.points}}, outputs);
  } catch (const std::invalid_argument& error) {
    throw CommandExit(kExitBadInput, "linkage geometry: " + std::string(error.what()));
  }
  // Charts and maps are drawn after the CSV is written: without gnuplot, nothing is written at all.
  if ((!args.chart.empty() || !args.maps.empty()) && !gnuplotAvailable())
    throw std::runtime_error("--chart and --maps need gnuplot with pngcairo: apt-get install gnuplot-nox");
  const Scene scene = loadSceneForCommand(args.scene, args.overrides);
  const std::string of = " of \"" + scene.name + "\" (L = " + shortest(scene.chain.baseLength) + ")" +
                         (args.csv.empty() ? "" : " -> " + args.csv);
  if (!args.holonomy.empty() || !args.sectional.empty()) {
    const CurvatureRequest request{args.holonomy.empty() ? args.sectional : args.holonomy, args.csv, args.quiet};
    summary.print((args.holonomy.empty() ? runSectional(scene, request) : runHolonomy(scene, request)) + of);
    return;
  }
  if (scene.chain.rods != 4)
    throw CommandExit(kExitBadInput, args.scene + ": linkage.rods: found " + std::to_string(scene.chain.rods) +
                                         "; the curvature of the configuration space is computed for 4 rods "
                                         "(a surface, S^2) only");
  if (distance && args.grid > 0 && (args.grid < 8 || args.grid > kMaxDistanceGrid))
    throw CommandExit(kExitBadInput, "--grid: found " + std::to_string(args.grid) +
                                         "; with --distance-from expected 8 to " + std::to_string(kMaxDistanceGrid));
  if (distance) {
    DistanceMapRequest request{args.distanceFrom, args.grid > 0 ? args.grid : kDefaultDistanceGrid,
                               args.csv,          args.maps,
                               args.json,         args.quiet,
                               formats,           {}};
    if (!args.points.empty()) request.points = readPoints(args.points);
    summary.print(runDistanceMap(scene, request) + " of \"" + scene.name + "\" (L = " +
                  shortest(scene.chain.baseLength) + ")" + (args.csv.empty() ? "" : " -> " + args.csv));
    return;
  }
  const ConfigurationSurface surface(scene.chain);
  std::string done;
  if (args.grid > 0 || !args.maps.empty()) {
    const int n = args.grid > 0 ? args.grid : kDefaultMapGrid;
    const ChartGrid grid = uniformChartGrid(n, n);
    if (!args.csv.empty() || args.maps.empty()) {
      Progress progress(long(grid.phis.size()), args.quiet, "geometry", "grid row");
      writeGridCsv(args.csv, surface, grid, progress);
    }
    if (!args.maps.empty()) {
      const std::vector<CurvatureSample> samples = curvatureGrid(surface, grid.phis, grid.ts);
      std::filesystem::create_directories(args.maps);
      const std::string where = " (L = " + shortest(scene.chain.baseLength) + ", \"" + scene.name + "\")";
      renderMap(grid, samples, 0, "Gaussian curvature K" + where, args.maps + "/curvature.png");
      renderMap(grid, samples, 1, "bending |II|^2" + where, args.maps + "/bending.png");
      renderMap(grid, samples, 2, "largest directional stiffness" + where, args.maps + "/stiffness.png");
      writeChartFormats({args.maps + "/curvature.png", args.maps + "/bending.png", args.maps + "/stiffness.png"},
                        formats);
    }
    done =
        std::to_string(n) + " x " + std::to_string(n) + " grid" + (args.maps.empty() ? "" : ", maps in " + args.maps);
  } else if (!args.points.empty()) {
    const std::vector<Eigen::Vector2d> points = readPoints(args.points);
    writeOrPrint(args.csv, samplesCsv(curvatureSamples(surface, points)));
    done = std::to_string(points.size()) + " points";
  } else if (args.summary) {
    writeOrPrint(args.csv, summaryJson(curvatureSummary(scene.chain)).dump(2) + "\n");
    done = "summary";
  } else {
    const SweepRange range = parseSweep(args.sweep, scene.chain);
    const std::vector<CurvatureSummary> sweep = curvatureSweep(scene.chain, range.first, range.last, range.count);
    writeOrPrint(args.csv, sweepCsv(sweep));
    if (!args.chart.empty()) {
      renderSweepChart(sweep, args.chart);
      writeChartFormats({args.chart}, formats);
    }
    done = "L sweep of " + std::to_string(range.count) + " values";
  }
  summary.print(done + of);
}

}  // namespace

void addGeometryCommand(CLI::App& app) {
  auto args = std::make_shared<GeometryArguments>();
  CLI::App* command = app.add_subcommand(
      "geometry", "Curvature, bending and stiffness of the scene's configuration sphere (4 rods), exact");
  command->add_option("scene", args->scene, "scene file (JSON, see scenes/README.md; - reads standard input): its linkage is used")->required();
  addSceneOverrideOption(*command, args->overrides);
  command->add_option("--grid", args->grid, "N x N chart grid (phi from pole to pole, t periodic): CSV")
      ->check(CLI::Range(2, kMaxGrid));
  command->add_option("--points", args->points,
                      "CSV file of chart points (header phi,t): the same columns there; with --distance-from, the "
                      "exact distance at those points (the shortest motion, seeded from the map) instead of the grid");
  command->add_flag("--summary", args->summary,
                    "JSON: area, total curvature (4 pi by Gauss-Bonnet), min and max K, max bending");
  command->add_option("--sweep-L", args->sweep, "A:B:N: the summary for N values of L from A to B, as CSV");
  command->add_option("--csv", args->csv, "write here instead of standard output (written whole or not at all)");
  command->add_option("--chart", args->chart, "with --sweep-L: a PNG chart of min K, max K and area against L");
  command->add_option("--maps", args->maps, "folder for PNG maps of K, bending and stiffness over (phi, t)");
  command->add_option("--distance-from", args->distanceFrom,
                      "POINT: the distance map from a configuration ({\"coords\": [...]}, {\"hinges\": ...}, a file, "
                      "or start), with its conjugate and cut loci and the injectivity radius (--grid, default 256)");
  command->add_flag("--json", args->json, "with --distance-from: the radii and the loci as JSON on standard output");
  command->add_option("--holonomy", args->holonomy,
                      "LOOP: how a vector parallel transported round a loop comes back turned (4 rods), checked "
                      "against Gauss-Bonnet: {\"corners\": [3 or more configurations]} joined by their shortest "
                      "motions, {\"latitude\": phi} or {\"periodic\": k} (closed geodesic k of linkage periodic's "
                      "list: back unturned, 2 pi inside a simple one); JSON text or a file");
  command->add_option("--sectional", args->sectional,
                      "POINTS: the range of the sectional curvature over the tangent planes at each configuration "
                      "(5 rods and more), and of given planes: [{\"coords\": [...], \"planes\": [[X, Y]]}, ...]; JSON "
                      "text or a file");
  command->add_flag("--quiet", args->quiet, "no summary line");
  addChartFormatsOption(*command, args->chartFormats);
  command->footer(
      "Columns of --grid and --points: phi,t,K,bending,stiffness_max,stiffness_min,stiffness_angle\n"
      "Charts (--chart, --maps) get their gnuplot script beside them (.gp); --chart-formats svg,pdf adds .svg, .pdf.\n"
      "Examples:\n  linkage geometry scenes/default.json --summary\n"
      "  linkage geometry scenes/default.json --grid 256 --csv renders/curvature.csv\n"
      "  linkage geometry scenes/default.json --sweep-L 2.1:3.9:37 --csv renders/sweep.csv --chart renders/sweep.png\n"
      "  linkage geometry scenes/default.json --distance-from start --csv renders/distance.csv --maps "
      "renders/distance\n"
      "  linkage geometry scenes/default.json --distance-from start --points points.csv --grid 64\n"
      "  linkage geometry scenes/default.json --holonomy '{\"latitude\": 0.5}'\n"
      "  linkage geometry scenes/default.json --holonomy '{\"periodic\": 0}'\n"
      "  linkage geometry scenes/holonomy.json --holonomy '{\"corners\": [{\"coords\": [0.2, 0]}, {\"coords\": [0.3, "
      "1.4]}, "
      "{\"coords\": [1.2, 0.6]}]}'\n"
      "  linkage geometry scenes/five-rods.json --sectional '[{\"coords\": [0.3, -0.2, 0.5]}]'\n"
      "Columns of --distance-from: phi,t,distance,direction (angle of the shortest geodesic at the point).\n"
      "--holonomy and --sectional write JSON (to --csv FILE when given); each result carries its own checks and a "
      "failed check ends the command with exit 3.");
  command->callback([args] { runGeometry(*args); });
}

}  // namespace sl

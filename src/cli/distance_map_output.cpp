// `linkage geometry SCENE.json --distance-from POINT`: the distance from one configuration over the whole
// configuration sphere (4 rods), its conjugate and cut loci and the injectivity radius (src/inverse/distance_map.hpp),
// as CSV, an equirectangular PNG map and a JSON summary.

#include "cli/distance_map_output.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "analysis/gnuplot.hpp"
#include "cli/chart_formats.hpp"
#include "cli/configuration_point.hpp"
#include "cli/exit_codes.hpp"
#include "cli/progress.hpp"
#include "cli/scene_input.hpp"
#include "cli/self_check_words.hpp"
#include "contracts/csv_format.hpp"
#include "inverse/distance_map.hpp"
#include "linkage/chart.hpp"
#include "output/atomic_file.hpp"

namespace sl {

namespace {

Eigen::Vector2d chartOf(const Eigen::Vector3d& x) {
  return {std::asin(std::clamp(x.z(), -1.0, 1.0)), std::atan2(x.y(), x.x())};
}

std::string gridCsv(const DistanceMap& map) {
  std::string text = "phi,t,distance,direction\n";
  for (std::size_t i = 0; i < map.phis.size(); ++i)
    for (std::size_t j = 0; j < map.ts.size(); ++j) {
      const std::size_t n = i * map.ts.size() + j;
      std::string row;
      for (double v : {map.phis[i], map.ts[j], map.distance[n], map.direction[n]}) {
        if (!row.empty()) row += ',';
        appendCsvNumber(row, v);
      }
      text += row + "\n";
    }
  return text;
}

// Polylines in (t, phi), broken where they jump (across the seam t = +-pi, or between far directions).
std::vector<std::string> conjugateLines(const DistanceMap& map) {
  std::vector<std::string> lines;
  const auto& locus = map.conjugateLocus;
  for (std::size_t k = 0; k <= locus.size() && !locus.empty(); ++k) {
    const ConjugatePoint& c = locus[k % locus.size()];
    const Eigen::Vector2d p = chartOf(c.x);
    if (k > 0) {
      const ConjugatePoint& previous = locus[k - 1];
      const Eigen::Vector2d q = chartOf(previous.x);
      if (std::abs(p(1) - q(1)) > M_PI || (c.x - previous.x).norm() > 0.2) lines.emplace_back();
    }
    lines.push_back(shortest(p(1)) + " " + shortest(p(0)));
  }
  return lines;
}

void renderDistanceMap(const DistanceMap& map, const std::string& title, const std::string& png) {
  std::vector<std::string> grid;
  for (std::size_t i = 0; i < map.phis.size(); ++i) {
    for (std::size_t j = 0; j < map.ts.size(); ++j)
      grid.push_back(shortest(map.ts[j]) + " " + shortest(map.phis[i]) + " " +
                     shortest(map.distance[i * map.ts.size() + j]));
    grid.emplace_back();
  }
  std::vector<std::string> cut;
  for (const CutEdge& e : map.cutLocus) {
    const Eigen::Vector2d p = chartOf(e.x);
    cut.push_back(shortest(p(1)) + " " + shortest(p(0)));
  }
  if (cut.empty()) cut.push_back("NaN NaN");
  std::vector<std::string> conjugate = conjugateLines(map);
  if (conjugate.empty()) conjugate.push_back("NaN NaN");
  const Eigen::Vector2d centre = chartOf(map.point);
  std::string script = gnuplotPngPreamble(png, 1200, 640) + gnuplotDatablock("map", grid) +
                       gnuplotDatablock("cut", cut) + gnuplotDatablock("conjugate", conjugate) +
                       gnuplotDatablock("point", {shortest(centre(1)) + " " + shortest(centre(0))});
  script += "set title " + gnuplotQuote(title) +
            " noenhanced\nset xlabel 't'\nset ylabel 'phi'\nset xrange [-pi:pi]\nset yrange [-pi/2:pi/2]\n"
            "set xtics ('-pi' -pi, '-pi/2' -pi/2, '0' 0, 'pi/2' pi/2, 'pi' pi)\n"
            "set ytics ('-pi/2' -pi/2, '-pi/4' -pi/4, '0' 0, 'pi/4' pi/4, 'pi/2' pi/2)\n"
            "set cblabel 'distance (kinetic length)'\nset key outside bottom center horizontal\n"
            "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')\n"
            "plot $map using 1:2:3 with image notitle, "
            "$conjugate using 1:2 with lines lw 2 lc rgb '#ff7f0e' title 'conjugate locus', "
            "$cut using 1:2 with points pt 7 ps 0.35 lc rgb '#ffffff' title 'cut locus', "
            "$point using 1:2 with points pt 3 ps 2.5 lw 3 lc rgb '#e31a1c' title 'the point'\n";
  renderGnuplotChart(script, png);
}

// The distance at each given point, exact, in the grid CSV's columns; the points no motion was found to are named.
std::string pointsCsv(const Chain& chain, const ConstrainedModel& model, const DistanceMap& map,
                      const Eigen::VectorXd& from, const std::vector<Eigen::Vector2d>& points,
                      std::vector<std::string>& missed) {
  std::string text = "phi,t,distance,direction\n";
  for (const Eigen::Vector2d& p : points) {
    const Eigen::Vector3d x(std::cos(p(0)) * std::cos(p(1)), std::cos(p(0)) * std::sin(p(1)), std::sin(p(0)));
    const std::optional<Arrival> arrival =
        shortestArrival(model, map, from, ConstrainedModel::stack(hingePositionsAt(chain, x)), x);
    if (!arrival) missed.push_back("(" + shortest(p(0)) + ", " + shortest(p(1)) + ")");
    std::string row;
    for (double v :
         {p(0), p(1), arrival ? arrival->distance : std::nan(""), arrival ? arrival->direction : std::nan("")}) {
      if (!row.empty()) row += ',';
      appendCsvNumber(row, v);
    }
    text += row + "\n";
  }
  return text;
}

nlohmann::json chartPoint(const Eigen::Vector3d& x, double distance) {
  const Eigen::Vector2d p = chartOf(x);
  return nlohmann::json::array({p(0), p(1), distance});
}

}  // namespace

std::string runDistanceMap(const Scene& scene, const DistanceMapRequest& request) {
  const Chain& chain = scene.chain;
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  Eigen::VectorXd point;
  if (request.point == "start") {
    const InitialState start = runStarts(scene).at(0);
    point = ConstrainedModel::stack(start.byHinges() ? start.hinges : hingePositionsAt(chain, start.spherePoint));
  } else {
    point = readConfigurationPoint(chain, model, request.point, "--distance-from");
  }
  DistanceMapOptions options;
  options.grid = request.grid;
  // The fan ends with about 3 geodesics per grid column; the first fan is told exactly.
  Progress progress(4L * request.grid, request.quiet, "geometry", "geodesic");
  options.progress = [&](int done, int) { progress.update(std::min<long>(done, 4L * request.grid - 1)); };
  const DistanceMap map = distanceMap(
      model,
      [&chain](const Eigen::VectorXd& q) -> Eigen::Vector3d {
        return spherePointFromHinges(chain, ConstrainedModel::unstack(q));
      },
      point, options);
  progress.update(4L * request.grid);

  const Eigen::Vector2d centre = chartOf(map.point);
  std::vector<std::string> missed;  // --points no motion was found to
  if (!request.csv.empty() || (request.maps.empty() && !request.json)) {
    const std::string text =
        request.points.empty() ? gridCsv(map) : pointsCsv(chain, model, map, point, request.points, missed);
    if (request.csv.empty()) {
      if (!(std::cout << text << std::flush))
        throw CommandExit(kExitFailure, "linkage geometry: cannot write to standard output");
    } else {
      writeFileAtomically(request.csv, text);
    }
  }
  if (!request.maps.empty()) {
    std::filesystem::create_directories(request.maps);
    const std::string png = request.maps + "/distance.png";
    renderDistanceMap(map,
                      "distance from (phi, t) = (" + shortest(std::round(centre(0) * 1e4) / 1e4) + ", " +
                          shortest(std::round(centre(1) * 1e4) / 1e4) + "), L = " + shortest(chain.baseLength) +
                          ", \"" + scene.name + "\"; injectivity radius " +
                          shortest(std::round(map.injectivityRadius * 1e4) / 1e4),
                      png);
    writeChartFormats({png}, request.formats);
  }
  if (request.json) {
    nlohmann::json j;
    j["point"] = {{"phi", centre(0)}, {"t", centre(1)}};
    j["grid"] = request.grid;
    j["geodesics"] = map.geodesics;
    j["farthest"] = map.farthest;
    j["injectivity_radius"] = map.injectivityRadius;
    j["conjugate_radius"] = map.conjugateRadius;
    j["shortest_loop"] = map.shortestLoop > 0 ? nlohmann::json(map.shortestLoop) : nlohmann::json(nullptr);
    j["klingenberg"] = map.klingenberg();
    j["check"] = selfCheckName(selfCheck(map));
    nlohmann::json conjugate = nlohmann::json::array(), cut = nlohmann::json::array();
    for (const ConjugatePoint& c : map.conjugateLocus) conjugate.push_back(chartPoint(c.x, c.distance));
    for (const CutEdge& e : map.cutLocus) cut.push_back(chartPoint(e.x, e.distance));
    j["conjugate_locus"] = conjugate;  // [phi, t, distance] by direction
    j["cut_locus"] = cut;              // [phi, t, distance], unordered
    if (!(std::cout << j.dump(2) << "\n" << std::flush))
      throw CommandExit(kExitFailure, "linkage geometry: cannot write to standard output");
  }
  // The map is written whole either way; one whose two injectivity radii disagree is reported as failed.
  reportUnconfirmed("geometry", "distance map", {selfCheck(map)}, request.quiet);
  if (!missed.empty())
    throw CommandExit(kExitFailure, "linkage geometry: no motion found to " + std::to_string(missed.size()) +
                                        " of the --points (the first at (phi, t) = " + missed.front() +
                                        "); their rows are written with nan");
  const std::string atPoints =
      request.points.empty() ? "" : ", the distance at " + std::to_string(request.points.size()) + " points";
  return "distance map from (phi, t) = (" + shortest(std::round(centre(0) * 1e6) / 1e6) + ", " +
         shortest(std::round(centre(1) * 1e6) / 1e6) + "), " + std::to_string(request.grid) + " x " +
         std::to_string(request.grid) + " grid, " + std::to_string(map.geodesics) + " geodesics, injectivity radius " +
         shortest(std::round(map.injectivityRadius * 1e6) / 1e6) + " (Klingenberg: min(first conjugate " +
         shortest(std::round(map.conjugateRadius * 1e6) / 1e6) + ", half the shortest loop " +
         shortest(std::round(map.shortestLoop / 2 * 1e6) / 1e6) + "))" + atPoints;
}

}  // namespace sl

#include "cli/curvature_output.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "cli/configuration_json.hpp"
#include "cli/configuration_point.hpp"
#include "cli/exit_codes.hpp"
#include "cli/interrupt.hpp"
#include "cli/progress.hpp"
#include "cli/self_check_words.hpp"
#include "contracts/csv_format.hpp"
#include "geometry/sectional_curvature.hpp"
#include "inverse/constrained_model.hpp"
#include "inverse/holonomy.hpp"
#include "inverse/self_check.hpp"
#include "linkage/chain_constants.hpp"
#include "linkage/chart.hpp"
#include "linkage/sphere_coordinates.hpp"
#include "output/atomic_file.hpp"

namespace sl {

namespace {

void writeJson(const std::string& file, const nlohmann::ordered_json& j) {
  const std::string text = j.dump(2) + "\n";
  if (file.empty()) {
    std::cout << text << std::flush;
    if (!std::cout) throw CommandExit(kExitFailure, "linkage geometry: cannot write to standard output");
  } else {
    writeFileAtomically(file, text);
  }
}

double numberAt(const nlohmann::json& j, const std::string& where) {
  if (!j.is_number() || !std::isfinite(j.get<double>()))
    throw CommandExit(kExitBadInput, where + ": expected a finite number");
  return j.get<double>();
}

Eigen::VectorXd vectorAt(const nlohmann::json& j, Eigen::Index size, const std::string& where) {
  if (!j.is_array() || static_cast<Eigen::Index>(j.size()) != size)
    throw CommandExit(kExitBadInput, where + ": expected an array of " + std::to_string(size) + " numbers");
  Eigen::VectorXd v(size);
  for (Eigen::Index i = 0; i < size; ++i)
    v(i) = numberAt(j[static_cast<std::size_t>(i)], where + "[" + std::to_string(i) + "]");
  return v;
}

// Chart 0's coordinates of a configuration (stacked hinges), the form points are written back in.
Eigen::VectorXd chartZeroCoords(const Chain& chain, const Eigen::VectorXd& q) {
  return coordinatesFromHinges(chain, ConstrainedModel::unstack(q));
}

nlohmann::ordered_json holonomyJson(const Holonomy& h) {
  nlohmann::ordered_json j;
  j["holonomy"] = h.angle;
  j["enclosed_curvature"] = h.enclosedCurvature;
  if (h.angleExcess) {
    j["angle_excess"] = *h.angleExcess;
    j["interior_angles"] = h.interiorAngles;
    j["piece_lengths"] = h.pieceLengths;
  }
  j["length"] = h.length;
  nlohmann::ordered_json checks;
  checks["chart_route_holonomy"] = h.chartAngle;
  checks["routes"] = std::abs(h.routeDifference());
  checks["enclosed_curvature"] = std::abs(h.curvatureDifference());
  if (h.excessDifference()) checks["angle_excess"] = std::abs(*h.excessDifference());
  checks["chart_changes"] = h.chartChanges;
  checks["result"] = selfCheckName(selfCheck(h));
  j["checks"] = checks;
  return j;
}

}  // namespace

std::string runHolonomy(const Scene& scene, const CurvatureRequest& request) {
  const Chain& chain = scene.chain;
  if (chain.rods != 4)
    throw CommandExit(kExitBadInput, "--holonomy: the linkage has " + std::to_string(chain.rods) +
                                         " rods; holonomy is computed for 4 rods (a surface, S^2); for more rods see "
                                         "--sectional");
  std::string where;
  const nlohmann::json loop = readJsonArgument(request.input, "--holonomy", where);
  const int keys = int(loop.contains("corners")) + int(loop.contains("latitude")) + int(loop.contains("periodic"));
  if (!loop.is_object() || keys != 1 || loop.size() != 1)
    throw CommandExit(kExitBadInput, where +
                                         ": expected an object with one key, \"corners\" (a list of at least 3 "
                                         "configurations), \"latitude\" (phi of chart 0) or \"periodic\" (an index "
                                         "of linkage periodic's list)");
  Holonomy h;
  nlohmann::ordered_json out;
  out["L"] = chain.baseLength;
  std::string what;
  try {
    if (loop.contains("periodic")) {
      const nlohmann::json& index = loop["periodic"];
      if (!index.is_number_unsigned())
        throw CommandExit(kExitBadInput, where + ": periodic: found " + index.dump() +
                                             "; expected an index of linkage periodic's list (0, 1, ...)");
      const std::vector<ClosedGeodesic> found = closedGeodesicsOf(chain, 0, interruptRequested);
      const std::size_t k = index.get<std::size_t>();
      if (k >= found.size())
        throw CommandExit(kExitBadInput, where + ": periodic: found " + std::to_string(k) +
                                             "; linkage periodic lists " + std::to_string(found.size()) +
                                             " closed geodesics here (indices 0.." + std::to_string(found.size() - 1) +
                                             ")");
      h = closedGeodesicHolonomy(chain, found[k]);
      out["loop"] = {{"periodic", k}};
      what = "closed geodesic " + std::to_string(k) + (found[k].simple ? " (simple)" : "");
    } else if (loop.contains("latitude")) {
      const double phi = numberAt(loop["latitude"], where + ": latitude");
      if (!(std::abs(phi) < std::numbers::pi / 2))
        throw CommandExit(kExitBadInput,
                          where + ": latitude: found " + shortest(phi) + "; expected -pi/2 < phi < pi/2");
      h = latitudeHolonomy(chain, phi);
      out["loop"] = {{"latitude", phi}};
      what = "latitude phi = " + shortest(phi);
    } else {
      const nlohmann::json& list = loop["corners"];
      if (!list.is_array() || list.size() < 3)
        throw CommandExit(kExitBadInput, where + ": corners: expected a list of at least 3 configurations");
      const ConstrainedModel model = ConstrainedModel::fromChain(chain);
      std::vector<Eigen::VectorXd> corners;
      nlohmann::json written = nlohmann::json::array();
      for (std::size_t i = 0; i < list.size(); ++i) {
        const Eigen::VectorXd q =
            configurationFromJson(chain, model, list[i], where + ": corners[" + std::to_string(i) + "]");
        corners.push_back(spherePointFromHinges(chain, ConstrainedModel::unstack(q)));
        written.push_back({{"coords", vectorJson(chartZeroCoords(chain, q))}});
      }
      h = polygonHolonomy(chain, corners, interruptRequested);
      out["loop"] = {{"corners", written}};
      what = std::to_string(corners.size()) + "-corner loop";
    }
  } catch (const std::invalid_argument& error) {
    throw CommandExit(kExitBadInput, where + ": " + error.what());
  }
  const nlohmann::ordered_json result = holonomyJson(h);
  for (const auto& [key, value] : result.items()) out[key] = value;
  writeJson(request.output, out);
  const SelfCheck check = selfCheck(h);
  if (check != SelfCheck::confirmed)
    throw CommandExit(kExitFailure, "linkage geometry: the holonomy of the " + what + " is unconfirmed: " +
                                        selfCheckReason(check) + " (the JSON written lists its checks)");
  char figures[160];
  std::snprintf(figures, sizeof figures, "holonomy %.10g rad of a %s (routes agree to %.0e, Gauss-Bonnet to %.0e)",
                h.angle, what.c_str(), std::max(std::abs(h.routeDifference()), 1e-16),
                std::max({std::abs(h.curvatureDifference()), std::abs(h.excessDifference().value_or(0.0)), 1e-16}));
  return figures;
}

std::string runSectional(const Scene& scene, const CurvatureRequest& request) {
  const Chain& chain = scene.chain;
  if (chain.rods < 5 || chain.isSlack())
    throw CommandExit(kExitBadInput, "--sectional: the linkage has " + std::to_string(chain.rods) +
                                         " rods; sectional curvature is for 5 rods and more (for 4 rods every plane "
                                         "has the Gaussian curvature: --points, --grid)");
  std::string where;
  const nlohmann::json list = readJsonArgument(request.input, "--sectional", where);
  if (!list.is_array() || list.empty())
    throw CommandExit(kExitBadInput, where +
                                         ": expected a list of configurations ({\"coords\": [...]} or "
                                         "{\"hinges\": [...]}, each with optional \"planes\": [[X, Y], ...] of "
                                         "chart-0 rates)");
  const ChainConstants bound(chain);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  const Eigen::Index k = chain.sphereDimension();
  Progress progress(static_cast<long>(list.size()), request.quiet, "geometry", "point");
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  double worstCheck = 0;
  for (std::size_t i = 0; i < list.size(); ++i) {
    stopIfCancelled(interruptRequested);
    const std::string at = where + "[" + std::to_string(i) + "]";
    const Eigen::VectorXd q = configurationFromJson(chain, model, list[i], at);
    const Eigen::VectorXd coords = chartZeroCoords(chain, q);
    const Eigen::VectorXd x = spherePointFromHinges(chain, ConstrainedModel::unstack(q));
    const SectionalRange range = sectionalCurvatureRange(bound, x);
    auto planeJson = [&](const Eigen::VectorXd(&plane)[2]) {
      return nlohmann::json::array({vectorJson(coordinateRatesFromSphereVelocity(coords, plane[0])),
                                    vectorJson(coordinateRatesFromSphereVelocity(coords, plane[1]))});
    };
    // The extremes again by the intrinsic route: the point's own check.
    const double check =
        std::max(std::abs(sectionalCurvatureIntrinsic(bound, x, range.minimumPlane[0], range.minimumPlane[1]) -
                          range.minimum),
                 std::abs(sectionalCurvatureIntrinsic(bound, x, range.maximumPlane[0], range.maximumPlane[1]) -
                          range.maximum)) /
        std::max({1.0, std::abs(range.minimum), std::abs(range.maximum)});
    worstCheck = std::max(worstCheck, check);
    nlohmann::ordered_json point{{"coords", vectorJson(coords)},
                                 {"K_min", range.minimum},
                                 {"K_max", range.maximum},
                                 {"plane_min", planeJson(range.minimumPlane)},
                                 {"plane_max", planeJson(range.maximumPlane)},
                                 {"intrinsic_check", check}};
    if (list[i].contains("planes")) {
      const nlohmann::json& planes = list[i]["planes"];
      if (!planes.is_array()) throw CommandExit(kExitBadInput, at + ": planes: expected a list of [X, Y]");
      nlohmann::json curvatures = nlohmann::json::array();
      for (std::size_t p = 0; p < planes.size(); ++p) {
        const std::string pw = at + ": planes[" + std::to_string(p) + "]";
        if (!planes[p].is_array() || planes[p].size() != 2)
          throw CommandExit(kExitBadInput,
                            pw + ": expected [X, Y], two arrays of " + std::to_string(k) + " chart-0 rates");
        const Eigen::VectorXd X = sphereVelocityFromCoordinateRates(coords, vectorAt(planes[p][0], k, pw + "[0]"));
        const Eigen::VectorXd Y = sphereVelocityFromCoordinateRates(coords, vectorAt(planes[p][1], k, pw + "[1]"));
        try {
          curvatures.push_back({{"K", sectionalCurvature(bound, x, X, Y)},
                                {"K_intrinsic", sectionalCurvatureIntrinsic(bound, x, X, Y)}});
        } catch (const std::invalid_argument& error) {
          throw CommandExit(kExitBadInput, pw + ": " + error.what());
        }
      }
      point["planes"] = curvatures;
    }
    out.push_back(point);
    progress.update(static_cast<long>(i + 1));
  }
  writeJson(request.output, out);
  if (!(worstCheck <= kRouteAgreement))
    throw CommandExit(kExitFailure,
                      "linkage geometry: the sectional curvature is unconfirmed: its two routes differ "
                      "by " +
                          shortest(worstCheck) + " (relative) at the extremes, more than " + shortest(kRouteAgreement) +
                          " (the JSON written lists each point's check)");
  return "sectional curvature at " + std::to_string(list.size()) + " point" + (list.size() == 1 ? "" : "s") +
         " (routes agree to " + shortest(std::round(worstCheck * 1e16) / 1e16) + ")";
}

}  // namespace sl

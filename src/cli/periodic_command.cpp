// `linkage periodic SCENE.json`: the closed geodesics (periodic force-free motions) of the scene's linkage,
// 4 rods (the configuration sphere) or 3 (its circle), by shooting and by an independent route
// (src/inverse/periodic.hpp).

#include <complex>
#include <cstdio>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/summary.hpp"
#include "cli/configuration_json.hpp"
#include "cli/exit_codes.hpp"
#include "cli/interrupt.hpp"
#include "cli/number_options.hpp"
#include "cli/progress.hpp"
#include "cli/scene_input.hpp"
#include "cli/self_check_words.hpp"
#include "contracts/limits.hpp"
#include "inverse/periodic.hpp"
#include "linkage/chart.hpp"
#include "simulation/ambient_system.hpp"

namespace sl {

namespace {

struct PeriodicArguments {
  std::vector<std::string> overrides;
  std::string scene;
  double maxLength = 0;
  bool json = false;
  bool quiet = false;
};

// The words of a closed geodesic's kinds, as the table and the JSON list say them: "-" for none.
std::string stabilityWord(const ClosedGeodesic& g) { return g.stability ? nameOf(*g.stability) : "-"; }
std::string symmetryWords(const ClosedGeodesic& g) {
  std::string words;
  for (const ChainSymmetryOf& s : g.symmetries)
    words += (words.empty() ? "" : ", ") + std::string(s.fixed ? "fixed by " : "") + nameOf(s.kind);
  return words;
}

nlohmann::json geodesicJson(const Chain& chain, const ClosedGeodesic& g) {
  nlohmann::json o;
  o["length"] = g.length;
  o["simple"] = g.simple;
  o["symmetry"] = symmetryWords(g);
  o["stability"] = stabilityWord(g);
  if (g.stability == Stability::Elliptic) o["rotation_number"] = g.rotationNumber;
  if (g.stability) {
    nlohmann::json eigen = nlohmann::json::array();
    for (int i = 0; i < 2; ++i) eigen.push_back({g.eigenvalues(i).real(), g.eigenvalues(i).imag()});
    o["eigenvalues"] = eigen;
    o["monodromy_trace"] = g.monodromy.trace();
  }
  // A unit-speed start: a scene's "initial" with these coords and velocity (chart 0) animates it.
  const Eigen::VectorXd x = spherePointFromHinges(chain, ConstrainedModel::unstack(g.point));
  const Eigen::VectorXd xdot = sphereVelocityFromHingeVelocities(chain, x, ConstrainedModel::unstack(g.velocity));
  const Eigen::VectorXd coords = coordinatesFromSpherePoint(x);
  o["start"] = {{"coords", vectorJson(coords)},
                {"velocity", vectorJson(coordinateRatesFromSphereVelocity(coords, xdot))}};
  o["start_hinges"] = hingesJson(g.point);
  o["start_hinge_velocities"] = hingesJson(g.velocity);
  o["closure_position"] = g.positionClosure;
  o["closure_velocity"] = g.velocityClosure;
  o["closure"] = g.closure();  // in the orbit's own units: what the check bounds
  o["check"] = selfCheckName(selfCheck(g));
  if (g.independentLength) {
    o["independent_length"] = *g.independentLength;
    o["independent_route"] = g.independentRoute;
  } else {
    o["independent_length"] = nullptr;
  }
  return o;
}

// Warns of each unconfirmed closed geodesic (exit 3 when none is confirmed); returns what the summary line says.
std::string foundWords(const std::vector<ClosedGeodesic>& found, bool quiet) {
  std::vector<SelfCheck> checks;
  for (const ClosedGeodesic& g : found) checks.push_back(selfCheck(g));
  const std::string unconfirmed = reportUnconfirmed("periodic", "closed geodesic", checks, quiet);
  return std::to_string(found.size()) + (found.size() == 1 ? " closed geodesic" : " closed geodesics") + unconfirmed;
}

// Prints the closed geodesics found; returns what the summary line says of them.
std::string runPeriodic(const PeriodicArguments& args) {
  const Scene scene = loadSceneForCommand(args.scene, args.overrides);
  const Chain& chain = scene.chain;
  if ((chain.rods != 3 && chain.rods != 4) || chain.isSlack())
    throw CommandExit(kExitBadInput, args.scene + ": linkage: periodic needs 3 or 4 rods with n - 2 < L < n (got " +
                                         std::to_string(chain.rods) + " rods, L = " + std::to_string(chain.baseLength) +
                                         ")");
  if (const auto refusal = periodicSearchRefusal(chain))
    throw CommandExit(kExitBadInput, args.scene + ": linkage: " + *refusal);
  const std::vector<ClosedGeodesic> found = closedGeodesicsOf(chain, args.maxLength, interruptRequested, searchProgress("periodic", args.quiet));
  if (args.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const ClosedGeodesic& g : found) list.push_back(geodesicJson(chain, g));
    std::cout << list.dump(2) << "\n" << std::flush;
    return foundWords(found, args.quiet);
  }
  std::printf("%3s %16s %16s %6s %-10s %9s %9s %9s  %-15s  %s\n", "#", "length", "independent", "simple",
              "stability", "rotation", "trace", "closure", "check", "symmetry");
  for (std::size_t i = 0; i < found.size(); ++i) {
    const ClosedGeodesic& g = found[i];
    char independent[32] = "-", rotation[32] = "-", trace[32] = "-";
    if (g.independentLength) std::snprintf(independent, sizeof independent, "%.12f", *g.independentLength);
    if (g.stability == Stability::Elliptic) std::snprintf(rotation, sizeof rotation, "%.6f", g.rotationNumber);
    if (g.stability) std::snprintf(trace, sizeof trace, "%.6f", g.monodromy.trace());
    std::printf("%3zu %16.12f %16s %6s %-10s %9s %9s %9.1e  %-15s  %s\n", i, g.length, independent,
                g.simple ? "yes" : "no", stabilityWord(g).c_str(), rotation, trace, g.closure(),
                selfCheckName(selfCheck(g)).c_str(), g.symmetries.empty() ? "-" : symmetryWords(g).c_str());
  }
  std::fflush(stdout);
  return foundWords(found, args.quiet);
}

}  // namespace

void addPeriodicCommand(CLI::App& app) {
  auto args = std::make_shared<PeriodicArguments>();
  CLI::App* command =
      app.add_subcommand("periodic", "Closed geodesics (periodic motions) of the scene's linkage, 3 or 4 rods");
  command->add_option("scene", args->scene, "scene file (JSON): its linkage is used")->required();
  addSceneOverrideOption(*command, args->overrides);
  command
      ->add_option("--max-length", args->maxLength, "longest closed geodesic wanted (default: about 2.5x the shortest)")
      ->check(finiteRange(0.0, limits::kMaxPeriodicLength));
  command->add_flag("--json", args->json,
                    "a JSON list of objects (length, simple, symmetry, stability, eigenvalues, start, ...)");
  command->footer(
      "Route 1 shoots on the return map (Newton with the monodromy); 'independent' is route 2's length where it\n"
      "applies (the end swap's fixed curve, twice a discrete geodesic between the half turn's fixed points, the\n"
      "3-rod circle). Stability from the linearised return map: elliptic (rotation number) or hyperbolic.\n"
      "'check': confirmed when it closes and its two routes agree within the bounds of docs/hardening.md\n"
      "(principle 22); an unconfirmed one is listed with a warning and cannot start a scene; exit 3 when none is.\n"
      "Example:\n  linkage periodic scenes/default.json --json");
  command->add_flag("--quiet", args->quiet, "errors only: no summary line");
  command->callback([args] {
    const CommandSummary summary("periodic", args->quiet);  // the search answers SIGINT/SIGTERM: exit 130
    summary.print(runAnsweringSignals([&] { return runPeriodic(*args); }));
  });
}

}  // namespace sl

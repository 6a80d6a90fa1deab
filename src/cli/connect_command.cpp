// `linkage connect SCENE.json --to TARGET`: every force-free motion from the scene's start to a target
// configuration up to a length, by shooting and by the discrete action (src/inverse/connect.hpp).

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/summary.hpp"
#include "contracts/csv_format.hpp"
#include "cli/configuration_json.hpp"
#include "cli/configuration_point.hpp"
#include "cli/exit_codes.hpp"
#include "cli/scene_input.hpp"
#include "contracts/limits.hpp"
#include "inverse/connect.hpp"
#include "linkage/chart.hpp"
#include "simulation/ambient_system.hpp"

namespace sl {

namespace {

struct ConnectArguments {
  std::vector<std::string> overrides;
  std::string scene;
  std::string target;
  double maxLength = 0;
  bool json = false;
  bool quiet = false;
};

std::string foundWords(const std::vector<Connection>& found) {
  return std::to_string(found.size()) + (found.size() == 1 ? " geodesic" : " geodesics") +
         " to the target, distance " + shortest(found[0].length);
}

// Prints the motions found; returns what the summary line says of them.
std::string runConnect(const ConnectArguments& args) {
  const Scene scene = loadSceneForCommand(args.scene, args.overrides);
  const Chain& chain = scene.chain;
  if (chain.rods > limits::kMaxConnectRods)
    throw CommandExit(kExitBadInput, args.scene + ": linkage.rods: connect handles at most " +
                                         std::to_string(limits::kMaxConnectRods) + " rods (got " +
                                         std::to_string(chain.rods) + ")");
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  const InitialState start = runStarts(scene).at(0);
  const Eigen::VectorXd from =
      ConstrainedModel::stack(start.byHinges() ? start.hinges : hingePositionsAt(chain, start.spherePoint));
  const Eigen::VectorXd to = readConfigurationPoint(chain, model, args.target, "--to");
  ConnectOptions options;
  options.maxLength = args.maxLength;
  const std::vector<Connection> found = findConnections(model, &chain, from, to, options);
  if (found.empty()) throw CommandExit(kExitFailure, args.scene + ": no geodesic to the target was found");

  if (args.json) {
    nlohmann::json list = nlohmann::json::array();
    for (std::size_t i = 0; i < found.size(); ++i) {
      const Connection& c = found[i];
      nlohmann::json o;
      o["length"] = c.length;
      o["shortest"] = i == 0;
      o["hinge_velocities"] = hingesJson(c.velocity);
      if (!chain.isSlack()) {
        const Eigen::VectorXd x = spherePointFromHinges(chain, ConstrainedModel::unstack(from));
        const Eigen::VectorXd xdot = sphereVelocityFromHingeVelocities(chain, x, ConstrainedModel::unstack(c.velocity));
        const Eigen::VectorXd coords = coordinatesFromSpherePoint(x);
        o["coords"] = vectorJson(coords);
        o["rates"] = vectorJson(coordinateRatesFromSphereVelocity(coords, xdot));
      }
      o["morse_index"] = c.morseIndex;
      o["end_error"] = c.endError;
      if (c.discrete) {
        o["discrete_length"] = c.discrete->length;
        o["discrete_seed"] = c.discrete->seed;
        o["length_difference"] = c.lengthDifference;
        o["path_difference"] = c.pathDifference;
      } else {
        o["discrete_length"] = nullptr;
      }
      list.push_back(o);
    }
    std::cout << list.dump(2) << "\n";
    return foundWords(found);
  }
  std::printf("distance %.12f (the shortest of %zu geodesics up to the length bound)\n", found[0].length, found.size());
  std::printf("%3s %16s %16s %6s %10s %10s %10s  %s\n", "#", "length", "discrete", "morse", "end err", "len diff",
              "path diff", "initial hinge velocities (time 1)");
  for (std::size_t i = 0; i < found.size(); ++i) {
    const Connection& c = found[i];
    std::string velocities;
    for (Eigen::Index k = 0; k + 1 < c.velocity.size(); k += 2) {
      char cell[64];
      std::snprintf(cell, sizeof cell, "%s(%.6f, %.6f)", k ? " " : "", c.velocity(k), c.velocity(k + 1));
      velocities += cell;
    }
    if (c.discrete)
      std::printf("%3zu %16.12f %16.12f %6d %10.1e %10.1e %10.1e  %s\n", i, c.length, c.discrete->length, c.morseIndex,
                  c.endError, c.lengthDifference, c.pathDifference, velocities.c_str());
    else
      std::printf("%3zu %16.12f %16s %6d %10.1e %10s %10s  %s\n", i, c.length, "-", c.morseIndex, c.endError, "-", "-",
                  velocities.c_str());
  }
  return foundWords(found);
}

}  // namespace

void addConnectCommand(CLI::App& app) {
  auto args = std::make_shared<ConnectArguments>();
  CLI::App* command =
      app.add_subcommand("connect", "Every force-free motion from the scene's start to a target shape, by two routes");
  command->add_option("scene", args->scene, "scene file (JSON): its linkage and start point are used")->required();
  addSceneOverrideOption(*command, args->overrides);
  command
      ->add_option("--to", args->target,
                   "target: {\"coords\": [...]} (chart 0) or {\"hinges\": [[x, y], ...]}, or a file holding it")
      ->required();
  command->add_option("--max-length", args->maxLength, "longest geodesic wanted (default: 2.5 times the shortest)")
      ->check(CLI::Range(0.0, limits::kMaxConnectLength));
  command->add_flag("--json", args->json, "a JSON list of objects (length, shortest, coords, rates, ...)");
  command->footer(
      "Route 1 shoots (Newton on the end point, Jacobi fields as the derivative, seeded by a fan of directions);\n"
      "route 2 makes a discrete action stationary under the rod constraints. 'discrete' is route 2's length\n"
      "where it found the same geodesic; 'morse' the conjugate points passed.\n"
      "Example:\n  linkage connect scenes/default.json --to '{\"coords\": [-0.6, 2.2]}' --max-length 8");
  command->add_flag("--quiet", args->quiet, "errors only: no summary line");
  command->callback([args] {
    const CommandSummary summary("connect", args->quiet);
    summary.print(runConnect(*args));
  });
}

}  // namespace sl

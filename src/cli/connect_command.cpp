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
#include "cli/interrupt.hpp"
#include "cli/number_options.hpp"
#include "cli/progress.hpp"
#include "cli/scene_input.hpp"
#include "cli/self_check_words.hpp"
#include "contracts/limits.hpp"
#include "inverse/connect.hpp"
#include "inverse/method_shooting.hpp"
#include "linkage/chart.hpp"
#include "simulation/ambient_system.hpp"
#include "simulation/chart_system.hpp"

namespace sl {

namespace {

struct ConnectArguments {
  std::vector<std::string> overrides;
  std::string scene;
  std::string target;
  double maxLength = 0;
  std::vector<std::string> methods;  // route 3: each found motion shot again with these
  bool json = false;
  bool quiet = false;
};

// Warns of each unconfirmed motion (exit 3 when none is confirmed); returns what the summary line says.
std::string foundWords(const std::vector<Connection>& found, bool quiet) {
  std::vector<SelfCheck> checks;
  for (const Connection& c : found) checks.push_back(selfCheck(c));
  const std::string unconfirmed = reportUnconfirmed("connect", "geodesic", checks, quiet);
  return std::to_string(found.size()) + (found.size() == 1 ? " geodesic" : " geodesics") +
         " to the target, distance " + shortest(found[0].length) + unconfirmed;
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
  if (sameShape(model, from, to))
    throw CommandExit(kExitBadInput, "--to: is the start's own shape; expected another shape (a motion back to the "
                                     "start is a closed geodesic: linkage periodic)");
  // Route 3's methods, refused before any work when they cannot move this chain.
  std::vector<Method> methods;
  for (const std::string& name : args.methods) {
    methods.push_back(*parseKind(kMethods, name));
    try {
      requireMethodMoves({methods.back(), &chain, false, false});
    } catch (const std::invalid_argument& refusal) {
      throw CommandExit(kExitBadInput, "--method " + name + ": " + refusal.what());
    }
  }
  ConnectOptions options;
  options.maxLength = args.maxLength;
  options.cancelled = interruptRequested;
  options.progress = searchProgress("connect", args.quiet);
  const std::vector<Connection> found = findConnections(model, &chain, from, to, options);
  if (found.empty()) throw CommandExit(kExitFailure, args.scene + ": no geodesic to the target was found");
  // Route 3: every motion found, shot again with each method asked for (empty where Newton did not converge).
  std::vector<std::vector<std::optional<MethodConnection>>> shots(found.size());
  if (!methods.empty()) {
    Progress progress(static_cast<long>(found.size() * methods.size()), args.quiet, "connect", "method shot");
    for (std::size_t i = 0; i < found.size(); ++i)
      for (const Method method : methods) {
        shots[i].push_back(shootWithMethod(chain, method, from, to, found[i].velocity, 1e-13, interruptRequested));
        progress.update(static_cast<long>(i * methods.size() + shots[i].size()));
      }
  }
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
      o["check"] = selfCheckName(selfCheck(c));
      if (c.discrete) {
        o["discrete_length"] = c.discrete->length;
        o["discrete_seed"] = nameOf(c.discrete->seed);
        o["length_difference"] = c.lengthDifference;
        o["path_difference"] = c.pathDifference;
      } else {
        o["discrete_length"] = nullptr;
      }
      if (!methods.empty()) {
        nlohmann::json byMethod = nlohmann::json::array();
        for (std::size_t k = 0; k < methods.size(); ++k) {
          const auto& shot = shots[i][k];
          nlohmann::json m;
          m["method"] = nameOf(methods[k]);
          m["length"] = shot ? nlohmann::json(shot->length) : nlohmann::json(nullptr);
          m["length_difference"] = shot ? nlohmann::json(std::abs(shot->length - c.length)) : nlohmann::json(nullptr);
          m["end_error"] = shot ? nlohmann::json(shot->endError) : nlohmann::json(nullptr);
          byMethod.push_back(m);
        }
        o["methods"] = byMethod;
      }
      list.push_back(o);
    }
    std::cout << list.dump(2) << "\n" << std::flush;
    return foundWords(found, args.quiet);
  }
  std::printf("distance %.12f (the shortest of %zu geodesics up to the length bound)\n", found[0].length, found.size());
  std::printf("%3s %16s %16s %6s %10s %10s %10s  %-15s  %s\n", "#", "length", "discrete", "morse", "end err",
              "len diff", "path diff", "check", "initial hinge velocities (time 1)");
  for (std::size_t i = 0; i < found.size(); ++i) {
    const Connection& c = found[i];
    std::string velocities;
    for (Eigen::Index k = 0; k + 1 < c.velocity.size(); k += 2) {
      char cell[64];
      std::snprintf(cell, sizeof cell, "%s(%.6f, %.6f)", k ? " " : "", c.velocity(k), c.velocity(k + 1));
      velocities += cell;
    }
    const std::string check = selfCheckName(selfCheck(c));
    if (c.discrete)
      std::printf("%3zu %16.12f %16.12f %6d %10.1e %10.1e %10.1e  %-15s  %s\n", i, c.length, c.discrete->length,
                  c.morseIndex, c.endError, c.lengthDifference, c.pathDifference, check.c_str(), velocities.c_str());
    else
      std::printf("%3zu %16.12f %16s %6d %10.1e %10s %10s  %-15s  %s\n", i, c.length, "-", c.morseIndex, c.endError,
                  "-", "-", check.c_str(), velocities.c_str());
  }
  if (!methods.empty()) {
    std::printf("\nroute 3, the same motions shot again by other methods (Newton on the end point, time 1):\n");
    std::printf("%3s %-14s %16s %10s %10s\n", "#", "method", "length", "len diff", "end err");
    for (std::size_t i = 0; i < found.size(); ++i)
      for (std::size_t k = 0; k < methods.size(); ++k) {
        const auto& shot = shots[i][k];
        if (shot)
          std::printf("%3zu %-14s %16.12f %10.1e %10.1e\n", i, nameOf(methods[k]).c_str(), shot->length,
                      std::abs(shot->length - found[i].length), shot->endError);
        else
          std::printf("%3zu %-14s %16s %10s %10s  (did not reach the target to %s)\n", i,
                      nameOf(methods[k]).c_str(), "-", "-", "-", shortest(kMethodShotEndBound).c_str());
      }
  }
  std::fflush(stdout);
  return foundWords(found, args.quiet);
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
      ->check(finiteRange(0.0, limits::kMaxConnectLength));
  command
      ->add_option("--method", args->methods,
                   "also shoot every motion found with this method (repeatable), e.g. christoffel or embedded: a "
                   "third route through a chart's own equations of motion")
      ->check(CLI::IsMember(namesOf(kMethods)));
  command->add_flag("--json", args->json, "a JSON list of objects (length, shortest, coords, rates, ...)");
  command->footer(
      "Route 1 shoots (Newton on the end point, Jacobi fields as the derivative, seeded by a fan of directions);\n"
      "route 2 makes a discrete action stationary under the rod constraints. 'discrete' is route 2's length\n"
      "where it found the same geodesic; 'morse' the conjugate points passed. With --method, route 3 shoots\n"
      "each motion again with that method's equations (the published -fd methods' step control collapses at\n"
      "the tolerance this needs, so they report '-'). 'check': confirmed when it reaches the target and its\n"
      "routes agree within the bounds of docs/hardening.md (principle 22); exit 3 when none is.\n"
      "Example:\n  linkage connect scenes/default.json --to '{\"coords\": [-0.6, 2.2]}' --max-length 8");
  command->add_flag("--quiet", args->quiet, "errors only: no summary line");
  command->callback([args] {
    const CommandSummary summary("connect", args->quiet);  // the search answers SIGINT/SIGTERM: exit 130
    summary.print(runAnsweringSignals([&] { return runConnect(*args); }));
  });
}

}  // namespace sl

#include "cli/motion_starts.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <map>
#include <string>
#include <vector>

#include "cli/interrupt.hpp"
#include "cli/self_check_words.hpp"
#include "inverse/connect.hpp"
#include "inverse/holonomy.hpp"
#include "inverse/periodic.hpp"
#include "inverse/self_check.hpp"
#include "linkage/chart.hpp"
#include "scene/json_fields.hpp"
#include "scene/scene_loader.hpp"
#include "scene/title_placeholders.hpp"
#include "simulation/ambient_system.hpp"

namespace sl {

namespace {

// How far a configuration given by hinges may lie off the rod constraints (as `linkage connect --to` allows).
constexpr double kMaxHingeOffset = 1e-2;

// A search's identity: the chain and what was asked, as exact decimals.
std::string numbersKey(const Eigen::Ref<const Eigen::VectorXd>& values) {
  std::string key;
  for (double v : values) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g,", v);
    key += text;
  }
  return key;
}

std::string chainKey(const Chain& chain) {
  return std::to_string(chain.rods) + ";" + numbersKey(Eigen::VectorXd::Constant(1, chain.baseLength)) + ";" +
         numbersKey(chain.hingeMasses) + ";" + numbersKey(chain.rodMasses);
}

std::string configurationKey(const ConfigurationSpec& c) {
  return c.hinges.cols() > 0 ? "h" + numbersKey(Eigen::Map<const Eigen::VectorXd>(c.hinges.data(), c.hinges.size()))
                             : "c" + numbersKey(c.coords);
}

// The configuration as stacked hinges on the rod constraints, or nullopt with a problem at `path`.
std::optional<Eigen::VectorXd> configurationOf(const Chain& chain, const ConstrainedModel& model,
                                               const ConfigurationSpec& spec, const std::string& path,
                                               std::vector<SceneProblem>& problems) {
  if (spec.hinges.cols() == 0) return ConstrainedModel::stack(hingePositions(chain, spec.coords));
  const Eigen::VectorXd given = ConstrainedModel::stack(spec.hinges);
  Eigen::VectorXd q = given;
  const bool placed = model.projectPosition(q);
  const double offset = placed ? (q - given).cwiseAbs().maxCoeff() : INFINITY;
  if (offset > kMaxHingeOffset) {
    char found[64] = "cannot be placed on them";
    if (placed) std::snprintf(found, sizeof found, "lie %.3g off them", offset);
    problems.push_back({path + ".hinges", std::string("are not a configuration of the chain: the hinges ") + found +
                                              "; expected hinges within 0.01 of a configuration with unit rods"});
    return std::nullopt;
  }
  return q;
}

// One search's list, shared by the runs that ask for it.
struct Found {
  std::vector<FoundMotion> motions;
  std::vector<SelfCheck> checks;  // each motion's own check: a run starts only on a confirmed one
  bool failed = false;  // a problem was recorded: the runs asking for it add none of their own
};

// The geodesics from `from` to `to`, shortest first: the list `linkage connect` prints (route 1's; route 2 only
// confirms them).
Found connections(const Chain& chain, const FoundMotionSpec& request, const std::string& path,
                  std::vector<SceneProblem>& problems) {
  Found found;
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  const auto from = configurationOf(chain, model, request.from, path + ".from", problems);
  const auto to = configurationOf(chain, model, request.to, path + ".to", problems);
  if (!from || !to) {
    found.failed = true;
    return found;
  }
  if (sameShape(model, *from, *to)) {
    problems.push_back({path + ".to", "is the start's own shape; expected another shape (a motion back to the start is "
                                      "a closed geodesic: initial.periodic)"});
    found.failed = true;
    return found;
  }
  ConnectOptions options;
  options.maxLength = request.maxLength;
  options.discreteRoute = false;
  options.cancelled = interruptRequested;
  const Eigen::VectorXd x = spherePointFromHinges(chain, ConstrainedModel::unstack(*from));
  for (const Connection& c : findConnections(model, &chain, *from, *to, options)) {
    FoundMotion motion;
    motion.spherePoint = x;
    motion.sphereVelocity =
        sphereVelocityFromHingeVelocities(chain, x, ConstrainedModel::unstack(c.velocity / c.length));
    motion.length = motion.time = c.length;
    found.motions.push_back(motion);
    found.checks.push_back(selfCheck(c));
  }
  return found;
}

// The closed geodesics, in the order `linkage periodic` lists them, each from its unit-speed start.
Found closedGeodesics(const Chain& chain, const FoundMotionSpec& request) {
  const std::vector<ClosedGeodesic> geodesics = closedGeodesicsOf(chain, request.maxLength, interruptRequested);
  Found found;
  for (const ClosedGeodesic& g : geodesics) {
    FoundMotion motion;
    motion.spherePoint = spherePointFromHinges(chain, ConstrainedModel::unstack(g.point));
    motion.sphereVelocity =
        sphereVelocityFromHingeVelocities(chain, motion.spherePoint, ConstrainedModel::unstack(g.velocity));
    motion.length = motion.time = g.length;
    motion.stability = g.stability;
    found.motions.push_back(motion);
    found.checks.push_back(selfCheck(g));
  }
  return found;
}

}  // namespace

std::vector<SceneProblem> resolveMotionStarts(Scene& scene) {
  std::vector<SceneProblem> problems;
  if (scene.distanceFrom) {  // the distance colouring's point, placed on the rod constraints as a start's
    const ConstrainedModel model = ConstrainedModel::fromChain(scene.chain);
    if (const auto q = configurationOf(scene.chain, model, *scene.distanceFrom, "view.sphere.distance_from", problems))
      scene.distancePoint = spherePointFromHinges(scene.chain, ConstrainedModel::unstack(*q));
  }
  scene.holonomyPoints.clear();
  if (!scene.holonomyCorners.empty()) {  // the holonomy polygon's corners, placed on the rod constraints
    const ConstrainedModel model = ConstrainedModel::fromChain(scene.chain);
    for (std::size_t i = 0; i < scene.holonomyCorners.size(); ++i) {
      const std::string path = indexPath("view.sphere.holonomy.corners", i);
      const auto q = configurationOf(scene.chain, model, scene.holonomyCorners[i], path, problems);
      if (!q) continue;
      scene.holonomyPoints.push_back(spherePointFromHinges(scene.chain, ConstrainedModel::unstack(*q)));
      if (i > 0 && scene.holonomyPoints.size() == i + 1 &&
          (scene.holonomyPoints[i] - scene.holonomyPoints[i - 1]).norm() < 1e-9)
        problems.push_back({path, "is the same shape as the corner before it; expected the corners of a polygon"});
    }
    // The polygon computed once here, so that what a render would refuse validate refuses too (its shortest motions
    // found, its enclosed curvature defined, its own checks passed); the frames compute it again (30 ms).
    if (problems.empty() && scene.holonomyPoints.size() == scene.holonomyCorners.size()) {
      const std::string path = "view.sphere.holonomy.corners";
      try {
        const SelfCheck check = selfCheck(polygonHolonomy(scene.chain, scene.holonomyPoints, interruptRequested));
        if (check != SelfCheck::confirmed)
          problems.push_back({path, "the polygon's holonomy is unconfirmed: " + selfCheckReason(check)});
      } catch (const RunCancelled&) {
        throw;
      } catch (const std::exception& error) {
        problems.push_back({path, error.what()});
      }
    }
  }
  std::map<std::string, Found> searches;
  bool any = false;
  for (std::size_t i = 0; i < scene.runs.size(); ++i) {
    RunSpec& run = scene.runs[i];
    InitialSpec& initial = run.initial;
    if (!initial.namesAMotion()) continue;
    any = true;
    const bool connect = initial.kind == InitialSpec::Kind::Connect;
    // A start the scene shares is reported once, where it is written.
    const std::string path =
        (run.ownInitial ? indexPath("runs", i) + ".initial" : std::string("initial")) + (connect ? ".connect" : ".periodic");
    const FoundMotionSpec& request = initial.search;
    const std::string key = chainKey(run.chain) + (connect ? "|connect|" + configurationKey(request.from) + "|" +
                                                                 configurationKey(request.to)
                                                           : "|periodic") +
                            "|" + numbersKey(Eigen::VectorXd::Constant(1, request.maxLength));
    auto search = searches.find(key);
    if (search == searches.end()) {
      Found found;
      try {
        found = connect ? connections(run.chain, request, path, problems) : closedGeodesics(run.chain, request);
      } catch (const std::exception& error) {
        problems.push_back({path, std::string("the search for the motion failed: ") + error.what()});
        found.failed = true;
      }
      search = searches.emplace(key, std::move(found)).first;
    }
    const Found& found = search->second;
    if (found.failed) continue;
    const int count = static_cast<int>(found.motions.size());
    if (request.index >= count) {
      const std::string what = connect ? (count == 1 ? " geodesic to the target was" : " geodesics to the target were")
                                       : (count == 1 ? " closed geodesic was" : " closed geodesics were");
      const std::string bound = request.maxLength > 0 ? "up to max_length" : "up to the search's own length bound";
      problems.push_back({path + ".index", "found " + std::to_string(request.index) + "; " + std::to_string(count) +
                                               what + " found " + bound +
                                               (count > 0 ? ", so expected an index from 0 to " +
                                                                std::to_string(count - 1)
                                                          : std::string(", so there is nothing to start from")) +
                                               (connect ? " (or a larger max_length)" : "")});
      continue;
    }
    if (const SelfCheck check = found.checks[static_cast<std::size_t>(request.index)]; check != SelfCheck::confirmed) {
      problems.push_back({path + ".index", "found " + std::to_string(request.index) + ", a motion that is unconfirmed: " +
                                               selfCheckReason(check) + " (linkage " +
                                               (connect ? "connect" : "periodic") +
                                               " lists its check); expected the index of a confirmed one"});
      continue;
    }
    FoundMotion motion = found.motions[static_cast<std::size_t>(request.index)];
    motion.found = count;
    if (request.arrival) {  // the same geodesic, run faster or slower: it reaches the target at `arrival`
      motion.sphereVelocity *= motion.length / *request.arrival;
      motion.time = *request.arrival;
    }
    initial.motion = motion;
  }
  if (!any || !problems.empty()) return problems;
  if (scene.durationFromMotions) {
    scene.duration = 0;
    for (const RunSpec& run : scene.runs) scene.duration = std::max(scene.duration, run.initial.motion->time);
    problems = checkResolvedDuration(scene);
  }
  scene.title = fillTitlePlaceholders(scene.title, scene);
  return problems;
}

}  // namespace sl

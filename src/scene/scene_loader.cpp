#include "scene/scene_loader.hpp"
#include "scene/scene_overrides.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "contracts/csv_format.hpp"
#include "contracts/limits.hpp"
#include "contracts/registry.hpp"
#include "linkage/method_rules.hpp"
#include "scene/did_you_mean.hpp"
#include "scene/title_placeholders.hpp"
#include "scene/json_error_path.hpp"
#include "scene/json_fields.hpp"
#include "scene/output_folder.hpp"
#include "scene/scene_cost.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_sections.hpp"

namespace sl {
namespace {

// Characters of UTF-8 text: the bytes that do not continue a code point.
std::size_t codePoints(const std::string& text) {
  return std::size_t(std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

}  // namespace

using nlohmann::json;

namespace {

// A scene name becomes a folder name: keep it to characters that are safe everywhere.
bool isSafeName(const std::string& name) {
  return !name.empty() && name.size() <= kMaxOutputNameBytes && name != "." && name != ".." &&
         std::all_of(name.begin(), name.end(), [](char c) {
           return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
         });
}

// The number of rods other checks measure against: the scene's, or none while its "rods" is invalid. A check whose
// expectation depends on n (the sizes of masses and starts, rules by rod count) is skipped then: the invalid
// "rods" is reported on its own, and comparing with a made-up n would add problems that are not there.
using RodCount = std::optional<int>;

// checkSize against a count that depends on n (`expected` is empty while n is unknown: the value passes).
bool fitsChain(const JsonObject& object, const std::string& key, const Eigen::VectorXd& value,
               std::optional<long> expected, const std::string& what) {
  return !expected || object.checkSize(key, value, *expected, what);
}

std::optional<long> chainSize(RodCount rods, int offset) {
  return rods ? std::optional<long>(*rods + offset) : std::nullopt;
}

// "n-1 = 4", or just "n-1" while n is unknown (an invalid "rods": no made-up number in a message either).
std::string hingeCountText(RodCount rods) { return rods ? "n-1 = " + std::to_string(*rods - 1) : "n-1"; }

// Reads a "linkage" object at `path` into `chain`. The scene's linkage sets n and L and gives the masses their
// defaults (unit hinges, massless rods); a run's linkage (forRun) starts from the scene's chain and may change L
// and the masses, never n: every run of a scene is drawn and compared with the same number of rods. Returns the
// number of rods the rest of the scene is checked against (for a run: `sceneRods`, the scene's).
RodCount readLinkage(const json& value, const std::string& path, RodCount sceneRods, bool forRun, Chain& chain,
                     std::vector<SceneProblem>& problems) {
  const JsonObject linkage(value, path, problems);
  bool rodsKnown = forRun && sceneRods.has_value();  // sizes and L are judged against n only when n is valid
  if (forRun) {
    if (const auto rods = linkage.integer("rods"); rods && sceneRods && *rods != *sceneRods) {
      linkage.report("rods", "found " + std::to_string(*rods) + "; a run keeps the scene's number of rods, " +
                                 std::to_string(*sceneRods) + " (a run may set its own L and masses)");
    }
  } else if (const auto rods = linkage.integer("rods", true)) {
    if (linkage.checkBounds("rods", *rods)) {
      chain.rods = static_cast<int>(*rods);
      rodsKnown = true;
    }
  }
  const int n = chain.rods;
  if (const auto base = linkage.number("L", !forRun)) {
    // n-2 < L < n: the configuration space is a sphere; 0 < L <= n-2: a slack chain, for the ambient method
    // (checked with the runs' methods, readRun).
    if (rodsKnown && (*base <= 0 || *base >= n)) {
      std::ostringstream allowed;
      allowed << "a length strictly between 0 and n = " << n
              << " (n-2 < L < n: the configuration space is a sphere; 0 < L <= n-2: a slack chain, ambient method "
                 "only)";
      linkage.report("L", "found " + describeJson((*linkage.member("L"))) + "; expected " + allowed.str());
    }
    chain.baseLength = *base;
  }
  if (!forRun) {
    chain.hingeMasses = Eigen::VectorXd::Ones(n - 1);
    chain.rodMasses = Eigen::VectorXd::Zero(n);
  }
  if (const auto masses = linkage.numbers("hinge_masses")) {
    if (fitsChain(linkage, "hinge_masses", *masses, rodsKnown ? std::optional<long>(n - 1) : std::nullopt,
                  "one per interior hinge, n-1")) {
      linkage.checkElements("hinge_masses", *masses);
      chain.hingeMasses = *masses;
    }
  }
  if (const auto masses = linkage.numbers("rod_masses")) {
    if (fitsChain(linkage, "rod_masses", *masses, rodsKnown ? std::optional<long>(n) : std::nullopt,
                  "one per rod, n")) {
      linkage.checkElements("rod_masses", *masses);
      chain.rodMasses = *masses;
    }
  }
  // A hinge may carry no point mass when a rod beside it has mass: the kinetic energy still sees it move.
  for (Eigen::Index j = 0; rodsKnown && j < chain.hingeMasses.size() && j + 1 < chain.rodMasses.size(); ++j) {
    if (chain.hingeMasses(j) == 0 && chain.rodMasses(j) == 0 && chain.rodMasses(j + 1) == 0) {
      linkage.report("hinge_masses", "hinge " + std::to_string(j + 1) +
                                         " carries no mass, and neither do the rods beside it; expected a positive "
                                         "hinge mass or a massive rod next to it");
      break;
    }
  }
  return rodsKnown ? RodCount(n) : std::nullopt;
}

void readDrag(const JsonObject& initial, RodCount rods, InitialSpec& spec, std::vector<SceneProblem>& problems) {
  const JsonObject drag(*initial.member("drag"), initial.pathOf("drag"), problems);
  const std::optional<long> size = chainSize(rods, -1);
  const std::string what = "a vector of R^(n-1), " + hingeCountText(rods);
  if (const auto point = drag.numbers("point", true); point && fitsChain(drag, "point", *point, size, what)) {
    // Only the point's direction matters: normalise here, overflow-free (a plain norm of [1e200, ...] is
    // inf and the "unit" point would be zero; of [1e-320, 0, 0] it is 0 and a valid point looks zero).
    if ((point->array() == 0).all()) {
      drag.report("point", "found the zero vector; expected a non-zero vector (normalised onto the sphere)");
    } else {
      spec.dragPoint = point->stableNormalized();
    }
  }
  if (const auto direction = drag.numbers("direction", true);
      direction && fitsChain(drag, "direction", *direction, size, what)) {
    spec.dragDirection = *direction;
  }
  // Whether the direction crosses the sphere at the point is decided when the start is set up
  // (initialStateFromDrag), for validate and render alike, with this start's path.
}

// A list of n-1 points [[x, y], ...] under `key` (any number of them while n is unknown), or nullopt (problems
// recorded).
std::optional<Eigen::Matrix2Xd> readPoints(const JsonObject& object, const std::string& key, RodCount rods) {
  const json* value = object.member(key);
  const std::string what = "an array of " + hingeCountText(rods) + " points [x, y]";
  if (!value->is_array() || (rods && value->size() != static_cast<std::size_t>(*rods - 1))) {
    object.report(key, "found " + describeJson(*value) + "; expected " + what);
    return std::nullopt;
  }
  const int count = static_cast<int>(value->size());
  Eigen::Matrix2Xd points(2, count);
  for (int k = 0; k < count; ++k) {
    const json& point = (*value)[static_cast<std::size_t>(k)];
    if (!point.is_array() || point.size() != 2 || !point[0].is_number() || !point[1].is_number()) {
      object.report(key, "found " + describeJson(point) + " at index " + std::to_string(k) + "; expected " + what);
      return std::nullopt;
    }
    points(0, k) = point[0].get<double>();
    points(1, k) = point[1].get<double>();
  }
  if (!points.allFinite()) {
    object.report(key, "holds a non-finite number; expected finite coordinates");
    return std::nullopt;
  }
  return points;
}

// A start by hinges (any chain, slack ones included; ambient method): "hinges" is "arc" or the n-1
// points, then "velocities" (n-1 vectors) or a "push": {"hinge": k, "velocity": [vx, vy]} or {"seed": s,
// "size": v} (a random velocity of size about v at every hinge). Both are projected onto the rod constraints
// when the run starts (simulation/initial_state.hpp), and the commands say if they had to move.
void readHingeStart(const JsonObject& initial, RodCount rods, InitialSpec& spec, std::vector<SceneProblem>& problems) {
  spec.kind = InitialSpec::Kind::Hinges;
  if (!initial.has("hinges")) {
    initial.reportMissing("hinges", "\"arc\" or the n-1 hinge positions [[x, y], ...]");
  } else if (initial.member("hinges")->is_string()) {
    const std::string shape = initial.member("hinges")->get<std::string>();
    if (shape == "arc")
      spec.shape = InitialSpec::Shape::Arc;
    else
      initial.report("hinges", "found \"" + shape + "\"; expected \"arc\" or the n-1 hinge positions");
  } else if (const auto points = readPoints(initial, "hinges", rods)) {
    spec.hinges = *points;
  }
  if (initial.has("velocities") == initial.has("push")) {
    initial.report(initial.has("push") ? "push" : "velocities",
                   "expected exactly one of \"velocities\" (n-1 vectors) and \"push\"");
    return;
  }
  if (initial.has("velocities")) {
    if (const auto velocities = readPoints(initial, "velocities", rods)) spec.hingeVelocities = *velocities;
    return;
  }
  const JsonObject push(*initial.member("push"), initial.pathOf("push"), problems);
  if (!push.isObject()) return;
  if (push.has("seed") || push.has("size")) {
    if (push.has("hinge") || push.has("velocity"))
      push.report("seed", "given with hinge/velocity; expected a push on one hinge or a random push (seed, size)");
    if (const auto seed = push.integer("seed", true)) {
      push.checkBounds("seed", *seed);
      spec.pushSeed = std::max(0L, *seed);
    }
    if (const auto size = push.number("size"); size && push.checkBounds("size", *size))
      spec.pushSize = *size;
    return;
  }
  if (const auto hinge = push.integer("hinge", true)) {
    if (*hinge < 1 || (rods && *hinge > *rods - 1))
      push.report("hinge", "found " + std::to_string(*hinge) + "; expected a hinge from 1 to " + hingeCountText(rods));
    else
      spec.pushHinge = static_cast<int>(*hinge);
  }
  if (const auto velocity = push.numbers("velocity", true);
      velocity && push.checkSize("velocity", *velocity, 2, "a velocity [vx, vy]")) {
    push.checkElements("velocity", *velocity);
    spec.pushVelocity = *velocity;
  }
}

}  // namespace

ConfigurationSpec detail::readConfiguration(const JsonObject& parent, const std::string& key, RodCount rods,
                                            std::vector<SceneProblem>& problems) {
  ConfigurationSpec spec;
  if (!parent.has(key)) {
    parent.reportMissing(key, "a configuration: {\"coords\": [...]} (chart 0, n-2 numbers) or {\"hinges\": [[x, y], "
                              "...]} (n-1 points)");
    return spec;
  }
  return readConfigurationObject(JsonObject(*parent.member(key), parent.pathOf(key), problems), rods);
}

ConfigurationSpec detail::readConfigurationObject(const JsonObject& object, RodCount rods) {
  ConfigurationSpec spec;
  if (!object.isObject()) return spec;
  if (object.has("coords") == object.has("hinges")) {
    object.report(object.has("coords") ? "hinges" : "coords",
                  "expected exactly one of \"coords\" (chart 0, n-2 numbers) and \"hinges\" (n-1 points)");
    return spec;
  }
  if (object.has("hinges")) {
    if (const auto points = readPoints(object, "hinges", rods)) spec.hinges = *points;
    return spec;
  }
  const std::optional<long> size = chainSize(rods, -2);
  const std::string what = "chart coordinates, outermost first, " + (size ? "n-2 = " + std::to_string(*size) : "n-2");
  if (const auto coords = object.numbers("coords", true); coords && fitsChain(object, "coords", *coords, size, what))
    spec.coords = *coords;
  return spec;
}

namespace {

using detail::readConfiguration;

// A start that names a found motion: "connect" (a geodesic from one configuration to another) or "periodic" (a
// closed geodesic), by its index in the list the inverse problems give. Resolved by the commands before any run
// starts (cli/motion_starts.hpp); here only what can be judged from the file.
void readMotionStart(const JsonObject& initial, const std::string& key, RodCount rods, InitialSpec& spec,
                     std::vector<SceneProblem>& problems) {
  spec.kind = key == "connect" ? InitialSpec::Kind::Connect : InitialSpec::Kind::Periodic;
  if (initial.has("unit_speed"))
    initial.report("unit_speed", "is not used by a " + key + " start (it moves at unit speed" +
                                     (key == "connect" ? std::string(", or arrives at \"arrival\")") : ")") +
                                     "; expected no unit_speed");
  const JsonObject motion(*initial.member(key), initial.pathOf(key), problems);
  if (!motion.isObject()) return;
  FoundMotionSpec& request = spec.search;
  if (key == "connect") {
    request.from = readConfiguration(motion, "from", rods, problems);
    request.to = readConfiguration(motion, "to", rods, problems);
    if (const auto arrival = motion.number("arrival");
        arrival && motion.checkPositive("arrival", *arrival) && motion.checkBounds("arrival", *arrival))
      request.arrival = *arrival;
    if (rods && *rods > limits::kMaxConnectRods)
      initial.report(key, "found " + std::to_string(*rods) + " rods; connecting motions are found for at most " +
                              std::to_string(limits::kMaxConnectRods) + " rods");
  } else if (rods && *rods != 3 && *rods != 4) {
    initial.report(key, "found " + std::to_string(*rods) +
                            " rods; closed geodesics are found for 3 rods (the circle) or 4 (the configuration "
                            "sphere)");
  }
  if (const auto index = motion.integer("index"); index && motion.checkBounds("index", *index))
    request.index = static_cast<int>(*index);
  if (const auto length = motion.number("max_length");
      length && motion.checkPositive("max_length", *length) && motion.checkBounds("max_length", *length))
    request.maxLength = *length;
}

// Reads an "initial" object at `path` (the scene's start, or a run's own) for a chain of `rods` rods. A run's
// start replaces the scene's whole: it is one start, in any form the scene's may take.
void readInitial(const json& value, const std::string& path, RodCount rods, InitialSpec& spec,
                 std::vector<SceneProblem>& problems) {
  const JsonObject initial(value, path, problems);
  if (!initial.isObject()) return;
  spec = InitialSpec{};
  spec.unitSpeed = initial.boolean("unit_speed").value_or(spec.unitSpeed);
  const bool hasDrag = initial.has("drag");
  const bool hasCoords = initial.has("coords") || initial.has("velocity");
  const bool hasHinges = initial.has("hinges") || initial.has("velocities") || initial.has("push");
  const bool hasConnect = initial.has("connect"), hasPeriodic = initial.has("periodic");
  if (int(hasDrag) + int(hasCoords) + int(hasHinges) + int(hasConnect) + int(hasPeriodic) > 1) {
    initial.report(hasDrag      ? "drag"
                   : hasHinges  ? "hinges"
                   : hasConnect ? "connect"
                                : "periodic",
                   "given together with another form of start; expected one start: coords and velocity, or drag, "
                   "or hinges with velocities or a push, or connect, or periodic");
    return;
  }
  if (hasConnect || hasPeriodic) {
    readMotionStart(initial, hasConnect ? "connect" : "periodic", rods, spec, problems);
    return;
  }
  if (hasHinges) {
    readHingeStart(initial, rods, spec, problems);
    return;
  }
  if (hasDrag) {
    spec.kind = InitialSpec::Kind::Drag;
    readDrag(initial, rods, spec, problems);
    return;
  }
  const std::optional<long> size = chainSize(rods, -2);
  const std::string what = "chart coordinates, outermost first, " + (size ? "n-2 = " + std::to_string(*size) : "n-2");
  if (const auto coords = initial.numbers("coords", true); coords && fitsChain(initial, "coords", *coords, size, what)) {
    spec.coords = *coords;
  }
  if (const auto velocity = initial.numbers("velocity", true);
      velocity && fitsChain(initial, "velocity", *velocity, size, what)) {
    spec.velocity = *velocity;
    if (velocity->norm() == 0) {
      initial.report("velocity", "is zero; expected a non-zero velocity (a linkage at rest has no motion to show)");
    }
  }
}

// "family": a fan, parallel family or cloud of geodesics around the run (FamilySpec). Keys that mean nothing to
// the kind are refused, as "step" is with an adaptive integrator.
std::optional<FamilySpec> readFamily(const JsonObject& run, RodCount rods, std::vector<SceneProblem>& problems) {
  const JsonObject object(*run.member("family"), run.pathOf("family"), problems);
  if (!object.isObject()) return std::nullopt;
  FamilySpec family;
  const std::size_t before = problems.size();
  if (const auto kind = object.string("kind", true)) {
    if (const auto parsed = detail::pickKind(object.pathOf("kind"), *kind, kFamilyKinds, problems)) family.kind = *parsed;
  }
  if (const auto count = object.integer("count")) {
    if (object.checkBounds("count", *count)) family.count = static_cast<int>(*count);
  }
  const bool isCloud = family.kind == FamilyKind::Cloud;
  const std::string kindName = "\"" + std::string(traitsOf(kFamilyKinds, family.kind).name) + "\"";
  if (const auto spread = object.number("spread")) {
    if (isCloud)
      object.report("spread", "is not used by a " + kindName + " family; expected \"epsilon\" instead");
    else if (object.checkBounds("spread", *spread))
      family.spread = *spread;
  }
  for (const char* key : {"epsilon", "seed"}) {
    if (!isCloud && object.has(key))
      object.report(key, std::string("is used by a \"cloud\" family only; expected \"spread\" for a ") + kindName +
                             " family");
  }
  if (const auto epsilon = object.number("epsilon"); epsilon && isCloud) {
    if (object.checkBounds("epsilon", *epsilon))
      family.epsilon = *epsilon;
  }
  if (const auto seed = object.integer("seed"); seed && isCloud) {
    if (object.checkBounds("seed", *seed)) family.seed = static_cast<unsigned long>(*seed);
  }
  if (!isCloud && rods && *rods < 4)
    object.report("kind", "found " + kindName + " for " + std::to_string(*rods) +
                              " rods; a fan or parallel family needs a tangent plane (4 or more rods); expected "
                              "\"cloud\"");
  if (problems.size() != before) return std::nullopt;
  return family;
}

void readWatchdog(const JsonObject& run, RunConfig& config, std::vector<SceneProblem>& problems) {
  const JsonObject watchdog(*run.member("watchdog"), run.pathOf("watchdog"), problems);
  if (const auto drift = watchdog.number("max_energy_drift");
      drift && watchdog.checkPositive("max_energy_drift", *drift)) {
    config.maxRelativeEnergyDrift = *drift;
  }
  if (const auto error = watchdog.number("max_rod_length_error");
      error && watchdog.checkPositive("max_rod_length_error", *error)) {
    config.maxRodLengthError = *error;
  }
  if (const auto steps = watchdog.integer("max_steps"); steps && watchdog.checkPositive("max_steps", double(*steps))) {
    config.maxSteps = *steps;
  }
}

std::optional<ColorRGB> readColor(const JsonObject& object, const std::string& key) {
  const auto rgb = object.numbers(key);
  if (!rgb) return std::nullopt;
  if (!object.checkSize(key, *rgb, 3, "red, green, blue from 0 to 1")) return std::nullopt;
  if (!object.checkElements(key, *rgb)) return std::nullopt;
  return ColorRGB{float((*rgb)(0)), float((*rgb)(1)), float((*rgb)(2))};
}

RunSpec readRun(const json& value, const std::string& path, const Scene& scene, RodCount rods,
                std::vector<SceneProblem>& problems) {
  const JsonObject run(value, path, problems);
  RunSpec spec;
  spec.name = run.string("name", true).value_or("");
  if (run.has("name") && spec.name.empty()) run.report("name", "is empty; expected a name shown in the panels");
  // The run's own physics and start, defaulting to the scene's (compare physics, not only methods).
  spec.chain = scene.chain;
  spec.initial = scene.initial;
  spec.ownLinkage = run.has("linkage");
  spec.ownInitial = run.has("initial");
  if (spec.ownLinkage) readLinkage(*run.member("linkage"), run.pathOf("linkage"), rods, true, spec.chain, problems);
  if (spec.ownInitial) readInitial(*run.member("initial"), run.pathOf("initial"), rods, spec.initial, problems);
  if (const auto method = run.string("method")) {
    if (const auto kind = detail::pickKind(run.pathOf("method"), *method, kMethods, problems)) {
      spec.config.method = *kind;
      // The published methods are the spec's 4-rod, unit-mass ones; the simulation refuses them otherwise,
      // so say so here, with the JSON path, before any work.
      for (const MethodRefusal refusal : methodRefusals({*kind, rods ? &spec.chain : nullptr, false, false}))
        if (refusal == MethodRefusal::PublishedNeedsFourRods || refusal == MethodRefusal::PublishedNeedsSpecMasses)
          run.report("method", "found \"" + *method +
                                   "\", the spec's published method for 4 rods with unit hinge masses and "
                                   "massless rods; this chain differs: expected christoffel, embedded or ambient");
    }
  }
  bool knownIntegrator = true;
  if (const auto integrator = run.string("integrator")) {
    const auto kind = detail::pickKind(run.pathOf("integrator"), *integrator, kIntegrators, problems);
    if (kind) spec.config.integrator = *kind;
    knownIntegrator = kind.has_value();
  }
  if (const auto tolerance = run.number("tolerance")) {
    if (run.checkBounds("tolerance", *tolerance)) {
      spec.config.tolerance = *tolerance;
    }
  }
  if (const auto step = run.number("step"); step && run.checkPositive("step", *step)) {
    if (!scene.durationFromMotions && *step > scene.duration) {
      std::ostringstream message;
      message << "found " << *step << "; expected a step no longer than the duration " << scene.duration;
      run.report("step", message.str());
    }
    spec.config.step = *step;
  }
  // A step means nothing to an adaptive integrator, a tolerance nothing to a fixed-step one: refuse
  // rather than silently ignore what the user believes is being computed.
  const bool adaptive = traits(spec.config.integrator).adaptive;
  if (knownIntegrator && adaptive && run.has("step")) {
    run.report("step", "is not used by the adaptive integrator \"" + nameOf(spec.config.integrator) +
                           "\"; expected \"tolerance\" instead");
  }
  if (knownIntegrator && !adaptive && run.has("tolerance")) {
    run.report("tolerance", "is not used by the fixed-step integrator \"" + nameOf(spec.config.integrator) +
                                "\"; expected \"step\" instead");
  }
  spec.color = readColor(run, "color");
  if (run.has("watchdog")) readWatchdog(run, spec.config, problems);
  // What only the ambient method can move: a slack chain, a start by hinges, more than kMaxRods rods.
  const bool byHinges = spec.initial.kind == InitialSpec::Kind::Hinges;
  const bool slack = rods && spec.chain.isSlack();
  const bool chartFree = slack || byHinges;
  const Chain* knownChain = rods ? &spec.chain : nullptr;  // the rules by n only while n is valid
  for (const MethodRefusal refusal : methodRefusals({spec.config.method, knownChain, byHinges, false})) {
    if (refusal == MethodRefusal::SlackChainHasNoChart)
      run.report("method", "found \"" + nameOf(spec.config.method) + "\" for a slack chain (L = " +
                               shortest(spec.chain.baseLength) + " <= n-2): it has no chart; expected ambient");
    else if (refusal == MethodRefusal::HingeStartHasNoChart)
      run.report("method", "found \"" + nameOf(spec.config.method) +
                               "\" for a start by hinges; expected ambient (the chart methods start from coords or "
                               "a drag)");
    else if (refusal == MethodRefusal::TooManyRodsForCharts)
      run.report("method", "found \"" + nameOf(spec.config.method) + "\" for " + std::to_string(*rods) +
                               " rods; the chart methods are limited to " + std::to_string(limits::kMaxRods) +
                               " rods (their charts stay well conditioned there); expected ambient");
  }
  if (slack && spec.initial.kind != InitialSpec::Kind::Hinges) {
    const SceneProblem problem{spec.ownInitial ? run.pathOf("initial") : "initial",
                               "a slack chain (L = " + shortest(spec.chain.baseLength) +
                                   " <= n-2) has no configuration sphere, so no chart, drag, connect or periodic "
                                   "start; expected a start by \"hinges\""};
    if (std::none_of(problems.begin(), problems.end(), [&](const SceneProblem& p) { return p.jsonPath == problem.jsonPath; }))
      problems.push_back(problem);
  }
  if (run.has("family")) spec.family = readFamily(run, rods, problems);
  if (spec.family && chartFree)
    run.report("family", "a family starts from a point of the configuration sphere; expected a start by coords or "
                         "drag on a chain with n-2 < L < n");
  spec.config.jacobi = run.boolean("jacobi").value_or(spec.config.jacobi);
  if (!spec.config.jacobi) return spec;
  for (const MethodRefusal refusal : methodRefusals({spec.config.method, knownChain, byHinges, true})) {
    if (refusal == MethodRefusal::JacobiNeedsAmbient)
      run.report("jacobi", "needs the ambient method (its linearisation gives the Jacobi fields); found \"" +
                               nameOf(spec.config.method) + "\"");
    else if (refusal == MethodRefusal::JacobiNeedsSpherePoint)
      run.report("jacobi", "Jacobi fields start from a point of the configuration sphere; expected a start by "
                           "coords or drag on a chain with n-2 < L < n");
    else if (refusal == MethodRefusal::JacobiNeedsFourRods)
      run.report("jacobi", "needs 4 or more rods (3 rods have no direction across the motion)");
  }
  return spec;
}

void readRuns(const json* value, Scene& scene, RodCount rods, std::vector<SceneProblem>& problems) {
  if (value == nullptr) {
    problems.push_back({"runs", "missing; expected an array of runs, each with a name and a method"});
    return;
  }
  if (!value->is_array() || value->empty()) {
    problems.push_back({"runs", "found " + describeJson(*value) + "; expected a non-empty array of runs"});
    return;
  }
  std::set<std::string> names;
  for (size_t i = 0; i < value->size(); ++i) {
    const std::string path = indexPath("runs", i);
    RunSpec run = readRun((*value)[i], path, scene, rods, problems);
    if (!run.name.empty() && !names.insert(run.name).second) {
      problems.push_back({path + ".name", "\"" + run.name + "\" is used by an earlier run; expected unique names"});
    }
    scene.runs.push_back(std::move(run));
  }
}

void readOutput(const json& value, Scene& scene, std::vector<SceneProblem>& problems) {
  const JsonObject output(value, "output", problems);
  OutputSettings& spec = scene.output;
  if (const auto fps = output.integer("fps")) {
    if (output.checkBounds("fps", *fps)) spec.fps = static_cast<int>(*fps);
  }
  const auto width = output.integer("width");
  const auto height = output.integer("height");
  spec.size.width = static_cast<int>(std::clamp<long>(width.value_or(spec.size.width), -1, 1 << 30));
  spec.size.height = static_cast<int>(std::clamp<long>(height.value_or(spec.size.height), -1, 1 << 30));
  spec.folder = output.string("folder").value_or("renders/" + scene.name);
  if (spec.folder.empty()) output.report("folder", "is empty; expected a folder for the frames");
  if (const std::string reason = unusablePathReason(spec.folder); !reason.empty())
    output.report("folder", reason + "; expected a usable folder path");
  spec.png = output.boolean("png").value_or(spec.png);
  if (const auto compression = output.string("png_compression")) {
    if (const auto kind = detail::pickKind(output.pathOf("png_compression"), *compression, kPngCompressions, problems))
      spec.pngCompression = *kind;
  }
  spec.video = output.string("video").value_or(spec.video);
  if (const auto quality = output.string("video_quality")) {
    if (const auto kind = detail::pickKind(output.pathOf("video_quality"), *quality, kVideoQualities, problems))
      spec.videoQuality = *kind;
  }
  if (const auto crf = output.integer("video_crf"); crf && output.checkBounds("video_crf", *crf))
    spec.videoCrf = static_cast<int>(*crf);
  if (const auto hold = output.number("hold_start"); hold && output.checkBounds("hold_start", *hold))
    spec.holdStart = *hold;
  if (const auto hold = output.number("hold_end"); hold && output.checkBounds("hold_end", *hold)) spec.holdEnd = *hold;
  if (const auto speed = output.number("playback_speed"); speed && output.checkBounds("playback_speed", *speed))
    spec.playbackSpeed = *speed;
  const auto format = videoFormatOfPath(spec.video);
  for (SceneProblem& problem : checkImageSize(spec.size, format && traits(*format).needsEvenSize, "output")) {
    problems.push_back(std::move(problem));
  }
}

}  // namespace

std::vector<SceneProblem> checkImageSize(ImageSize size, bool evenForVideo, const std::string& path) {
  std::vector<SceneProblem> problems;
  for (const auto& [key, value] : {std::pair{"width", size.width}, std::pair{"height", size.height}}) {
    const std::string where = path + "." + key;
    const SceneKey& described = sceneKey(std::string("output.") + key);
    if (!withinBounds(described, value)) {
      problems.push_back({where, "found " + std::to_string(value) + "; expected " + expectedWords(described)});
    } else if (evenForVideo && value % 2 != 0) {
      problems.push_back(
          {where, "found " + std::to_string(value) + "; an mp4 or webm video (yuv420p) needs an even size"});
    }
  }
  return problems;
}

std::vector<SceneProblem> checkFrameCount(double duration, int fps) {
  const double frames = std::ceil(duration * fps) + 1;
  if (frames <= static_cast<double>(limits::kMaxFrames)) return {};
  std::ostringstream message;
  message << "found " << duration << " s at " << fps << " fps = " << frames << " frames; at most " << limits::kMaxFrames
          << " frames are allowed (split the animation into several scenes)";
  return {{"duration", message.str()}};
}

Scene parseScene(const std::string& text, const std::string& file, const std::vector<std::string>& overrides) {
  json document;
  // A key twice in one object: nlohmann keeps the last silently, which could hide a whole section. Found while
  // parsing, with the JSON path that leads to it (array elements by their index: runs[1].name).
  std::vector<SceneProblem> duplicates;
  struct Level {
    bool isArray = false;
    std::string component;  // how this level is named in a path: "runs", "[1]" (empty for the document)
    std::set<std::string> keys;
    std::string pendingKey;  // objects: the key whose value comes next
    std::size_t elements = 0;  // arrays: how many elements so far
  };
  std::vector<Level> levels;
  const auto pathTo = [&levels](const std::string& key) {
    std::string path;
    for (const Level& level : levels)
      if (!level.component.empty())
        path += (path.empty() || level.component.front() == '[' ? "" : ".") + level.component;
    return path + (path.empty() ? "" : ".") + key;
  };
  const auto nextComponent = [&levels]() -> std::string {
    if (levels.empty()) return "";
    Level& parent = levels.back();
    return parent.isArray ? "[" + std::to_string(parent.elements++) + "]" : parent.pendingKey;
  };
  const json::parser_callback_t noticeDuplicates = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start: {
        Level level;
        level.isArray = event == json::parse_event_t::array_start;
        level.component = nextComponent();
        levels.push_back(std::move(level));
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        if (!levels.empty()) levels.pop_back();
        break;
      case json::parse_event_t::key:
        if (!levels.empty()) {
          const std::string key = parsed.get<std::string>();
          levels.back().pendingKey = key;
          if (!levels.back().keys.insert(key).second)
            duplicates.push_back({pathTo(key), "appears twice in one object; expected each key once (the later one "
                                               "would silently replace the earlier)"});
        }
        break;
      case json::parse_event_t::value:
        if (!levels.empty() && levels.back().isArray) ++levels.back().elements;
        break;
    }
    return true;
  };
  try {
    document = json::parse(text, noticeDuplicates);
  } catch (const json::exception& error) {
    // nlohmann says "parse error at line L, column C: ..." (or "number overflow parsing '1e999'"): keep
    // that, drop its "[json.exception...]" tag, and add the JSON path where reading stopped.
    std::string message = error.what();
    if (const size_t tag = message.find("] "); tag != std::string::npos) message = message.substr(tag + 2);
    if (message.find("overflow") != std::string::npos) message += " (numbers must be finite doubles)";
    throw SceneError(file, {{jsonPathOfParseError(text), "malformed JSON: " + message}});
  }

  std::vector<SceneProblem> problems = std::move(duplicates);
  applySceneOverrides(document, overrides, problems);
  Scene scene;
  scene.file = file;
  scene.identity = text;
  for (const std::string& assignment : overrides) scene.identity += "\n--set " + assignment;
  const JsonObject top(document, "", problems);
  if (!top.isObject()) throw SceneError(file, problems);

  scene.name = top.string("name", true).value_or("");
  if (top.has("name") && !isSafeName(scene.name)) {
    // Quoted as JSON (a NUL or control byte escaped, invalid UTF-8 replaced), so the whole message reaches a
    // terminal.
    top.report("name", "found " + json(scene.name).dump(-1, ' ', false, json::error_handler_t::replace) +
                           "; expected " + expectedWords(sceneKey("name")));
  }
  scene.title = top.string("title").value_or(scene.name);
  scene.shortTitle = top.string("short_title").value_or("");
  for (const auto& [key, text] : {std::pair{"title", &scene.title}, std::pair{"short_title", &scene.shortTitle}})
    if (const std::size_t characters = codePoints(*text); characters > std::size_t(limits::kMaxTitleCharacters))
      top.report(key, "found " + std::to_string(characters) + " characters; expected at most " +
                          std::to_string(limits::kMaxTitleCharacters) + " (a title is one line of a frame)");
  // Left out, the duration is the longest found motion's (when every run starts from one: checked below).
  scene.durationFromMotions = !top.has("duration");
  if (const auto duration = top.number("duration"); duration && top.checkPositive("duration", *duration)) {
    scene.duration = *duration;
  }
  RodCount rods;
  if (top.has("linkage"))
    rods = readLinkage(*top.member("linkage"), "linkage", std::nullopt, false, scene.chain, problems);
  else
    top.reportMissing("linkage", "an object with rods and L");
  if (top.has("initial"))
    readInitial(*top.member("initial"), "initial", rods, scene.initial, problems);
  else
    top.reportMissing("initial", "an object with coords and velocity, or drag");
  readRuns(top.member("runs"), scene, rods, problems);
  if (scene.durationFromMotions &&
      (scene.runs.empty() ||
       !std::all_of(scene.runs.begin(), scene.runs.end(), [](const RunSpec& run) { return run.initial.namesAMotion(); }))) {
    top.reportMissing("duration", "the simulated time in seconds (it may be left out only when every run starts from "
                                  "a connect or periodic motion)");
    scene.durationFromMotions = false;
  }
  readOutput(top.has("output") ? *top.member("output") : json::object(), scene, problems);
  if (!scene.durationFromMotions)
    for (SceneProblem& problem : checkFrameCount(scene.duration, scene.output.fps)) problems.push_back(problem);
  detail::readView(top.has("view") ? *top.member("view") : json::object(), scene, rods.has_value(), problems);

  // Measured on a valid scene only, and once its duration is known (checkResolvedDuration otherwise).
  if (problems.empty() && !scene.durationFromMotions) problems = checkSceneCost(scene);
  if (!problems.empty()) throw SceneError(file, std::move(problems));
  scene.title = fillTitlePlaceholders(scene.title, scene);
  scene.shortTitle = fillTitlePlaceholders(scene.shortTitle, scene);
  for (const auto& [key, text] : {std::pair{"title", &scene.title}, std::pair{"short_title", &scene.shortTitle}})
    if (const std::size_t characters = codePoints(*text); characters > std::size_t(limits::kMaxTitleCharacters))
      problems.push_back({key, "with its placeholders filled in, found " + std::to_string(characters) +
                                   " characters; expected at most " + std::to_string(limits::kMaxTitleCharacters)});
  if (!problems.empty()) throw SceneError(file, std::move(problems));
  return scene;
}

std::vector<SceneProblem> checkResolvedDuration(const Scene& scene) {
  std::vector<SceneProblem> problems = checkFrameCount(scene.duration, scene.output.fps);
  for (std::size_t i = 0; i < scene.runs.size(); ++i) {
    const RunConfig& config = scene.runs[i].config;
    if (!traits(config.integrator).adaptive && config.step > scene.duration) {
      std::ostringstream message;
      message << "found " << config.step << "; expected a step no longer than the duration " << scene.duration
              << " (the longest found motion's time)";
      problems.push_back({indexPath("runs", i) + ".step", message.str()});
    }
  }
  if (problems.empty()) problems = checkSceneCost(scene);
  return problems;
}

Scene loadScene(const std::string& file, const std::vector<std::string>& overrides) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) throw SceneError(file, {{"", "cannot open the file for reading"}});
  // Read once (it may be a pipe), and never more than a scene can sensibly be.
  std::string text(limits::kMaxSceneBytes + 1, '\0');
  stream.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (stream.bad()) throw SceneError(file, {{"", "cannot read the file"}});
  text.resize(static_cast<std::size_t>(stream.gcount()));
  if (text.size() > limits::kMaxSceneBytes)
    throw SceneError(file, {{"", "larger than " + std::to_string(limits::kMaxSceneBytes >> 20) +
                                     " MiB; a scene file is a few kilobytes"}});
  return parseScene(text, file, overrides);
}

}  // namespace sl

#include "scene/scene_schema.hpp"

#include <string>

#include "contracts/limits.hpp"
#include "contracts/registry.hpp"
#include "scene/output_folder.hpp"

namespace sl {
namespace {

using nlohmann::json;

template <class Table>
json oneOfNames(const Table& table, const std::string& description) {
  json names = json::array();
  for (const auto& entry : table) names.push_back(std::string(entry.name));
  return {{"enum", names}, {"description", description}};
}

// An object whose keys are exactly `properties` (as the loader refuses unknown keys).
json closedObject(json properties, const std::string& description, json required = json::array()) {
  json object{{"type", "object"},
              {"description", description},
              {"properties", std::move(properties)},
              {"additionalProperties", false}};
  if (!required.empty()) object["required"] = std::move(required);
  return object;
}

json positive(const std::string& description) {
  return {{"type", "number"}, {"exclusiveMinimum", 0}, {"description", description}};
}
json numbers(const std::string& description, double minimum = -1e308, double maximum = 1e308) {
  json items{{"type", "number"}};
  if (minimum > -1e308) items["minimum"] = minimum;
  if (maximum < 1e308) items["maximum"] = maximum;
  return {{"type", "array"}, {"items", items}, {"description", description}};
}
json fixedNumbers(int count, double minimum, double maximum, const std::string& description) {
  return {{"type", "array"},
          {"items", {{"type", "number"}, {"minimum", minimum}, {"maximum", maximum}}},
          {"minItems", count},
          {"maxItems", count},
          {"description", description}};
}
json integer(long minimum, long maximum, const std::string& description) {
  return {{"type", "integer"}, {"minimum", minimum}, {"maximum", maximum}, {"description", description}};
}
json text(const std::string& description) { return {{"type", "string"}, {"description", description}}; }
json flag(const std::string& description) { return {{"type", "boolean"}, {"description", description}}; }

json points(const std::string& description) {
  return {{"type", "array"},
          {"items", {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 2}, {"maxItems", 2}}},
          {"description", description}};
}

json linkageSchema(bool forRun) {
  json properties{{"rods", integer(limits::kMinRods, limits::kMaxAmbientRods, forRun ? "the scene's n (a run cannot change it)"
                                                                            : "n, unit rods")},
                  {"L", positive("distance between the pins, 0 < L < n (L <= n-2: a slack chain, ambient method)")},
                  {"hinge_masses", numbers("n-1 point masses at the interior hinges", 0, limits::kMaxMass)},
                  {"rod_masses", numbers("n uniform rod masses", 0, limits::kMaxMass)}};
  if (forRun) return closedObject(properties, "this run's own L and masses (default: the scene's linkage)");
  return closedObject(properties, "the chain", json::array({"rods", "L"}));
}

json initialSchema(const std::string& description) {
  return closedObject(
      {{"coords", numbers("start in the spec's chart, n-2 numbers")},
       {"velocity", numbers("chart velocity, n-2 numbers")},
       {"drag", closedObject({{"point", numbers("a point of R^(n-1)")},
                              {"direction", numbers("a release direction in R^(n-1)")}},
                             "start as the spec's demo", json::array({"point", "direction"}))},
       {"unit_speed", flag("rescale the velocity to kinetic energy 1/2")},
       {"hinges", {{"oneOf", json::array({{{"enum", json::array({"arc"})}}, points("n-1 hinge positions [x, y]")})},
                   {"description", "a start by hinges (ambient method): \"arc\" or the positions"}}},
       {"velocities", points("n-1 hinge velocities [vx, vy]")},
       {"push", closedObject({{"hinge", integer(1, limits::kMaxAmbientRods - 1, "the hinge pushed")},
                              {"velocity", fixedNumbers(2, -1e6, 1e6, "its velocity [vx, vy]")},
                              {"seed", integer(0, 9223372036854775807L, "a random push: its seed")},
                              {"size", positive("a random push: its size")}},
                             "instead of velocities: one hinge pushed, or every hinge at random")}},
      description);
}

json runSchema() {
  return closedObject(
      {{"name", {{"type", "string"}, {"minLength", 1}, {"description", "shown in panels and plots, unique"}}},
       {"method", oneOfNames(kMethods, "geodesic method (linkage list-methods)")},
       {"integrator", oneOfNames(kIntegrators, "integrator (linkage list-methods)")},
       {"tolerance",
        {{"type", "number"},
         {"minimum", limits::kMinTolerance},
         {"maximum", limits::kMaxTolerance},
         {"description", "adaptive integrators only"}}},
       {"step", positive("fixed-step integrators only; at most the duration")},
       {"color", fixedNumbers(3, 0, 1, "[r, g, b] in 0..1")},
       {"watchdog", closedObject({{"max_energy_drift", positive("stop when |E - E0| / E0 exceeds this")},
                                  {"max_rod_length_error", positive("stop when a rod length is off by more")},
                                  {"max_steps", positive("bound on the work of a run")}},
                                 "limits that stop a run")},
       {"linkage", linkageSchema(true)},
       {"jacobi", flag("carry the Jacobi fields and find conjugate points (ambient method)")},
       {"family", closedObject({{"kind", oneOfNames(kFamilyKinds, "fan, parallel or cloud")},
                                {"count", integer(2, limits::kMaxFamilyMembers, "members beside the run")},
                                {"spread", {{"type", "number"},
                                            {"exclusiveMinimum", 0},
                                            {"maximum", limits::kMaxFamilySpread},
                                            {"description", "fan: whole angle (radians); parallel: width"}}},
                                {"epsilon", {{"type", "number"},
                                             {"exclusiveMinimum", 0},
                                             {"maximum", limits::kMaxCloudEpsilon},
                                             {"description", "cloud: perturbation size"}}},
                                {"seed", integer(0, 9223372036854775807L, "cloud: random seed")}},
                               "a family of geodesics around the run", json::array({"kind"}))},
       {"initial", initialSchema("this run's own start (default: the scene's initial)")}},
      "one run: a method and integrator from the scene's start (or its own)", json::array({"name"}));
}

json panelSchema() {
  return {{"oneOf",
           json::array({oneOfNames(kPanelKinds, "a panel by kind"),
                        closedObject({{"panel", oneOfNames(kPanelKinds, "panel kind")},
                                      {"plot", oneOfNames(kPlotKinds, "what a plot panel shows")},
                                      {"scale", {{"enum", json::array({"log", "linear"})}}},
                                      {"rect", fixedNumbers(4, 0, 1, "[x, y, width, height] as fractions")},
                                      {"y_range", fixedNumbers(2, -1e308, 1e308, "[lowest, highest] of the y axis")}},
                                     "a panel with options", json::array({"panel"}))})}};
}

json viewSchema() {
  return closedObject(
      {{"panels", {{"type", "array"}, {"minItems", 1}, {"items", panelSchema()}, {"description", "layout order"}}},
       {"camera", closedObject({{"direction", fixedNumbers(3, -1e308, 1e308, "from the centre towards the eye")},
                                {"orbit_degrees_per_second",
                                 {{"type", "number"},
                                  {"minimum", -limits::kMaxOrbitDegreesPerSecond},
                                  {"maximum", limits::kMaxOrbitDegreesPerSecond},
                                  {"description", "slow orbit about the vertical axis"}}},
                                {"field_of_view",
                                 {{"type", "number"},
                                  {"minimum", limits::kMinFieldOfViewDegrees},
                                  {"maximum", limits::kMaxFieldOfViewDegrees}}}},
                               "the sphere panel's camera")},
       {"linkage_layout", oneOfNames(kLinkageLayouts, "how the linkage panel shows the runs")},
       {"linkage_run", text("the run the single layout shows")},
       {"trails",
        {{"type", "array"},
         {"items", {{"type", "integer"}, {"minimum", 1}}},
         {"maxItems", limits::kMaxTrails},
         {"description", "hinges with trails"}}},
       {"trail_fade_seconds",
        {{"type", "number"},
         {"exclusiveMinimum", 0},
         {"maximum", limits::kMaxTrailFadeSeconds},
         {"description", "how long a trail stays visible"}}},
       {"path_fade_seconds", {{"type", "number"}, {"minimum", 0}, {"description", "0 = never fades"}}},
       {"path_samples_per_frame", integer(1, limits::kMaxPathSamplesPerFrame, "sphere-path points per frame")},
       {"background", fixedNumbers(3, 0, 1, "[r, g, b] in 0..1")},
       {"antialias", flag("analytic anti-aliasing")},
       {"title_line", flag("title and time across the top when there is no text panel (default true)")},
       {"sphere", closedObject({{"color_by", oneOfNames(kSphereColorings, "colour the sphere (4 rods)")},
                                {"stiffness", flag("stiffness ellipses (4 rods)")}},
                               "the sphere panel's surface")}},
      "how the frames look");
}

}  // namespace

json sceneSchema() {
  return {
      {"$schema", "https://json-schema.org/draft/2020-12/schema"},
      {"$id", "https://github.com/sphere-linkages/sphere-linkages/scenes/scene.schema.json"},
      {"title", "sphere-linkages scene"},
      {"description", "A scene file of the linkage command (scenes/README.md). Generated by `linkage schema`."},
      {"type", "object"},
      {"additionalProperties", false},
      {"required", json::array({"name", "linkage", "initial", "duration", "runs"})},
      {"properties",
       {{"name", {{"type", "string"}, {"pattern", "^[A-Za-z0-9._-]+$"}, {"description", "names renders/<name>"}}},
        {"title", text("shown in the frames")},
        {"linkage", linkageSchema(false)},
        {"initial", initialSchema("where the motion starts: coords and velocity, or drag")},
        {"duration", positive("simulated time")},
        {"runs", {{"type", "array"}, {"minItems", 1}, {"items", runSchema()}}},
        {"output", closedObject({{"fps", integer(1, limits::kMaxFps, "frames per simulated second")},
                                 {"width", integer(limits::kMinImageSide, limits::kMaxImageSide, "pixels")},
                                 {"height", integer(limits::kMinImageSide, limits::kMaxImageSide, "pixels")},
                                 {"folder", {{"type", "string"}, {"minLength", 1}}},
                                 {"png", flag("write PNG frames")},
                                 {"png_compression", oneOfNames(kPngCompressions, "PNG speed against size")},
                                 {"video", {{"type", "string"}, {"pattern", "^$|\\.([Mm][Pp]4|[Ww][Ee][Bb][Mm]|[Gg][Ii][Ff])$"}}},
                                 {"video_quality", oneOfNames(kVideoQualities, "video size against quality")}},
                                "what is written")},
        {"view", viewSchema()}}}};
}

}  // namespace sl

// The "view" section: panels, camera, linkage layout, trails and fades, mapped onto ViewSettings.

#include <algorithm>
#include <cmath>

#include "contracts/csv_format.hpp"
#include "contracts/limits.hpp"
#include "scene/did_you_mean.hpp"
#include "scene/json_fields.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_sections.hpp"

namespace sl::detail {

using nlohmann::json;

namespace {}  // namespace

void reportUnknownName(const std::string& path, const std::string& word, const std::vector<std::string>& names,
                       std::vector<SceneProblem>& problems) {
  std::string allowed;
  for (const std::string& name : names) allowed += allowed.empty() ? name : ", " + name;
  problems.push_back({path, "found \"" + word + "\"" + didYouMean(word, names) + "; expected one of " + allowed});
}

namespace {

// "scale" of a plot: logarithmic or linear y axis.
constexpr std::array<Named<bool>, 2> kPlotScales{{{true, "log"}, {false, "linear"}}};

// A plot with no kind given: divergence needs two runs to compare, otherwise the energy error.
PlotSpec defaultPlot(const Scene& scene) {
  return {scene.runs.size() >= 2 ? PlotKind::Divergence : PlotKind::EnergyError, true, std::nullopt};
}

// A chain with no configuration sphere among the scene's and its runs' (judged only once n is known).
bool hasSlackChain(const Scene& scene, bool rodsKnown) {
  return rodsKnown && (scene.chain.isSlack() || std::any_of(scene.runs.begin(), scene.runs.end(),
                                                            [](const RunSpec& run) { return run.chain.isSlack(); }));
}

void addPanel(const json& value, const std::string& path, Scene& scene, bool rodsKnown,
              std::vector<SceneProblem>& problems) {
  PanelSpec panel;
  PlotSpec plot = defaultPlot(scene);
  std::optional<PanelKind> kind;
  if (value.is_string()) {
    kind = pickKind(path, value.get<std::string>(), kPanelKinds, problems);
  } else {
    const JsonObject object(value, path, problems);
    if (!object.isObject()) return;
    if (const auto name = object.string("panel", true))
      kind = pickKind(object.pathOf("panel"), *name, kPanelKinds, problems);
    if (const auto name = object.string("plot")) {
      if (const auto plotKind = pickKind(object.pathOf("plot"), *name, kPlotKinds, problems)) plot.kind = *plotKind;
      // A Jacobi field's zeros and a curvature's or an angle's sign need a linear axis.
      plot.logY = plot.kind != PlotKind::Jacobi && plot.kind != PlotKind::Sectional && plot.kind != PlotKind::Holonomy;
    }
    if (const auto scale = object.string("scale")) {
      plot.logY = pickKind(object.pathOf("scale"), *scale, kPlotScales, problems).value_or(true);
    }
    if (const auto range = object.numbers("y_range");
        range && object.checkSize("y_range", *range, 2, "the lowest and highest value of the y axis")) {
      if (!((*range)(0) < (*range)(1)))
        object.report("y_range", "expected the lowest value first, below the highest");
      else if (plot.logY && !((*range)(0) > 0))
        object.report("y_range", "expected positive values on a log axis (\"scale\": \"log\")");
      plot.yRange = std::array<double, 2>{(*range)(0), (*range)(1)};
    }
    if (const auto rect = object.numbers("rect");
        rect && object.checkSize("rect", *rect, 4, "x, y, width, height as fractions")) {
      if (rect->minCoeff() < 0 || rect->maxCoeff() > 1 || (*rect)(2) <= 0 || (*rect)(3) <= 0 ||
          (*rect)(0) + (*rect)(2) > 1 + 1e-9 || (*rect)(1) + (*rect)(3) > 1 + 1e-9) {
        object.report("rect", "expected fractions of the frame from 0 to 1, with positive width and height, inside "
                              "the frame (x + width and y + height at most 1)");
      }
      panel.rect = std::array<double, 4>{(*rect)(0), (*rect)(1), (*rect)(2), (*rect)(3)};
    }
  }
  if (!kind) return;
  panel.kind = *kind;
  if (panel.kind == PanelKind::Sphere && hasSlackChain(scene, rodsKnown))
    problems.push_back({path, "a slack chain (L <= n-2) has no configuration sphere to draw; expected linkage, plot "
                              "or text panels"});
  if (panel.kind == PanelKind::Plot) {
    if (plot.kind == PlotKind::Divergence && scene.runs.size() < 2) {
      problems.push_back({path, "a divergence plot compares runs; expected at least 2 runs, found " +
                                    std::to_string(scene.runs.size())});
    }
    const bool anyJacobi =
        std::any_of(scene.runs.begin(), scene.runs.end(), [](const RunSpec& run) { return run.config.jacobi; });
    if (plot.kind == PlotKind::Jacobi && !anyJacobi)
      problems.push_back({path, "a jacobi plot shows Jacobi fields; expected a run with \"jacobi\": true"});
    const bool anyFamily =
        std::any_of(scene.runs.begin(), scene.runs.end(), [](const RunSpec& run) { return run.family.has_value(); });
    if (plot.kind == PlotKind::Spread && !anyFamily)
      problems.push_back({path, "a spread plot shows how families spread; expected a run with a \"family\""});
    if (plot.kind == PlotKind::Sectional && rodsKnown && scene.chain.rods < 5)
      problems.push_back({path, "a sectional plot shows the curvature of the planes of S^3 and larger; expected 5 rods "
                                "or more, found " + std::to_string(scene.chain.rods) +
                                " (for 4 rods every plane has the Gaussian curvature: view.sphere.color_by)"});
    panel.plotIndex = static_cast<int>(scene.view.plots.size());
    scene.view.plots.push_back(plot);
  }
  scene.view.panels.push_back(panel);
}

void readPanels(const JsonObject& view, Scene& scene, bool rodsKnown, std::vector<SceneProblem>& problems) {
  const json* panels = view.member("panels");
  if (panels == nullptr) {
    // A slack chain has no sphere: its linkage alone.
    const bool slack = hasSlackChain(scene, rodsKnown);
    for (const char* name : {"sphere", "linkage"})
      if (!(slack && std::string(name) == "sphere")) addPanel(json(name), "view.panels", scene, rodsKnown, problems);
    return;
  }
  if (!panels->is_array() || panels->empty()) {
    view.report("panels", "found " + describeJson(*panels) + "; expected a non-empty array of panels");
    return;
  }
  for (size_t i = 0; i < panels->size(); ++i) addPanel((*panels)[i], indexPath("view.panels", i), scene, rodsKnown, problems);
}

void readCamera(const JsonObject& view, CameraSpec& camera, std::vector<SceneProblem>& problems) {
  const JsonObject object(*view.member("camera"), view.pathOf("camera"), problems);
  if (const auto direction = object.numbers("direction");
      direction && object.checkSize("direction", *direction, 3, "x, y, z towards the eye")) {
    // Only the direction counts: brought to size 1 by its largest component, so [1e300, 1e300, 1e300] (whose
    // length overflows) and [1e-300, 0, 0] are directions like any other.
    const double largest = direction->cwiseAbs().maxCoeff();
    if (largest == 0) object.report("direction", "found the zero vector; expected a direction");
    const Eigen::VectorXd unit = largest > 0 ? Eigen::VectorXd(*direction / largest) : *direction;
    camera.viewDirection = {unit(0), unit(1), unit(2)};
  }
  if (const auto orbit = object.number("orbit_degrees_per_second");
      orbit && object.checkBounds("orbit_degrees_per_second", *orbit)) {
    camera.orbitDegreesPerSecond = *orbit;
  }
  if (const auto fov = object.number("field_of_view"); fov && object.checkBounds("field_of_view", *fov)) {
    camera.fieldOfViewDegrees = *fov;
  }
  // The mode: as asked; else a scene that fixes a direction or an orbit keeps it, and the rest are directed.
  const bool orbits = camera.orbitDegreesPerSecond != 0;
  camera.mode = orbits ? CameraMode::Orbit : object.has("direction") ? CameraMode::Fixed : CameraMode::Directed;
  if (const auto name = object.string("mode")) {
    if (const auto mode = pickKind(object.pathOf("mode"), *name, kCameraModes, problems)) {
      camera.mode = *mode;
      if (*mode == CameraMode::Orbit && !orbits)
        object.report("mode", "found \"orbit\" without orbit_degrees_per_second; expected a non-zero orbit rate");
      if (*mode != CameraMode::Orbit && orbits)
        object.report("orbit_degrees_per_second", "found an orbit rate with mode \"" + *name +
                                                      "\"; expected mode \"orbit\" (or no rate)");
    }
  }
}

void readLinkageChoice(const JsonObject& view, Scene& scene, std::vector<SceneProblem>& problems) {
  if (const auto layout = view.string("linkage_layout")) {
    if (const auto kind = pickKind(view.pathOf("linkage_layout"), *layout, kLinkageLayouts, problems))
      scene.view.linkageLayout = *kind;
  }
  if (const auto run = view.string("linkage_run")) {
    std::vector<std::string> names;
    for (const RunSpec& spec : scene.runs) names.push_back(spec.name);
    const auto found = std::find(names.begin(), names.end(), *run);
    if (found == names.end()) reportUnknownName(view.pathOf("linkage_run"), *run, names, problems);
    scene.view.linkageRun = found == names.end() ? 0 : static_cast<int>(found - names.begin());
  }
}

void readTrails(const JsonObject& view, Scene& scene, bool rodsKnown) {
  const auto hinges = view.numbers("trails");
  if (!hinges) return;
  if (const double most = sceneKey(view.pathOf("trails")).maximum; hinges->size() > most) {
    view.report("trails", "found " + std::to_string(hinges->size()) + " hinges; expected at most " +
                              std::to_string(static_cast<long>(most)) + " (each trail is drawn and kept per frame)");
    return;
  }
  // While n is unknown (an invalid "rods") only the form is checked: the largest hinge number depends on n.
  const double count = rodsKnown ? scene.chain.hingeCount() : double(limits::kMaxAmbientRods - 1);
  for (Eigen::Index i = 0; i < hinges->size(); ++i) {
    const double hinge = (*hinges)(i);
    // Range first: converting a double beyond int's range to int is undefined behaviour.
    if (!(hinge >= 1 && hinge <= count) || hinge != std::floor(hinge)) {
      view.report("trails", "found " + shortest(hinge) + "; expected hinge numbers from 1 to n-1" +
                                (rodsKnown ? " = " + std::to_string(scene.chain.hingeCount()) : ""));
      return;
    }
    scene.view.trailHinges.push_back(static_cast<int>(hinge));
  }
}

void readFades(const JsonObject& view, Scene& scene) {
  ViewSettings& render = scene.view;
  if (const auto fade = view.number("path_fade_seconds");
      fade && view.checkBounds("path_fade_seconds", *fade)) {
    render.pathFadeSeconds = *fade;
  }
  if (const auto fade = view.number("trail_fade_seconds");
      fade && view.checkPositive("trail_fade_seconds", *fade) && view.checkBounds("trail_fade_seconds", *fade)) {
    render.trailFadeSeconds = *fade;
  }
  if (const auto samples = view.integer("path_samples_per_frame")) {
    if (view.checkBounds("path_samples_per_frame", *samples))
      scene.view.pathSamplesPerFrame = static_cast<int>(*samples);
  }
}

// "sphere": how the sphere panel's surface is coloured and decorated. The geometry behind it (curvature,
// bending, stiffness; docs/geometry.md) is that of a surface, so 4 rods only.
void readSphereSurface(const JsonObject& view, Scene& scene, bool rodsKnown, std::vector<SceneProblem>& problems) {
  const JsonObject object(*view.member("sphere"), view.pathOf("sphere"), problems);
  if (!object.isObject()) return;
  SphereSurfaceSpec& surface = scene.view.sphereSurface;
  if (const auto name = object.string("color_by")) {
    if (const auto kind = pickKind(object.pathOf("color_by"), *name, kSphereColorings, problems))
      surface.colorBy = *kind;
  }
  surface.stiffness = object.boolean("stiffness").value_or(surface.stiffness);
  surface.seam = object.boolean("seam").value_or(surface.seam);
  surface.closedGeodesics = object.boolean("closed_geodesics").value_or(surface.closedGeodesics);
  scene.distanceFrom.reset();
  if (object.has("distance_from")) {
    const nlohmann::json& from = *object.member("distance_from");
    if (surface.colorBy != SphereColoring::Distance)
      object.report("distance_from", "is measured only for the distance colouring; expected color_by \"distance\" "
                                     "with it");
    else if (from.is_object())
      scene.distanceFrom = readConfiguration(object, "distance_from", rodsKnown ? std::optional<int>(scene.chain.rods)
                                                                                : std::nullopt, problems);
    else if (!from.is_string() || from.get<std::string>() != "start")
      object.report("distance_from", "found " + from.dump() + "; expected \"start\" or a configuration: "
                                     "{\"coords\": [...]} (chart 0, n-2 numbers) or {\"hinges\": [[x, y], ...]} "
                                     "(n-1 points)");
  }
  scene.holonomyCorners.clear();
  surface.holonomy = false;
  if (object.has("holonomy")) {
    const JsonObject holonomy(*object.member("holonomy"), object.pathOf("holonomy"), problems);
    const nlohmann::json* corners = holonomy.isObject() ? holonomy.member("corners") : nullptr;
    if (holonomy.isObject() && !corners) {
      holonomy.reportMissing("corners", "a list of at least 3 configurations, the corners of a geodesic polygon");
    } else if (corners && (!corners->is_array() || corners->size() < 3)) {
      holonomy.report("corners", "found " + describeJson(*corners) + "; expected a list of at least 3 "
                                 "configurations, the corners of a geodesic polygon");
    } else if (corners) {
      const std::optional<int> rods = rodsKnown ? std::optional<int>(scene.chain.rods) : std::nullopt;
      for (std::size_t i = 0; i < corners->size(); ++i)
        scene.holonomyCorners.push_back(
            readConfigurationObject(JsonObject((*corners)[i], indexPath(holonomy.pathOf("corners"), i), problems), rods));
      surface.holonomy = true;
    }
  }
  auto reset = [&] {
    surface = {};
    scene.distanceFrom.reset();
    scene.holonomyCorners.clear();
  };
  if (rodsKnown && scene.chain.isSlack() && surface.decorated()) {
    object.report(surface.colorBy != SphereColoring::None ? "color_by"
                  : surface.stiffness                      ? "stiffness"
                  : surface.seam                           ? "seam"
                  : surface.holonomy                       ? "holonomy"
                                                           : "closed_geodesics",
                  "a slack chain (L <= n-2) has no configuration sphere to colour or decorate");
    reset();
  }
  if (rodsKnown && scene.chain.rods != 4 && surface.decorated()) {
    const std::string why = "found " + std::to_string(scene.chain.rods) +
                            " rods; curvature, bending, distance, stiffness and closed geodesics are drawn for 4 "
                            "rods only (the configuration space is then a surface, S^2)";
    if (surface.colorBy != SphereColoring::None) object.report("color_by", why);
    if (surface.stiffness) object.report("stiffness", why);
    if (surface.seam) object.report("seam", why);
    if (surface.closedGeodesics) object.report("closed_geodesics", why);
    if (surface.holonomy)
      object.report("holonomy", "found " + std::to_string(scene.chain.rods) +
                                    " rods; the holonomy of a loop is drawn for 4 rods only (for more rods: "
                                    "linkage geometry --sectional)");
    reset();
  }
}

}  // namespace

void readView(const json& value, Scene& scene, bool rodsKnown, std::vector<SceneProblem>& problems) {
  const JsonObject view(value, "view", problems);
  if (!view.isObject()) return;
  ViewSettings& render = scene.view;
  readPanels(view, scene, rodsKnown, problems);
  if (view.has("camera")) readCamera(view, render.camera, problems);
  if (view.has("sphere")) readSphereSurface(view, scene, rodsKnown, problems);
  for (std::size_t i = 0; i < render.panels.size(); ++i) {  // in file order (a panel read wrong is reported already)
    const PanelSpec& panel = render.panels[i];
    if (panel.kind == PanelKind::Plot && render.plots.at(std::size_t(panel.plotIndex)).kind == PlotKind::Holonomy &&
        !render.sphereSurface.holonomy)
      problems.push_back({indexPath("view.panels", i) + ".plot",
                          "a holonomy plot shows the curvature a polygon's sides sweep; expected "
                          "view.sphere.holonomy with its corners"});
  }
  readLinkageChoice(view, scene, problems);
  readTrails(view, scene, rodsKnown);
  readFades(view, scene);
  if (const auto theme = view.string("theme")) {
    if (const auto kind = pickKind(view.pathOf("theme"), *theme, kThemes, problems)) {
      render.theme = *kind;
      render.background = themeBackground(*kind);  // the scene's own background, read next, wins
    }
  }
  if (const auto rgb = view.numbers("background"); rgb && view.checkSize("background", *rgb, 3, "red, green, blue")) {
    view.checkElements("background", *rgb);
    render.background = {float((*rgb)(0)), float((*rgb)(1)), float((*rgb)(2))};
  }
  render.antialias = view.boolean("antialias").value_or(render.antialias);
  render.titleLine = view.boolean("title_line").value_or(render.titleLine);
}

}  // namespace sl::detail

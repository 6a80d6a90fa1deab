// Every bound a scene key has, at its exact boundary from both sides: the value on the bound is accepted,
// the next representable step beyond it is refused under that key's JSON path. A bound moved off its place
// (1000 rods refused, a push bound raised tenfold, an inclusive bound made exclusive) fails here.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "contracts/limits.hpp"
#include "scene/scene_loader.hpp"

namespace sl {
namespace {

using nlohmann::json;

json baseScene() {
  return json::parse(R"({"name": "bounds", "linkage": {"rods": 4, "L": 3},
      "initial": {"coords": [0.1, 0.2], "velocity": [1, 0]}, "duration": 1,
      "runs": [{"name": "r", "method": "ambient"}]})");
}

// The problems the loader reports for `scene`, or none.
std::vector<SceneProblem> problemsOf(const json& scene) {
  try {
    parseScene(scene.dump(), "bounds.json");
  } catch (const SceneError& error) {
    return error.problems();
  }
  return {};
}

// `scene` with `value` at the JSON pointer `pointer` is accepted.
void expectAccepted(json scene, const std::string& pointer, const json& value) {
  scene[json::json_pointer(pointer)] = value;
  const std::vector<SceneProblem> problems = problemsOf(scene);
  EXPECT_TRUE(problems.empty()) << pointer << " = " << value.dump() << ": "
                                << (problems.empty() ? "" : problems[0].jsonPath + ": " + problems[0].message);
}

// `scene` with `value` at `pointer` is refused, the first problem naming `path`.
void expectRefused(json scene, const std::string& pointer, const json& value, const std::string& path) {
  scene[json::json_pointer(pointer)] = value;
  const std::vector<SceneProblem> problems = problemsOf(scene);
  ASSERT_FALSE(problems.empty()) << pointer << " = " << value.dump() << " was accepted";
  EXPECT_EQ(problems[0].jsonPath, path) << problems[0].message;
}

double above(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }
double below(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }

// A chain of n rods at L = n - 1 started in the chart at its origin (the chart's dimension is n - 2).
json chainOf(int rods, const std::string& method) {
  json scene = baseScene();
  scene["linkage"] = {{"rods", rods}, {"L", rods - 1}};
  scene["initial"] = {{"coords", std::vector<double>(rods - 2, 0.1)}, {"velocity", std::vector<double>(rods - 2, 0)}};
  scene["initial"]["velocity"][0] = 1;
  scene["runs"][0]["method"] = method;
  return scene;
}

TEST(LimitBoundaries, RodCounts) {
  expectAccepted(chainOf(limits::kMinRods, "ambient"), "/linkage/rods", limits::kMinRods);
  expectRefused(baseScene(), "/linkage/rods", limits::kMinRods - 1, "linkage.rods");
  expectAccepted(chainOf(limits::kMaxAmbientRods, "ambient"), "/linkage/rods", limits::kMaxAmbientRods);
  expectRefused(chainOf(limits::kMaxAmbientRods + 1, "ambient"), "/linkage/rods", limits::kMaxAmbientRods + 1,
                "linkage.rods");
  // The chart methods up to kMaxRods, inclusive.
  expectAccepted(chainOf(limits::kMaxRods, "christoffel"), "/linkage/rods", limits::kMaxRods);
  const std::vector<SceneProblem> beyond = problemsOf(chainOf(limits::kMaxRods + 1, "christoffel"));
  ASSERT_FALSE(beyond.empty()) << limits::kMaxRods + 1 << " rods with christoffel were accepted";
  EXPECT_EQ(beyond[0].jsonPath, "runs[0].method") << beyond[0].message;
}

TEST(LimitBoundaries, Masses) {
  for (const char* key : {"/linkage/hinge_masses", "/linkage/rod_masses"}) {
    const std::size_t count = std::string(key) == "/linkage/hinge_masses" ? 3 : 4;
    std::vector<double> masses(count, 1.0);
    masses[1] = limits::kMaxMass;
    expectAccepted(baseScene(), key, masses);
    masses[1] = above(limits::kMaxMass);
    expectRefused(baseScene(), key, masses, std::string("linkage.") + (std::string(key).substr(9)));
  }
}

TEST(LimitBoundaries, OutputRates) {
  expectAccepted(baseScene(), "/output/fps", limits::kMaxFps);
  expectRefused(baseScene(), "/output/fps", limits::kMaxFps + 1, "output.fps");
  expectAccepted(baseScene(), "/output/fps", 1);
  expectRefused(baseScene(), "/output/fps", 0, "output.fps");
  // The frame count: frames k = 0..ceil(duration * fps), at most kMaxFrames of them.
  json scene = baseScene();
  scene["output"]["fps"] = 1000;
  expectAccepted(scene, "/duration", double(limits::kMaxFrames - 1) / 1000);
  expectRefused(scene, "/duration", double(limits::kMaxFrames) / 1000, "duration");
}

TEST(LimitBoundaries, ViewBounds) {
  expectAccepted(baseScene(), "/view/camera/orbit_degrees_per_second", limits::kMaxOrbitDegreesPerSecond);
  expectAccepted(baseScene(), "/view/camera/orbit_degrees_per_second", -limits::kMaxOrbitDegreesPerSecond);
  expectRefused(baseScene(), "/view/camera/orbit_degrees_per_second", above(limits::kMaxOrbitDegreesPerSecond),
                "view.camera.orbit_degrees_per_second");
  expectRefused(baseScene(), "/view/camera/orbit_degrees_per_second", below(-limits::kMaxOrbitDegreesPerSecond),
                "view.camera.orbit_degrees_per_second");
  expectAccepted(baseScene(), "/view/camera/field_of_view", limits::kMinFieldOfViewDegrees);
  expectAccepted(baseScene(), "/view/camera/field_of_view", limits::kMaxFieldOfViewDegrees);
  expectRefused(baseScene(), "/view/camera/field_of_view", below(limits::kMinFieldOfViewDegrees),
                "view.camera.field_of_view");
  expectRefused(baseScene(), "/view/camera/field_of_view", above(limits::kMaxFieldOfViewDegrees),
                "view.camera.field_of_view");
  expectAccepted(baseScene(), "/view/path_samples_per_frame", limits::kMaxPathSamplesPerFrame);
  expectRefused(baseScene(), "/view/path_samples_per_frame", limits::kMaxPathSamplesPerFrame + 1,
                "view.path_samples_per_frame");
  expectAccepted(baseScene(), "/view/trail_fade_seconds", limits::kMaxTrailFadeSeconds);
  expectRefused(baseScene(), "/view/trail_fade_seconds", above(limits::kMaxTrailFadeSeconds),
                "view.trail_fade_seconds");
  expectAccepted(baseScene(), "/output/video_crf", limits::kMaxVideoCrf);
  expectAccepted(baseScene(), "/output/video_crf", 0);
  expectRefused(baseScene(), "/output/video_crf", limits::kMaxVideoCrf + 1, "output.video_crf");
  expectRefused(baseScene(), "/output/video_crf", -1, "output.video_crf");
  for (const std::string key : {"hold_start", "hold_end"}) {
    expectAccepted(baseScene(), "/output/" + key, limits::kMaxHoldSeconds);
    expectAccepted(baseScene(), "/output/" + key, 0.0);
    expectRefused(baseScene(), "/output/" + key, above(limits::kMaxHoldSeconds), "output." + key);
    expectRefused(baseScene(), "/output/" + key, below(0.0), "output." + key);
  }
  expectAccepted(baseScene(), "/output/playback_speed", limits::kMinPlaybackSpeed);
  expectAccepted(baseScene(), "/output/playback_speed", limits::kMaxPlaybackSpeed);
  expectRefused(baseScene(), "/output/playback_speed", below(limits::kMinPlaybackSpeed), "output.playback_speed");
  expectRefused(baseScene(), "/output/playback_speed", above(limits::kMaxPlaybackSpeed), "output.playback_speed");
  json trails = baseScene();
  trails["linkage"] = {{"rods", 40}, {"L", 39}};
  trails["initial"] = {{"coords", std::vector<double>(38, 0.1)}, {"velocity", std::vector<double>(38, 0)}};
  trails["initial"]["velocity"][0] = 1;
  std::vector<int> hinges;
  for (int k = 1; k <= limits::kMaxTrails; ++k) hinges.push_back(k);
  expectAccepted(trails, "/view/trails", hinges);
  hinges.push_back(limits::kMaxTrails + 1);
  expectRefused(trails, "/view/trails", hinges, "view.trails");
}

TEST(LimitBoundaries, Tolerances) {
  json scene = baseScene();
  scene["runs"][0]["integrator"] = "dopri5";
  expectAccepted(scene, "/runs/0/tolerance", limits::kMinTolerance);
  expectAccepted(scene, "/runs/0/tolerance", limits::kMaxTolerance);
  expectRefused(scene, "/runs/0/tolerance", below(limits::kMinTolerance), "runs[0].tolerance");
  expectRefused(scene, "/runs/0/tolerance", above(limits::kMaxTolerance), "runs[0].tolerance");
}

TEST(LimitBoundaries, Families) {
  json scene = baseScene();
  scene["runs"][0]["family"] = {{"kind", "fan"}, {"count", 16}, {"spread", 0.2}};
  expectAccepted(scene, "/runs/0/family/count", limits::kMaxFamilyMembers);
  expectRefused(scene, "/runs/0/family/count", limits::kMaxFamilyMembers + 1, "runs[0].family.count");
  expectAccepted(scene, "/runs/0/family/count", 2);
  expectRefused(scene, "/runs/0/family/count", 1, "runs[0].family.count");
  expectAccepted(scene, "/runs/0/family/spread", limits::kMaxFamilySpread);
  expectRefused(scene, "/runs/0/family/spread", above(limits::kMaxFamilySpread), "runs[0].family.spread");
  scene["runs"][0]["family"] = {{"kind", "cloud"}, {"epsilon", 1e-6}};
  expectAccepted(scene, "/runs/0/family/epsilon", limits::kMaxCloudEpsilon);
  expectRefused(scene, "/runs/0/family/epsilon", above(limits::kMaxCloudEpsilon), "runs[0].family.epsilon");
}

TEST(LimitBoundaries, Pushes) {
  json scene = baseScene();
  scene["initial"] = {{"hinges", "arc"}, {"push", {{"hinge", 1}, {"velocity", {0, 1}}}}};
  expectAccepted(scene, "/initial/push/velocity", {0, 1e6});
  expectRefused(scene, "/initial/push/velocity", {0, above(1e6)}, "initial.push.velocity");
  expectAccepted(scene, "/initial/push/velocity", {-1e6, 0});
  expectRefused(scene, "/initial/push/velocity", {below(-1e6), 0}, "initial.push.velocity");
  scene["initial"]["push"] = {{"seed", 1}, {"size", 1}};
  expectAccepted(scene, "/initial/push/size", 1e6);
  expectRefused(scene, "/initial/push/size", above(1e6), "initial.push.size");
  expectAccepted(scene, "/initial/push/size", 1e-12);
  expectRefused(scene, "/initial/push/size", below(1e-12), "initial.push.size");
}

}  // namespace
}  // namespace sl

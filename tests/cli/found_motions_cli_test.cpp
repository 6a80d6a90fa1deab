// Starts on found motions (a scene's initial.connect and initial.periodic): resolved once when the scene is read,
// they start ordinary runs that reach the target at the motion's length, or close up after one period, through
// the normal simulation; the shipped scenes render the same frames in shards; refusals name the JSON path.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/motion_starts.hpp"
#include "cli/scene_input.hpp"
#include "linkage/chart.hpp"
#include "scene/scene_loader.hpp"
#include "simulation/trajectory.hpp"
#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A 4-rod scene (L = 3) whose runs start as `initials` say (a run's own "initial" each); no duration unless given.
json sceneOf(const std::vector<json>& initials, double L = 3.0, int rods = 4) {
  json scene = {{"name", "found"}, {"linkage", {{"rods", rods}, {"L", L}}}, {"initial", initials.at(0)}};
  json runs = json::array();
  for (std::size_t i = 0; i < initials.size(); ++i)
    runs.push_back({{"name", "run " + std::to_string(i)}, {"initial", initials[i]}});
  scene["runs"] = runs;
  return scene;
}

json connectTo(int index, const json& extra = json::object()) {
  json connect = {{"from", {{"coords", {0.3, 0.2}}}}, {"to", {{"coords", {-0.6, 2.2}}}}, {"index", index}};
  connect.update(extra);
  return {{"connect", connect}};
}

json periodic(int index) { return {{"periodic", {{"index", index}}}}; }

Scene resolvedScene(const json& text) {
  Scene scene = parseScene(text.dump(), "found.json");
  const std::vector<SceneProblem> problems = resolveMotionStarts(scene);
  EXPECT_TRUE(problems.empty()) << formatProblems("found.json", problems);
  return scene;
}

Eigen::Matrix2Xd hingesAt(const Chain& chain, double phi, double t) {
  Eigen::VectorXd coords(2);
  coords << phi, t;
  return hingePositions(chain, coords);
}

// The resolved start of a connect run, integrated by the run's own method (the default: ambient, RKF 7(8) at
// 1e-14), is at the target when t = the motion's length (unit speed), for the shortest motion and the next; the
// list is `linkage connect`'s, in its order.
TEST(FoundMotions, ConnectRunsReachTheTargetAtTheirLengthThroughTheSimulation) {
  Scene scene = resolvedScene(sceneOf({connectTo(0), connectTo(1), connectTo(2)}));
  ASSERT_EQ(scene.runs.size(), 3u);
  const Eigen::Matrix2Xd from = hingesAt(scene.chain, 0.3, 0.2), to = hingesAt(scene.chain, -0.6, 2.2);
  const std::vector<InitialState> starts = runStarts(scene);
  std::vector<double> lengths;
  for (std::size_t i = 0; i < scene.runs.size(); ++i) {
    SCOPED_TRACE(i);
    const FoundMotion& motion = *scene.runs[i].initial.motion;
    lengths.push_back(motion.length);
    EXPECT_EQ(motion.time, motion.length);
    Trajectory run(scene.runs[i].chain, starts[i], scene.runs[i].config);
    const auto start = run.sampleAt(0);
    ASSERT_TRUE(start);
    EXPECT_LT((start->hinges - from).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_NEAR(2 * start->energy, 1.0, 1e-12);  // unit speed
    // Not there earlier: a tenth of the length before, the chain is visibly elsewhere.
    const auto before = run.sampleAt(0.9 * motion.length);
    ASSERT_TRUE(before);
    EXPECT_GT((before->hinges - to).cwiseAbs().maxCoeff(), 1e-2);
    const auto end = run.sampleAt(motion.length);
    ASSERT_TRUE(end);
    EXPECT_LT((end->hinges - to).cwiseAbs().maxCoeff(), 1e-8);
  }
  EXPECT_LT(lengths[0], lengths[1]);
  EXPECT_LT(lengths[1], lengths[2]);
  // Left out, the duration is the longest motion's time.
  EXPECT_TRUE(scene.durationFromMotions);
  EXPECT_DOUBLE_EQ(scene.duration, lengths[2]);

  // The same list as `linkage connect` prints for this start and target, in the same order.
  TempFolder folder;
  json plain = sceneOf({{{"coords", {0.3, 0.2}}, {"velocity", {1, 0}}}});
  plain["duration"] = 1;
  writeFile(folder / "plain.json", plain.dump());
  const ProcessResult listed =
      runLinkage({"connect", "plain.json", "--to", R"({"coords": [-0.6, 2.2]})", "--json", "--quiet"}, folder.path());
  ASSERT_EQ(listed.code, 0) << listed.err;
  const json list = json::parse(listed.out);
  ASSERT_GE(list.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(list[i]["length"].get<double>(), lengths[i], 1e-9) << i;
}

// With "arrival", the same geodesic is run so that it reaches the target at that time; by hinges, "from" and "to"
// are placed on the rod constraints first.
TEST(FoundMotions, ConnectArrivalAndHingeConfigurations) {
  json byHinges = connectTo(0, {{"arrival", 2.5}});
  Scene probe = parseScene(sceneOf({connectTo(0)}).dump(), "probe.json");
  const Eigen::Matrix2Xd target = hingesAt(probe.chain, -0.6, 2.2);
  json hinges = json::array();
  for (int k = 0; k < 3; ++k) hinges.push_back({target(0, k) + 1e-4, target(1, k)});  // a little off the rods
  byHinges["connect"]["to"] = {{"hinges", hinges}};
  Scene scene = resolvedScene(sceneOf({byHinges}));
  const FoundMotion& motion = *scene.runs[0].initial.motion;
  EXPECT_EQ(motion.time, 2.5);
  EXPECT_DOUBLE_EQ(scene.duration, 2.5);
  Trajectory run(scene.runs[0].chain, runStarts(scene).at(0), scene.runs[0].config);
  const auto end = run.sampleAt(2.5);
  ASSERT_TRUE(end);
  // The target as placed on the constraints: within the 1e-4 it was given off them, to the integrator's 1e-8.
  EXPECT_LT((end->hinges - target).cwiseAbs().maxCoeff(), 2e-4);
  EXPECT_NEAR(std::sqrt(2 * end->energy), motion.length / 2.5, 1e-9);
}

// A periodic run is back at its start, in position and velocity, after one period (its length at unit speed),
// for each of the three simple closed geodesics of the 4-rod chain and the 3-rod chain's circle.
TEST(FoundMotions, PeriodicRunsReturnToTheirStartAfterOnePeriod) {
  Scene scene = resolvedScene(sceneOf({periodic(0), periodic(1), periodic(2)}));
  const std::vector<InitialState> starts = runStarts(scene);
  double longest = 0;
  for (std::size_t i = 0; i < scene.runs.size(); ++i) {
    SCOPED_TRACE(i);
    const FoundMotion& motion = *scene.runs[i].initial.motion;
    ASSERT_TRUE(motion.stability);
    EXPECT_TRUE(motion.stability == Stability::Elliptic || motion.stability == Stability::Hyperbolic)
        << nameOf(*motion.stability);
    longest = std::max(longest, motion.length);
    Trajectory run(scene.runs[i].chain, starts[i], scene.runs[i].config);
    const auto start = run.sampleAt(0);
    const auto half = run.sampleAt(0.5 * motion.length);
    const auto end = run.sampleAt(motion.length);
    ASSERT_TRUE(start && half && end);
    EXPECT_GT((half->spherePoint - start->spherePoint).norm(), 0.1);  // it went somewhere
    EXPECT_LT((end->spherePoint - start->spherePoint).cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_LT((end->sphereVelocity - start->sphereVelocity).cwiseAbs().maxCoeff(), 1e-8);
  }
  EXPECT_DOUBLE_EQ(scene.duration, longest);

  Scene circle = resolvedScene(sceneOf({periodic(0)}, 2.0, 3));
  const FoundMotion& loop = *circle.runs[0].initial.motion;
  Trajectory run(circle.runs[0].chain, runStarts(circle).at(0), circle.runs[0].config);
  const auto start = run.sampleAt(0);
  const auto end = run.sampleAt(loop.length);
  ASSERT_TRUE(start && end);
  EXPECT_LT((end->hinges - start->hinges).cwiseAbs().maxCoeff(), 1e-8);
}

// The title names the found motions: {runs[i].length} and {runs[i].stability}, filled once they are found.
TEST(FoundMotions, TitlePlaceholdersShowLengthAndStability) {
  json text = sceneOf({periodic(0), connectTo(0)});
  text["title"] = "{runs[0].stability} {runs[0].length}; {runs[1].length}; {runs[1].stability} {L}";
  const Scene scene = resolvedScene(text);
  char expected[128];
  std::snprintf(expected, sizeof expected, "%s %.4f; %.4f; {runs[1].stability} 3",
                nameOf(scene.runs[0].initial.motion->stability.value()).c_str(), scene.runs[0].initial.motion->length,
                scene.runs[1].initial.motion->length);
  EXPECT_EQ(scene.title, expected);
}

// What cannot start is refused by validate and render alike, naming the JSON path and what was expected.
TEST(FoundMotions, RefusalsNameTheJsonPath) {
  TempFolder folder;
  const auto refused = [&](const json& scene, const std::string& words, const std::string& more = "") {
    writeFile(folder / "bad.json", scene.dump());
    for (const std::vector<std::string>& command :
         {std::vector<std::string>{"validate", "bad.json"}, {"render", "bad.json", "--out", "out", "--quiet"}}) {
      SCOPED_TRACE(command[0]);
      const ProcessResult result = runLinkage(command, folder.path());
      EXPECT_EQ(result.code, 2);
      EXPECT_NE(result.err.find("bad.json: " + words), std::string::npos) << result.err;
      EXPECT_NE(result.err.find(more), std::string::npos) << result.err;
      EXPECT_FALSE(fs::exists(folder.path() / "out"));
    }
  };
  refused(sceneOf({periodic(0), periodic(40)}), "runs[1].initial.periodic.index: found 40; ",
          "closed geodesics were found up to the search's own length bound, so expected an index from 0 to ");
  json connectBeyond = sceneOf({connectTo(0, {{"index", 60}, {"max_length", 5}})});
  refused(connectBeyond, "runs[0].initial.connect.index: found 60; 2 geodesics to the target were found up to "
                         "max_length, so expected an index from 0 to 1 (or a larger max_length)");
  json offRods = sceneOf({connectTo(0)});
  offRods["initial"]["connect"]["to"] = {{"hinges", {{0, 0}, {1, 0}, {2, 0}}}};
  offRods["runs"][0].erase("initial");
  refused(offRods, "initial.connect.to.hinges: are not a configuration of the chain");
  json slack = sceneOf({connectTo(0)}, 1.5);
  slack["runs"][0].erase("initial");
  refused(slack, "initial: a slack chain (L = 1.5 <= n-2) has no configuration sphere, so no chart, drag, connect or "
                 "periodic start");
  refused(sceneOf({periodic(0)}, 3.5, 5), "runs[0].initial.periodic: found 5 rods; closed geodesics are found for 3");
  json speed = sceneOf({connectTo(0)});
  speed["runs"][0]["initial"]["unit_speed"] = true;
  refused(speed, "runs[0].initial.unit_speed: is not used by a connect start");
  json missing = sceneOf({connectTo(0)});
  missing["runs"][0]["initial"]["connect"].erase("from");
  refused(missing, "runs[0].initial.connect.from: missing");
  json mixed = sceneOf({connectTo(0), {{"coords", {0.3, 0.2}}, {"velocity", {1, 0}}}});
  refused(mixed, "duration: missing; expected the simulated time in seconds (it may be left out only when every run");
}

// The shipped scenes: each renders, and frames 10-12 rendered alone are those frames of the whole render (the
// motions and cut-locus.json's distance map are found before the first frame, the same in every shard).
TEST(FoundMotions, ShippedScenesRenderTheSameFramesInShards) {
  for (const char* name : {"connect.json", "periodic.json", "cut-locus.json"}) {
    SCOPED_TRACE(name);
    TempFolder folder;
    const std::string scene = shippedScene(name);
    const ProcessResult whole =
        runLinkage({"render", scene, "--size", "160x90", "--out", "whole", "--quiet"}, folder.path(), 300);
    ASSERT_EQ(whole.code, 0) << whole.err;
    const ProcessResult part = runLinkage(
        {"render", scene, "--size", "160x90", "--frames", "10:13", "--out", "part", "--quiet"}, folder.path());
    ASSERT_EQ(part.code, 0) << part.err;
    for (const char* frame : {"frame_00010.png", "frame_00011.png", "frame_00012.png"})
      EXPECT_EQ(readFile(folder.path() / "part" / frame), readFile(folder.path() / "whole" / frame)) << frame;
    EXPECT_FALSE(fs::exists(folder.path() / "part" / "frame_00013.png"));
    EXPECT_NE(readFile(folder.path() / "whole" / "frame_00010.png"), readFile(folder.path() / "whole" / "frame_00011.png"));
  }
}

// view.sphere.distance_from: a configuration by coords or by hinges is placed on the rod constraints when the scene
// is read (one rule with a connect start's), so both name the same point; a still shows the same sphere for both,
// and another one when the distance is measured from the start instead.
TEST(FoundMotions, DistanceFromCoordsAndFromHingesNameTheSamePoint) {
  json byCoords = sceneOf({{{"coords", {0.3, 0.2}}, {"velocity", {0.4, 0.5}}}});
  byCoords["duration"] = 1;
  byCoords["view"] = {{"sphere", {{"color_by", "distance"}, {"distance_from", {{"coords", {-0.4, 1.9}}}}}}};
  const Scene coords = resolvedScene(byCoords);
  const Eigen::Matrix2Xd hinges = hingesAt(coords.chain, -0.4, 1.9);
  const Eigen::VectorXd expected = spherePointFromHinges(coords.chain, hinges);
  ASSERT_EQ(coords.distancePoint.size(), 3);
  EXPECT_LT((coords.distancePoint - expected).norm(), 1e-12);
  json byHinges = byCoords;
  json points = json::array();
  for (Eigen::Index k = 0; k < hinges.cols(); ++k) points.push_back({hinges(0, k) + 2e-4, hinges(1, k) - 1e-4});
  byHinges["view"]["sphere"]["distance_from"] = {{"hinges", points}};
  EXPECT_LT((resolvedScene(byHinges).distancePoint - expected).norm(), 2e-3);

  TempFolder folder;
  json exact = byHinges;
  exact["view"]["sphere"]["distance_from"]["hinges"] = json::array();
  for (Eigen::Index k = 0; k < hinges.cols(); ++k)
    exact["view"]["sphere"]["distance_from"]["hinges"].push_back({hinges(0, k), hinges(1, k)});
  json fromStart = byCoords;
  fromStart["view"]["sphere"]["distance_from"] = "start";
  for (const auto& [name, scene] : {std::pair<std::string, json>{"coords", byCoords}, {"hinges", exact}, {"start", fromStart}}) {
    writeFile(folder.path() / (name + ".json"), scene.dump());
    const ProcessResult still = runLinkage(
        {"still", name + ".json", "--time", "0.5", "--size", "320x180", "--out", name + ".png", "--quiet"}, folder.path());
    ASSERT_EQ(still.code, 0) << still.err;
  }
  EXPECT_EQ(readFile(folder.path() / "coords.png"), readFile(folder.path() / "hinges.png"));
  EXPECT_NE(readFile(folder.path() / "coords.png"), readFile(folder.path() / "start.png"));
}

}  // namespace
}  // namespace sl::testing

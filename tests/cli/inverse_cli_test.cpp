// `linkage connect` and `linkage periodic` from the command line: what a user sees (the JSON keys, the
// shortest first, both routes agreeing) and the refusals. The numbers are pinned by tests/inverse.
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "contracts/limits.hpp"
#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

TEST(ConnectCli, JsonListsTheShortestFirstWithBothRoutes) {
  TempFolder folder;
  const ProcessResult result = runLinkage(
      {"connect", shippedScene("default.json"), "--to", R"({"coords": [-0.6, 2.2]})", "--max-length", "5", "--json"},
      folder.path());
  ASSERT_EQ(result.code, 0) << result.err;
  const nlohmann::json list = nlohmann::json::parse(result.out);
  ASSERT_GE(list.size(), 2u);
  EXPECT_TRUE(list[0]["shortest"].get<bool>());
  EXPECT_EQ(list[0]["morse_index"].get<int>(), 0);
  for (const auto& c : list) {
    EXPECT_LE(c["length"].get<double>(), 5.0);
    EXPECT_GE(c["length"].get<double>(), list[0]["length"].get<double>());
    EXPECT_LE(c["end_error"].get<double>(), 1e-12);
    EXPECT_EQ(c["coords"].size(), 2u);
    EXPECT_EQ(c["hinge_velocities"].size(), 3u);
  }
  EXPECT_LT(list[0]["length_difference"].get<double>(), 1e-8);
}

TEST(ConnectCli, TargetByHingesAndRefusals) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  // The arc shape's hinges of a 4-rod chain on L = 3 (unit rods).
  const ProcessResult byHinges = runLinkage(
      {"connect", scene, "--to",
       R"({"hinges": [[0.5, -0.8660254037844386], [1.5, -0.8660254037844386], [2.5, -0.8660254037844386]]})"},
      folder.path());
  EXPECT_EQ(byHinges.code, 0) << byHinges.err;
  EXPECT_NE(byHinges.out.find("distance "), std::string::npos);
  const ProcessResult wrongCount = runLinkage({"connect", scene, "--to", R"({"coords": [1]})"}, folder.path());
  EXPECT_EQ(wrongCount.code, 2);
  EXPECT_NE(wrongCount.err.find("coords: expected an array of 2 numbers"), std::string::npos) << wrongCount.err;
  const ProcessResult offRods =
      runLinkage({"connect", scene, "--to", R"({"hinges": [[0, 0], [1, 0], [2, 0]]})"}, folder.path());
  EXPECT_EQ(offRods.code, 2);
  EXPECT_NE(offRods.err.find("not within 0.01"), std::string::npos) << offRods.err;
}

// Route 3: --method shoots every motion again with a chart method; the lengths agree with route 1 in the JSON,
// and a method the chain refuses names the option and why.
TEST(ConnectCli, ChartMethodsAsAThirdRoute) {
  TempFolder folder;
  const ProcessResult result =
      runLinkage({"connect", shippedScene("default.json"), "--to", R"({"coords": [-0.6, 2.2]})", "--max-length", "5",
                  "--method", "christoffel", "--method", "embedded", "--json"},
                 folder.path());
  ASSERT_EQ(result.code, 0) << result.err;
  const nlohmann::json list = nlohmann::json::parse(result.out);
  ASSERT_GE(list.size(), 2u);
  for (const auto& c : list) {
    ASSERT_EQ(c["methods"].size(), 2u);
    EXPECT_EQ(c["methods"][0]["method"], "christoffel");
    EXPECT_EQ(c["methods"][1]["method"], "embedded");
    for (const auto& m : c["methods"]) {
      ASSERT_TRUE(m["length"].is_number()) << m.dump();
      EXPECT_NEAR(m["length"].get<double>(), c["length"].get<double>(), 1e-8);
      EXPECT_LE(m["end_error"].get<double>(), 1e-12);
    }
  }
  const ProcessResult refused = runLinkage(
      {"connect", shippedScene("five-rods.json"), "--to", R"({"coords": [0.1, 0.2, 0.3]})", "--method",
       "christoffel-fd"},
      folder.path());
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("--method christoffel-fd: "), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("4-rod"), std::string::npos) << refused.err;
}

// The published embedded-fd reaches every motion at its own noise floor (integrated at 1e-11, Newton stopping
// when its error no longer halves): it spent 713 s in 30 futile iterations a motion and then printed "-" for each.
// Its lengths agree with route 1 to its finite differences' accuracy, its end errors within kMethodShotEndBound.
TEST(ConnectCli, ThePublishedEmbeddedFdReachesTheMotionsAtItsOwnFloor) {
  TempFolder folder;
  const ProcessResult result =
      runLinkage({"connect", shippedScene("default.json"), "--to", R"({"coords": [-0.6, 2.2]})", "--max-length", "5",
                  "--method", "embedded-fd", "--json"},
                 folder.path());
  ASSERT_EQ(result.code, 0) << result.err;
  const nlohmann::json list = nlohmann::json::parse(result.out);
  ASSERT_GE(list.size(), 2u);
  for (const auto& c : list) {
    const auto& m = c["methods"][0];
    ASSERT_TRUE(m["length"].is_number()) << m.dump();
    EXPECT_NEAR(m["length"].get<double>(), c["length"].get<double>(), 1e-6);
    EXPECT_LE(m["end_error"].get<double>(), 1e-8);
  }
}

TEST(PeriodicCli, ThreeSimpleClosedGeodesicsAsJson) {
  TempFolder folder;
  const ProcessResult result = runLinkage({"periodic", shippedScene("default.json"), "--json"}, folder.path());
  ASSERT_EQ(result.code, 0) << result.err;
  const nlohmann::json list = nlohmann::json::parse(result.out);
  int simple = 0;
  for (const auto& g : list) {
    simple += g["simple"].get<bool>();
    EXPECT_TRUE(g.contains("length"));
    EXPECT_EQ(g["start"]["coords"].size(), 2u);
    EXPECT_LT(g["closure_position"].get<double>(), 1e-10);
    EXPECT_EQ(g["check"], "confirmed");
  }
  EXPECT_GE(simple, 3);
  EXPECT_NEAR(list[0]["length"].get<double>(), 6.593902692917, 1e-8);
}

// The headline of the fourth hostile round: on 3 rods at L = 1.5 and 1.9 the circle was listed with closure 1.3 and
// an independent length 10.769 beside its 6.655. Now both routes agree, the row says "confirmed", and a scene
// starts on it.
TEST(PeriodicCli, TheThreeRodCircleBelowLTwoIsConfirmed) {
  TempFolder folder;
  writeFile(folder.path() / "three.json", R"({"name": "three", "linkage": {"rods": 3, "L": 1.5},
    "initial": {"periodic": {"index": 0}},
    "runs": [{"name": "a", "method": "ambient", "integrator": "dopri5", "tolerance": 1e-10}]})");
  for (const char* length : {"1.5", "1.9"}) {
    const ProcessResult result =
        runLinkage({"periodic", "three.json", "--json", "--set", std::string("linkage.L=") + length}, folder.path());
    ASSERT_EQ(result.code, 0) << result.err;
    const nlohmann::json list = nlohmann::json::parse(result.out);
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list[0]["check"], "confirmed") << length;
    EXPECT_NEAR(list[0]["length"].get<double>(), list[0]["independent_length"].get<double>(), 1e-9) << length;
    EXPECT_LT(list[0]["closure_position"].get<double>(), 1e-9) << length;
  }
  const ProcessResult simulated = runLinkage({"simulate", "three.json", "--quiet"}, folder.path());
  ASSERT_EQ(simulated.code, 0) << simulated.err;
  EXPECT_NE(simulated.out.find("run,time"), std::string::npos);
}

TEST(ConnectCli, RefusesChainsBeyondItsLimit) {
  TempFolder folder;
  const std::string rods = std::to_string(limits::kMaxConnectRods + 1);
  const ProcessResult result = runLinkage({"connect", shippedScene("rope.json"), "--set", "linkage.rods=" + rods,
                                           "--to", R"({"coords": [0]})"},
                                          folder.path());
  EXPECT_EQ(result.code, 2);
  EXPECT_NE(result.err.find("connect handles at most " + std::to_string(limits::kMaxConnectRods) + " rods"),
            std::string::npos)
      << result.err;
}

// A chain well past the 40 rods connect once stopped at (docs/geometry.md, "Long chains"): 50 rods, from the
// scene's start to a target given by its chart coordinates, end to end (distance 0.7766).
TEST(ConnectCli, FiftyRodsEndToEnd) {
  TempFolder folder;
  std::string start = "0.3, -0.2", target = "0.1, 0", rates = "0.1, 0";
  for (int k = 2; k < 48; ++k) {
    start += k == 20 ? ", 0.1" : ", 0";
    target += k == 20 ? ", 0.1" : k == 33 ? ", -0.05" : ", 0";
    rates += ", 0";
  }
  const std::filesystem::path scene = folder.path() / "fifty.json";
  writeFile(scene, R"({"name": "fifty", "linkage": {"rods": 50, "L": 49.2}, "initial": {"coords": [)" + start +
                       R"(], "velocity": [)" + rates + R"(]}, "duration": 1, "runs": [{"name": "a", "method": "ambient"}]})");
  const ProcessResult result = runLinkage(
      {"connect", scene.string(), "--to", R"({"coords": [)" + target + "]}", "--max-length", "1", "--json"},
      folder.path());
  ASSERT_EQ(result.code, 0) << result.err;
  const nlohmann::json list = nlohmann::json::parse(result.out);
  ASSERT_GE(list.size(), 1u);
  EXPECT_TRUE(list[0]["shortest"].get<bool>());
  EXPECT_EQ(list[0]["morse_index"].get<int>(), 0);
  EXPECT_LE(list[0]["end_error"].get<double>(), 1e-12);
  EXPECT_EQ(list[0]["coords"].size(), 48u);
  EXPECT_EQ(list[0]["hinge_velocities"].size(), 49u);
  ASSERT_FALSE(list[0]["discrete_length"].is_null());
  EXPECT_LT(list[0]["length_difference"].get<double>(), 1e-8);
  EXPECT_LT(list[0]["path_difference"].get<double>(), 1e-7);
}

// Masses a million apart: refused before any search (it would run for many minutes), naming the scene and the
// linkage; a scene starting on such a closed geodesic is refused by validate at its start.
TEST(PeriodicCli, RefusesMassesTooFarApart) {
  TempFolder folder;
  writeFile(folder.path() / "far.json", R"({"name": "far", "linkage": {"rods": 4, "L": 3.5,
      "hinge_masses": [1e-3, 1, 1e3]}, "initial": {"coords": [0.1, 0.2], "velocity": [1, 0]}, "duration": 2,
      "runs": [{"name": "a", "method": "christoffel"}]})");
  const ProcessResult periodic = runLinkage({"periodic", "far.json"}, folder.path());
  EXPECT_EQ(periodic.code, 2);
  EXPECT_NE(periodic.err.find("far.json: linkage: hinge and rod masses 1e+06 apart"), std::string::npos) << periodic.err;
  writeFile(folder.path() / "far-start.json", R"({"name": "far", "linkage": {"rods": 4, "L": 3.5,
      "hinge_masses": [1e-3, 1, 1e3]}, "initial": {"periodic": {"index": 0}}, "duration": 2,
      "runs": [{"name": "a", "method": "christoffel"}]})");
  const ProcessResult validate = runLinkage({"validate", "far-start.json"}, folder.path());
  EXPECT_NE(validate.code, 0);
  EXPECT_NE(validate.err.find("initial.periodic"), std::string::npos) << validate.err;
  EXPECT_NE(validate.err.find("apart"), std::string::npos) << validate.err;
}

// A search says how far it got in a log (stderr not a terminal), and --quiet leaves only its table.
TEST(PeriodicCli, ShowsItsProgressInALogAndNothingWhenQuiet) {
  TempFolder folder;
  const ProcessResult shown = runLinkage({"periodic", shippedScene("default.json")}, folder.path());
  EXPECT_EQ(shown.code, 0) << shown.err;
  EXPECT_NE(shown.err.find("linkage periodic: search step "), std::string::npos) << shown.err;
  EXPECT_NE(shown.err.find("(100%)"), std::string::npos) << shown.err;
  const ProcessResult quiet = runLinkage({"periodic", shippedScene("default.json"), "--quiet"}, folder.path());
  EXPECT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
}

TEST(PeriodicCli, RefusesLongChains) {
  TempFolder folder;
  const ProcessResult result = runLinkage({"periodic", shippedScene("five-rods.json")}, folder.path());
  EXPECT_EQ(result.code, 2);
  EXPECT_NE(result.err.find("periodic needs 3 or 4 rods"), std::string::npos) << result.err;
}

// `geometry --distance-from`: the grid's CSV and the JSON summary; a bad point is refused naming the option,
// and nothing is written.
TEST(DistanceMapCli, CsvJsonAndRefusals) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  const std::filesystem::path csv = folder.path() / "distance.csv";
  const ProcessResult result = runLinkage(
      {"geometry", scene, "--distance-from", "start", "--grid", "48", "--csv", csv.string(), "--json", "--quiet"},
      folder.path());
  ASSERT_EQ(result.code, 0) << result.err;
  const std::string text = readFile(csv);
  EXPECT_EQ(text.rfind("phi,t,distance,direction\n", 0), 0u);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 48 * 48 + 1);
  const nlohmann::json j = nlohmann::json::parse(result.out);
  EXPECT_GT(j["injectivity_radius"].get<double>(), 0.5);
  EXPECT_LE(j["injectivity_radius"].get<double>(), j["farthest"].get<double>());
  EXPECT_FALSE(j["conjugate_locus"].empty());
  EXPECT_FALSE(j["cut_locus"].empty());

  const std::filesystem::path bad = folder.path() / "bad.csv";
  const ProcessResult refused = runLinkage(
      {"geometry", scene, "--distance-from", R"({"coords": [1]})", "--grid", "48", "--csv", bad.string()},
      folder.path());
  EXPECT_EQ(refused.code, 2);
  EXPECT_NE(refused.err.find("--distance-from: coords: expected an array of 2 numbers"), std::string::npos)
      << refused.err;
  EXPECT_FALSE(std::filesystem::exists(bad));
  const ProcessResult jsonAlone = runLinkage({"geometry", scene, "--summary", "--json"}, folder.path());
  EXPECT_EQ(jsonAlone.code, 2);
  EXPECT_NE(jsonAlone.err.find("--json: goes with --distance-from"), std::string::npos) << jsonAlone.err;
}

// `geometry --distance-from --points`: the distance at given points, exact, in the grid's columns; at two of the
// grid's own nodes it agrees with the map (good to 1e-3); a bad points file is refused naming its line.
TEST(DistanceMapCli, DistanceAtGivenPoints) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  const ProcessResult grid =
      runLinkage({"geometry", scene, "--distance-from", "start", "--grid", "48", "--quiet"}, folder.path());
  ASSERT_EQ(grid.code, 0) << grid.err;
  std::istringstream rows(grid.out);
  std::string header, line;
  std::getline(rows, header);
  std::vector<std::array<double, 3>> nodes;  // phi, t, distance of every 700th node
  for (int k = 0; std::getline(rows, line); ++k) {
    if (k % 700 != 350) continue;
    std::array<double, 3> node{};
    std::sscanf(line.c_str(), "%lf,%lf,%lf", &node[0], &node[1], &node[2]);
    nodes.push_back(node);
  }
  ASSERT_GE(nodes.size(), 2u);
  std::string points = "phi,t\n";
  for (const auto& node : nodes) points += std::to_string(node[0]) + "," + std::to_string(node[1]) + "\n";
  writeFile(folder.path() / "points.csv", points);
  const ProcessResult at = runLinkage(
      {"geometry", scene, "--distance-from", "start", "--grid", "48", "--points", "points.csv"}, folder.path());
  ASSERT_EQ(at.code, 0) << at.err;
  EXPECT_NE(at.err.find("the distance at " + std::to_string(nodes.size()) + " points"), std::string::npos) << at.err;
  std::istringstream found(at.out);
  std::getline(found, header);
  EXPECT_EQ(header, "phi,t,distance,direction");
  for (const auto& node : nodes) {
    ASSERT_TRUE(std::getline(found, line));
    double phi = 0, t = 0, distance = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf", &phi, &t, &distance), 3) << line;
    EXPECT_NEAR(distance / node[2], 1.0, 2e-3) << line;
  }
  EXPECT_FALSE(std::getline(found, line));
  writeFile(folder.path() / "bad.csv", "phi,t\n0.1,x\n");
  const ProcessResult bad =
      runLinkage({"geometry", scene, "--distance-from", "start", "--grid", "48", "--points", "bad.csv"}, folder.path());
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("bad.csv:2: expected two finite numbers phi,t"), std::string::npos) << bad.err;
  EXPECT_EQ(bad.out, "");
}

}  // namespace
}  // namespace sl::testing

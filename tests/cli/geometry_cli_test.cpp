// `linkage geometry`: the curvature of the configuration sphere from the command line. The values themselves
// are pinned by tests/geometry (two routes, Gauss-Bonnet, symmetry); these tests pin what a user sees: the
// summary's figures, the CSV's columns and size, the maps and the sweep chart, and the refusals.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/files.hpp"
#include "support/linkage_binary.hpp"
#include "support/scene_files.hpp"
#include "support/temp_folder.hpp"

namespace sl::testing {
namespace {

namespace fs = std::filesystem;

int lineCount(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n';
  return lines;
}

TEST(GeometryCli, SummaryMatchesTheIndependentFiniteDifferenceFigures) {
  TempFolder folder;
  const ProcessResult result = runLinkage({"geometry", shippedScene("default.json"), "--summary"}, folder.path());
  ASSERT_EQ(result.code, 0) << result.err;
  const nlohmann::json summary = nlohmann::json::parse(result.out);
  // Figures of an independent finite-difference calculation, good to about 1e-4.
  EXPECT_NEAR(summary["area"].get<double>(), 21.326, 1e-3);
  EXPECT_NEAR(summary["K_min"]["value"].get<double>(), -0.272, 1e-3);
  EXPECT_NEAR(std::abs(summary["K_min"]["phi"].get<double>()), 0.39, 0.01);
  EXPECT_NEAR(summary["K_max"]["value"].get<double>(), 4.15, 1e-2);
  EXPECT_NEAR(summary["total_curvature"].get<double>(), 4 * M_PI, 1e-9);
  EXPECT_LT(std::abs(summary["gauss_bonnet_error"].get<double>()), 1e-9);
  EXPECT_NE(result.err.find("linkage geometry: summary of \"default\" (L = 3) in "), std::string::npos) << result.err;
}

TEST(GeometryCli, GridAndPointsAgree) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  ASSERT_EQ(runLinkage({"geometry", scene, "--grid", "8", "--csv", "grid.csv", "--quiet"}, folder.path()).code, 0);
  const std::string grid = readFile(folder / "grid.csv");
  EXPECT_EQ(grid.substr(0, grid.find('\n')), "phi,t,K,bending,stiffness_max,stiffness_min,stiffness_angle");
  EXPECT_EQ(lineCount(grid), 1 + 8 * 8);

  // The points of the grid's second row, read back through --points, give the same bytes.
  std::istringstream rows(grid);
  std::string header, line, points = "phi,t\n", expected = "";
  std::getline(rows, header);
  for (int i = 0; i < 16 && std::getline(rows, line); ++i) {
    if (i < 8) continue;
    const size_t second = line.find(',', line.find(',') + 1);
    points += line.substr(0, second) + "\n";
    expected += line + "\n";
  }
  writeFile(folder / "points.csv", points);
  const ProcessResult atPoints = runLinkage({"geometry", scene, "--points", "points.csv"}, folder.path());
  ASSERT_EQ(atPoints.code, 0) << atPoints.err;
  EXPECT_EQ(atPoints.out, header + "\n" + expected);
}

TEST(GeometryCli, MapsAndSweepChart) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  const ProcessResult maps = runLinkage({"geometry", scene, "--grid", "24", "--maps", "maps"}, folder.path());
  ASSERT_EQ(maps.code, 0) << maps.err;
  EXPECT_EQ(maps.out, "") << "--maps without --csv writes no CSV";
  for (const char* name : {"curvature.png", "bending.png", "stiffness.png"})
    EXPECT_GT(fs::file_size(fs::path(folder.path()) / "maps" / name), 1000u) << name;

  const ProcessResult sweep =
      runLinkage({"geometry", scene, "--sweep-L", "2.5:3.5:5", "--csv", "sweep.csv", "--chart", "sweep.png"},
                 folder.path());
  ASSERT_EQ(sweep.code, 0) << sweep.err;
  const std::string csv = readFile(folder / "sweep.csv");
  EXPECT_EQ(lineCount(csv), 1 + 5);
  EXPECT_NE(csv.find("\n3,21.32635"), std::string::npos) << csv;
  EXPECT_GT(fs::file_size(folder / "sweep.png"), 1000u);
}

TEST(GeometryCli, Refusals) {
  TempFolder folder;
  const std::string scene = shippedScene("default.json");
  // Five rods: the configuration space is S^3, not a surface.
  const ProcessResult fiveRods = runLinkage({"geometry", shippedScene("five-rods.json"), "--summary"}, folder.path());
  EXPECT_EQ(fiveRods.code, 2);
  EXPECT_NE(fiveRods.err.find("linkage.rods"), std::string::npos) << fiveRods.err;
  // Exactly one mode; --chart only with a sweep; a sweep inside the allowed range of L.
  EXPECT_EQ(runLinkage({"geometry", scene}, folder.path()).code, 2);
  EXPECT_EQ(runLinkage({"geometry", scene, "--summary", "--grid", "4"}, folder.path()).code, 2);
  EXPECT_EQ(runLinkage({"geometry", scene, "--summary", "--chart", "x.png"}, folder.path()).code, 2);
  EXPECT_EQ(runLinkage({"geometry", scene, "--sweep-L", "1.5:3:4"}, folder.path()).code, 2);
  EXPECT_EQ(runLinkage({"geometry", scene, "--sweep-L", "nan:3:4"}, folder.path()).code, 2);
  writeFile(folder / "bad.csv", "phi,t\n0.1,abc\n");
  const ProcessResult badPoints = runLinkage({"geometry", scene, "--points", "bad.csv"}, folder.path());
  EXPECT_EQ(badPoints.code, 2);
  EXPECT_NE(badPoints.err.find("bad.csv"), std::string::npos) << badPoints.err;
  EXPECT_FALSE(fs::exists(folder / "x.png"));
}

// Holonomy (docs/geometry.md, "Parallel transport and holonomy"): the values are pinned by tests/inverse; here what a
// user reads: three figures that agree, the checks written beside them, the orientation, and the summary.
TEST(GeometryCli, HolonomyOfATriangleAgreesWithItsCurvatureAndItsAngleExcess) {
  TempFolder folder;
  const std::string corners = R"([{"coords": [0.2, 0]}, {"coords": [0.3, 1.4]}, {"coords": [1.2, 0.6]}])";
  const ProcessResult forward =
      runLinkage({"geometry", shippedScene("default.json"), "--holonomy", R"({"corners": )" + corners + "}"},
                 folder.path());
  ASSERT_EQ(forward.code, 0) << forward.err;
  const nlohmann::json h = nlohmann::json::parse(forward.out);
  const double angle = h["holonomy"].get<double>();
  EXPECT_GT(std::abs(angle), 0.1);
  EXPECT_NEAR(h["enclosed_curvature"].get<double>(), angle, 1e-8);
  EXPECT_NEAR(h["angle_excess"].get<double>(), angle, 1e-8);
  EXPECT_NEAR(h["checks"]["chart_route_holonomy"].get<double>(), angle, 1e-10);
  EXPECT_EQ(h["checks"]["result"], "confirmed");
  EXPECT_EQ(h["interior_angles"].size(), 3u);
  EXPECT_NE(forward.err.find("holonomy " ), std::string::npos) << forward.err;
  EXPECT_NE(forward.err.find("3-corner loop (routes agree to"), std::string::npos) << forward.err;

  // Run the other way round, from a file: the vector turns back by as much.
  const nlohmann::json reversed = {{"corners", nlohmann::json::parse(corners).get<std::vector<nlohmann::json>>()}};
  nlohmann::json backwards = reversed;
  std::reverse(backwards["corners"].begin(), backwards["corners"].end());
  writeFile(folder / "loop.json", backwards.dump());
  const ProcessResult back = runLinkage(
      {"geometry", shippedScene("default.json"), "--holonomy", "loop.json", "--csv", "back.json", "--quiet"},
      folder.path());
  ASSERT_EQ(back.code, 0) << back.err;
  EXPECT_EQ(back.err, "");
  EXPECT_NEAR(nlohmann::json::parse(readFile(folder / "back.json"))["holonomy"].get<double>(), -angle, 1e-10);
}

// A closed geodesic from linkage periodic's list: the vector comes back unturned, and 2 pi of curvature lies inside;
// an index past the list is refused naming it.
TEST(GeometryCli, HolonomyOfAClosedGeodesicIsNoneWithTwoPiInside) {
  TempFolder folder;
  const ProcessResult result =
      runLinkage({"geometry", shippedScene("default.json"), "--holonomy", R"({"periodic": 0})"}, folder.path());
  ASSERT_EQ(result.code, 0) << result.err;
  const nlohmann::json h = nlohmann::json::parse(result.out);
  EXPECT_EQ(h["loop"]["periodic"], 0);
  EXPECT_NEAR(h["holonomy"].get<double>(), 0.0, 1e-8);
  EXPECT_NEAR(h["enclosed_curvature"].get<double>(), 2 * M_PI, 1e-8);
  EXPECT_EQ(h["checks"]["result"], "confirmed");
  EXPECT_NE(result.err.find("closed geodesic 0 (simple)"), std::string::npos) << result.err;
  const ProcessResult past =
      runLinkage({"geometry", shippedScene("default.json"), "--holonomy", R"({"periodic": 99})"}, folder.path());
  EXPECT_EQ(past.code, 2);
  EXPECT_NE(past.err.find("--holonomy: periodic: found 99; linkage periodic lists"), std::string::npos) << past.err;
  EXPECT_EQ(past.out, "");
}

TEST(GeometryCli, HolonomyOfALatitudeIsTheCurvatureOfItsCap) {
  TempFolder folder;
  const ProcessResult result =
      runLinkage({"geometry", shippedScene("default.json"), "--holonomy", R"({"latitude": 0.5})"}, folder.path());
  ASSERT_EQ(result.code, 0) << result.err;
  const nlohmann::json h = nlohmann::json::parse(result.out);
  // The cap above phi = 0.5 holds more curvature than pi: the holonomy is its remainder in (-pi, pi].
  EXPECT_NEAR(std::remainder(h["enclosed_curvature"].get<double>() - h["holonomy"].get<double>(), 2 * M_PI), 0.0, 1e-8);
  EXPECT_FALSE(h.contains("angle_excess"));
  EXPECT_EQ(h["checks"]["result"], "confirmed");
}

TEST(GeometryCli, SectionalCurvatureRangeHoldsGivenPlanesAndIsAttained) {
  TempFolder folder;
  const std::string scene = shippedScene("five-rods.json");
  const ProcessResult first = runLinkage(
      {"geometry", scene, "--sectional",
       R"([{"coords": [0.3, -0.2, 0.5], "planes": [[[1, 0, 0], [0, 1, 0]], [[0, 0, 1], [1, 1, 0]]]}, {"coords": [-1.0, 0.4, 2.0]}])"},
      folder.path());
  ASSERT_EQ(first.code, 0) << first.err;
  const nlohmann::json points = nlohmann::json::parse(first.out);
  ASSERT_EQ(points.size(), 2u);
  const double lo = points[0]["K_min"].get<double>(), hi = points[0]["K_max"].get<double>();
  EXPECT_LT(lo, hi);
  for (const nlohmann::json& plane : points[0]["planes"]) {
    EXPECT_GE(plane["K"].get<double>(), lo - 1e-12);
    EXPECT_LE(plane["K"].get<double>(), hi + 1e-12);
    EXPECT_NEAR(plane["K_intrinsic"].get<double>(), plane["K"].get<double>(), 1e-9);
  }
  EXPECT_LT(points[0]["intrinsic_check"].get<double>(), 1e-9);
  EXPECT_NE(first.err.find("sectional curvature at 2 points (routes agree to"), std::string::npos) << first.err;

  // The plane reported for the maximum, given back as a plane, has the maximum.
  const nlohmann::json again = {{{"coords", points[0]["coords"]}, {"planes", {points[0]["plane_max"]}}}};
  const ProcessResult second = runLinkage({"geometry", scene, "--sectional", again.dump(), "--quiet"}, folder.path());
  ASSERT_EQ(second.code, 0) << second.err;
  EXPECT_NEAR(nlohmann::json::parse(second.out)[0]["planes"][0]["K"].get<double>(), hi, 1e-10);
}

TEST(GeometryCli, HolonomyAndSectionalRefusals) {
  TempFolder folder;
  const std::string four = shippedScene("default.json"), five = shippedScene("five-rods.json");
  const std::string triangle = R"({"corners": [{"coords": [0.2, 0]}, {"coords": [0.3, 1.4]}, {"coords": [1.2, 0.6]}]})";
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{"geometry", five, "--holonomy", triangle}, "holonomy is computed for 4 rods"},
      {{"geometry", four, "--sectional", R"([{"coords": [0, 0]}])"}, "sectional curvature is for 5 rods and more"},
      {{"geometry", four, "--holonomy", triangle, "--summary"}, "expected exactly one of"},
      {{"geometry", four, "--holonomy", R"({"corners": [{"coords": [0.2, 0]}, {"coords": [0.3, 1.4]}]})"},
       "--holonomy: corners: expected a list of at least 3 configurations"},
      {{"geometry", four, "--holonomy", R"({"corners": [{"coords": [0.2, 0]}, {"coords": [0.2, 0]}, {"coords": [1, 1]}]})"},
       "corners 1 and 2 are the same shape"},
      {{"geometry", four, "--holonomy", R"({"corners": [{"coords": [0.2, 0]}, {"coords": [0.3, "x"]}, {"coords": [1, 1]}]})"},
       "--holonomy: corners[1]: coords[1]: expected a finite number"},
      {{"geometry", four, "--holonomy", R"({"latitude": 1.6})"}, "latitude: found 1.6; expected -pi/2 < phi < pi/2"},
      {{"geometry", four, "--holonomy", R"({"latitude": 0.1, "corners": []})"}, "expected an object with one key"},
      {{"geometry", four, "--holonomy", "missing.json"}, "--holonomy missing.json: neither JSON nor a readable file"},
      {{"geometry", five, "--sectional", R"([{"coords": [0, 0, 0], "planes": [[[1, 0, 0], [2, 0, 0]]]}])"},
       "--sectional[0]: planes[0]: sectional curvature: the two tangent vectors do not span a plane"},
      {{"geometry", five, "--sectional", R"([{"coords": [0, 0, 0], "planes": [[[1, 0], [0, 1, 0]]]}])"},
       "--sectional[0]: planes[0][0]: expected an array of 3 numbers"},
      {{"geometry", five, "--sectional", "{}"}, "--sectional: expected a list of configurations"},
  };
  for (const Case& c : cases) {
    const ProcessResult result = runLinkage(c.args, folder.path());
    EXPECT_EQ(result.code, 2) << c.expected << "\n" << result.err;
    EXPECT_NE(result.err.find(c.expected), std::string::npos) << result.err;
    EXPECT_EQ(result.out, "") << c.expected;
  }
}

}  // namespace
}  // namespace sl::testing

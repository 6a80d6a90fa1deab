// `linkage geometry`: the curvature of the configuration sphere from the command line. The values themselves
// are pinned by tests/geometry (two routes, Gauss-Bonnet, symmetry); these tests pin what a user sees: the
// summary's figures, the CSV's columns and size, the maps and the sweep chart, and the refusals.
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

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

}  // namespace
}  // namespace sl::testing

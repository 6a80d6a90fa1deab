// Charts: gnuplot draws them, from the data alone (same rows, same PNG bytes).

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "analysis/gnuplot.hpp"
#include "analysis/stability_charts.hpp"
#include "analysis/stability_sweep.hpp"
#include "analysis/work_precision_charts.hpp"
#include "contracts/registry.hpp"
#include "test_paths.hpp"

namespace sl {
namespace {

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

bool isPng(const std::string& path) { return fileBytes(path).rfind("\x89PNG\r\n\x1a\n", 0) == 0; }

CsvTable syntheticStabilityRows() {
  CsvTable rows{stabilityColumns(), {}};
  const std::vector<std::string> statuses = {"ok", "pole-fold-back", "non-finite", "ok"};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      std::vector<std::string> row(rows.columns.size(), "0");
      row[rows.column("cell")] = std::to_string(j * 2 + i);
      row[rows.column("x")] = std::to_string(i);
      row[rows.column("y")] = std::to_string(j);
      row[rows.column("method")] = nameOf(Method::ChristoffelFd);
      row[rows.column("integrator")] = nameOf(Integrator::Rk4);
      row[rows.column("status")] = statuses[j * 2 + i];
      row[rows.column("max_error")] = formatNumber(std::pow(10.0, -3.0 * (i + 2 * j + 1)));
      rows.rows.push_back(row);
    }
  return rows;
}

// The test command installs gnuplot (scripts/install-deps.sh): a missing one is a failure, never a skip.
constexpr const char* kGnuplotIsInstalled = "gnuplot with pngcairo is missing; scripts/install-deps.sh installs it";

TEST(StabilityCharts, TheSameRowsDrawTheSameBytes) {
  ASSERT_TRUE(gnuplotAvailable()) << kGnuplotIsInstalled;
  const std::string first = sl::testing::freshTestFolder("a"), second = sl::testing::freshTestFolder("b");
  const CsvTable rows = syntheticStabilityRows();
  const auto a = writeStabilityCharts(rows, "pole", first);
  const auto b = writeStabilityCharts(rows, "pole", second);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_TRUE(isPng(a[0]));
  EXPECT_EQ(std::filesystem::path(a[0]).filename(), "stability-pole-christoffel-fd.png");
  EXPECT_EQ(fileBytes(a[0]), fileBytes(b[0]));
}

// The error map's colours span the whole decades its data reach (cells ok at 1e-3 and 1e-12 here:
// -12 to -3, not a fixed -16..0 with an empty end), in a sequential map, and failed cells are grey, not the
// failure-mode key's black for non-finite.
TEST(StabilityCharts, TheErrorScaleIsTrimmedToTheData) {
  ASSERT_TRUE(gnuplotAvailable()) << kGnuplotIsInstalled;
  const std::string folder = sl::testing::freshTestFolder("trimmed");
  const CsvTable rows = syntheticStabilityRows();
  const auto written = writeStabilityCharts(rows, "pole", folder);
  ASSERT_EQ(written.size(), 1u);
  const std::string script = fileBytes(std::filesystem::path(written[0]).replace_extension(".gp").string());
  EXPECT_NE(script.find("set cbrange [-12:-3]"), std::string::npos) << script;
  EXPECT_NE(script.find("'#440154'"), std::string::npos);  // viridis
  EXPECT_NE(script.find("(grey: failed)"), std::string::npos);
  EXPECT_EQ(script.find("#303030"), std::string::npos);
}

TEST(WorkPrecisionCharts, DrawsThreeChartsPerStartAndTheWorstCase) {
  ASSERT_TRUE(gnuplotAvailable()) << kGnuplotIsInstalled;
  std::vector<WorkPrecisionPoint> points;
  for (double h : {0.1, 0.01})
    for (const std::string start : {"generic", "seam-crossing"}) {
      WorkPrecisionPoint p{start, Method::ChristoffelFd, Integrator::Rk4, h, Method::Ambient, {}};
      p.measurement.maxError = h * h * h * h;
      p.measurement.evaluations = static_cast<long>(80 / h);
      p.measurement.wallSeconds = 1e-5 / h;
      if (start == "seam-crossing" && h == 0.1) p.measurement.status = StopReason::NonFinite;
      points.push_back(p);
    }
  const std::string folder = sl::testing::freshTestFolder("wp");
  const auto written = writeWorkPrecisionCharts(points, folder);
  EXPECT_EQ(written.size(), 9u);
  for (const auto& png : written) {
    EXPECT_TRUE(isPng(png)) << png;
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(png).replace_extension(".gp"))) << png;
  }
}

TEST(WorkPrecisionCharts, EveryMethodHasItsOwnColourAndMarkerAndEveryIntegratorItsOwnDash) {
  std::set<std::string> colors;
  std::set<int> markers, dashes;
  for (const auto& method : kMethods) {
    const SeriesStyle style = workPrecisionStyle(method.kind, Integrator::Rkf78);
    colors.insert(style.color);
    markers.insert(style.pointType);
  }
  for (const auto& integrator : kIntegrators) dashes.insert(workPrecisionStyle(Method::Ambient, integrator.kind).dashType);
  EXPECT_EQ(colors.size(), kMethods.size());
  EXPECT_EQ(markers.size(), kMethods.size());
  EXPECT_EQ(dashes.size(), kIntegrators.size());
}

// Every method x integrator, two settings, one start; every -fd run fails.
std::vector<WorkPrecisionPoint> everySeries() {
  std::vector<WorkPrecisionPoint> points;
  for (const auto& method : kMethods)
    for (const auto& integrator : kIntegrators)
      for (double setting : {1e-6, 1e-9}) {
        WorkPrecisionPoint p{"generic", method.kind, integrator.kind, setting, Method::Ambient, {}};
        p.measurement.maxError = setting * 10;
        p.measurement.maxEnergyDrift = setting;
        p.measurement.evaluations = static_cast<long>(-100 * std::log10(setting));
        p.measurement.wallSeconds = p.measurement.evaluations * 1e-6;
        if (method.kind == Method::ChristoffelFd || method.kind == Method::EmbeddedFd)
          p.measurement.status = StopReason::PoleFoldBack;
        points.push_back(p);
      }
  return points;
}

TEST(WorkPrecisionCharts, TwentySeriesBecomeOnePanelPerIntegratorWithAFailureEntryPerMethodAndTrimmedAxes) {
  ASSERT_TRUE(gnuplotAvailable()) << kGnuplotIsInstalled;
  const std::string folder = sl::testing::freshTestFolder("wp-multiples");
  writeWorkPrecisionCharts(everySeries(), folder);
  const std::string script = fileBytes(folder + "/wp-generic-error-time.gp");
  EXPECT_NE(script.find("set multiplot layout 2,2"), std::string::npos) << script;
  size_t plots = 0;
  for (size_t at = script.find("\nplot "); at != std::string::npos; at = script.find("\nplot ", at + 1)) ++plots;
  EXPECT_EQ(plots, kIntegrators.size());
  for (const std::string name : {"christoffel-fd", "embedded-fd"}) {
    const std::string entry = "title 'failed: " + name + "'";
    size_t count = 0;
    for (size_t at = script.find(entry); at != std::string::npos; at = script.find(entry, at + 1)) ++count;
    EXPECT_EQ(count, kIntegrators.size()) << entry;  // once per panel, in the method's colour
  }
  EXPECT_EQ(script.find("failed: ambient"), std::string::npos);
  // Errors from 1e-8 to 1e-5: the y axis starts at 1e-8, not at the old fixed 1e-17, and ends just above the
  // failure band, whose label no decade label crowds (10^2 sat right above 'failed').
  EXPECT_NE(script.find("set yrange [1e-08:60]"), std::string::npos) << script;
  EXPECT_NE(script.find("'10^{0}' 1e0, "), std::string::npos) << script;
  EXPECT_EQ(script.find("1e1,"), std::string::npos) << script;
  EXPECT_NE(script.find("'failed' 30)"), std::string::npos) << script;
  // A method x integrator whose every point failed has no line entry in the legend, only its crosses.
  for (const auto& p : everySeries()) {
    const bool listed = script.find("title '" + nameOf(p.method) + " " + nameOf(p.integrator) + "'") != std::string::npos;
    EXPECT_EQ(listed, !p.measurement.failed()) << nameOf(p.method) << " " << nameOf(p.integrator);
  }
  // Four series or fewer stay one chart.
  std::vector<WorkPrecisionPoint> few;
  for (const auto& p : everySeries())
    if (p.integrator == Integrator::Rkf78) few.push_back(p);
  const std::string single = sl::testing::freshTestFolder("wp-single");
  writeWorkPrecisionCharts(few, single);
  EXPECT_EQ(fileBytes(single + "/wp-generic-error-time.gp").find("multiplot"), std::string::npos);
}

}  // namespace
}  // namespace sl

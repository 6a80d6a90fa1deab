// Charts: gnuplot draws them, from the data alone (same rows, same PNG bytes).

#include <filesystem>
#include <fstream>
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

TEST(StabilityCharts, TheSameRowsDrawTheSameBytes) {
  if (!gnuplotAvailable()) GTEST_SKIP() << "gnuplot with pngcairo not installed (apt-get install gnuplot-nox)";
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

TEST(WorkPrecisionCharts, DrawsThreeChartsPerStartAndTheWorstCase) {
  if (!gnuplotAvailable()) GTEST_SKIP() << "gnuplot with pngcairo not installed (apt-get install gnuplot-nox)";
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

}  // namespace
}  // namespace sl

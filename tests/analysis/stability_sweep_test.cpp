// The stability sweep machinery on tiny grids: bytes independent of threads and shards, the published
// method's pole failure classified, cells well formed, and the summary's fractions.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "analysis/stability_sweep.hpp"
#include "test_paths.hpp"

namespace sl {
namespace {

StabilityOptions tinySweep(const std::string& kind) {
  StabilityOptions options;
  options.kind = kind;
  options.grid = 4;
  options.duration = 2;
  options.methods = {"christoffel-fd", "ambient"};
  // Each method's sweep default: rk4 with step 0.01 for christoffel-fd, the default run's integrator for ambient.
  options.threads = 2;
  return options;
}

// One run of the pole sweep, shared by the tests that only read it.
const CsvTable& poleSweep() {
  static const CsvTable rows = runStabilitySweep(tinySweep("pole"));
  return rows;
}

TEST(StabilitySweep, HasOneRowPerCellAndMethodInCellOrder) {
  const CsvTable& rows = poleSweep();
  EXPECT_EQ(rows.columns, stabilityColumns());
  ASSERT_EQ(rows.rows.size(), 4u * 4u * 2u);
  for (size_t r = 0; r < rows.rows.size(); ++r) {
    EXPECT_EQ(std::stol(rows.text(r, "cell")), static_cast<long>(r / 2));
    EXPECT_EQ(rows.text(r, "method"), r % 2 == 0 ? "christoffel-fd" : "ambient");
  }
}

TEST(StabilitySweep, ThreadCountDoesNotChangeTheBytes) {
  StabilityOptions options = tinySweep("seam");
  options.threads = 1;
  const std::string single = csvText(runStabilitySweep(options));
  options.threads = 3;
  EXPECT_EQ(csvText(runStabilitySweep(options)), single);
}

TEST(StabilitySweep, MergedShardsEqualASingleRunByteForByte) {
  const std::string folder = sl::testing::freshTestFolder("shards");
  const StabilityOptions options = tinySweep("pole");
  const std::string single = csvText(poleSweep());
  CsvTable merged;
  for (int k = 1; k <= 3; ++k) {
    EXPECT_FALSE(mergeStabilityShards(folder, options.kind, 3, merged)) << "merged before shard " << k << " ran";
    StabilityOptions shard = options;
    shard.shard = {k, 3};
    shard.threads = 1;
    writeFileAtomically(stabilityShardPath(folder, options.kind, shard.shard), csvText(runStabilitySweep(shard)));
  }
  EXPECT_EQ(stabilityShardCounts(folder, options.kind), std::vector<int>{3});
  ASSERT_TRUE(mergeStabilityShards(folder, options.kind, 3, merged));
  EXPECT_EQ(csvText(merged), single);
}

TEST(StabilitySweep, MergingShardsOfDifferentGridsIsRefused) {
  const std::string folder = sl::testing::freshTestFolder("mixed");
  StabilityOptions options = tinySweep("seam");
  options.methods = {"ambient"};
  options.duration = 0.2;
  options.shard = {1, 2};
  writeFileAtomically(stabilityShardPath(folder, "seam", options.shard), csvText(runStabilitySweep(options)));
  options.grid = 3;
  options.shard = {2, 2};
  writeFileAtomically(stabilityShardPath(folder, "seam", options.shard), csvText(runStabilitySweep(options)));
  CsvTable merged;
  EXPECT_THROW(mergeStabilityShards(folder, "seam", 2, merged), std::runtime_error);
}

// Columns of the pole sweep (grid 4): closest approach 0 (exactly through the pole), 10^-7.7, 10^-4.3
// and 10^-1, at half the duration. Within the published method's pole margin it is stopped as a pole
// fold-back, unless one RK4 step jumps from outside the margin (|cos phi| = 1e-3) across the pole, whose
// stages then evaluate the fields beyond it: non-finite (seen in 1 of these 8 cells). Exactly through
// the pole it fails too; the chart-free method carries on accurately everywhere.
TEST(StabilitySweep, ThePublishedMethodFoldsBackNearThePole) {
  const CsvTable& rows = poleSweep();
  int foldBacks = 0;
  for (size_t r = 0; r < rows.rows.size(); ++r) {
    const int column = std::stoi(rows.text(r, "i"));
    if (rows.text(r, "method") == "christoffel-fd") {
      EXPECT_EQ(rows.text(r, "integrator"), "rk4");
      if (column == 1 || column == 2) {
        const std::string status = rows.text(r, "status");
        EXPECT_TRUE(status == "pole-fold-back" || status == "non-finite")
            << status << ": " << rows.text(r, "stop_detail");
        foldBacks += status == "pole-fold-back";
      }
      if (column < 3) EXPECT_LE(rows.number(r, "stop_time"), 1.0);
      if (column == 0) EXPECT_NE(rows.text(r, "status"), "ok");
    }
    if (rows.text(r, "method") == "ambient") {
      EXPECT_EQ(rows.text(r, "status"), "ok");
      EXPECT_LT(rows.number(r, "max_error"), 1e-7);
    }
  }
  EXPECT_GE(foldBacks, 6);
}

TEST(StabilitySweep, WithoutAReferenceOnlyFateAndInvariantsAreMeasured) {
  StabilityOptions options = tinySweep("launch");
  options.grid = 2;
  options.methods = {"ambient"};
  options.checkAgainstReference = false;
  const CsvTable rows = runStabilitySweep(options);
  ASSERT_EQ(rows.rows.size(), 4u);
  for (size_t r = 0; r < rows.rows.size(); ++r) {
    EXPECT_EQ(rows.text(r, "status"), "ok");
    EXPECT_EQ(rows.text(r, "reference_method"), "none");
    EXPECT_EQ(rows.text(r, "max_error"), "nan");
    EXPECT_LT(rows.number(r, "max_energy_drift"), 1e-8);
  }
  EXPECT_EQ(stabilitySummary(rows).text(0, "within_1e-9"), "nan");
}

TEST(StabilitySummary, CountsFractionsAndFailureModes) {
  CsvTable rows{stabilityColumns(), {}};
  auto add = [&](const std::string& method, const std::string& status, double error) {
    std::vector<std::string> row(rows.columns.size(), "0");
    row[rows.column("method")] = method;
    row[rows.column("integrator")] = "dopri5";
    row[rows.column("status")] = status;
    row[rows.column("max_error")] = formatNumber(error);
    rows.rows.push_back(row);
  };
  add("embedded", "ok", 1e-12);
  add("embedded", "ok", 1e-7);
  add("embedded", "ok", 1e-3);
  add("embedded", "non-finite", 1e-13);  // failed: never counted as accurate
  add("ambient", "ok", 1e-11);
  const CsvTable summary = stabilitySummary(rows);
  ASSERT_EQ(summary.rows.size(), 2u);
  EXPECT_EQ(summary.text(0, "method"), "embedded");
  EXPECT_EQ(summary.number(0, "within_1e-9"), 0.25);
  EXPECT_EQ(summary.number(0, "within_1e-6"), 0.5);
  EXPECT_EQ(summary.text(0, "non-finite"), "1");
  EXPECT_EQ(summary.text(0, "ok"), "3");
  EXPECT_EQ(summary.number(1, "within_1e-9"), 1.0);
}

TEST(StabilityGrid, EveryKindGivesStartsOnTheSphere) {
  for (const auto& kind : stabilityKindNames()) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const StabilityCell cell = stabilityCell(kind, 3, i, j, 2.0);
        EXPECT_NEAR(cell.start.spherePoint.norm(), 1.0, 1e-9) << kind << " " << i << "," << j;
        EXPECT_NEAR(cell.start.spherePoint.dot(cell.start.sphereVelocity), 0.0, 1e-9) << kind;
        EXPECT_GT(cell.start.sphereVelocity.norm(), 0.1) << kind;
        EXPECT_GT(cell.chain.baseLength, 2.0);
        EXPECT_LT(cell.chain.baseLength, 4.0);
      }
    }
  }
  EXPECT_NEAR(stabilityCell("length", 3, 0, 0, 2.0).chain.baseLength - 2.0, 1e-6, 1e-12);
  EXPECT_NEAR(4.0 - stabilityCell("length", 3, 2, 0, 2.0).chain.baseLength, 1e-6, 1e-12);
  EXPECT_EQ(stabilityCell("seam", 3, 0, 1, 2.0).start.spherePoint(0), std::cos(0.3) * std::cos(std::numbers::pi / 2));
  EXPECT_THROW(stabilityCell("nowhere", 3, 0, 0, 2.0), std::invalid_argument);
}

TEST(Shard, ParsesKOfNAndRefusesNonsense) {
  EXPECT_EQ(parseShard("2/5").index, 2);
  EXPECT_EQ(parseShard("2/5").count, 5);
  for (const char* bad : {"0/3", "4/3", "1", "a/b", "1/0", "-1/2"})
    EXPECT_THROW(parseShard(bad), std::invalid_argument) << bad;
}

}  // namespace
}  // namespace sl

// The stability sweep machinery on tiny grids: bytes independent of threads and shards, the published
// method's pole failure classified, cells well formed, and the summary's fractions.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "analysis/measurement.hpp"
#include "analysis/stability_sweep.hpp"
#include "contracts/parallel_for.hpp"
#include "contracts/registry.hpp"
#include "output/atomic_file.hpp"
#include "test_paths.hpp"

namespace sl {
namespace {

StabilityOptions tinySweep(const std::string& kind) {
  StabilityOptions options;
  options.kind = kind;
  options.grid = 4;
  options.duration = 2;
  options.methods = {Method::ChristoffelFd, Method::Ambient};
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
    EXPECT_EQ(rows.text(r, "method"), nameOf(r % 2 == 0 ? Method::ChristoffelFd : Method::Ambient));
  }
}

TEST(StabilitySweep, ThreadCountDoesNotChangeTheBytes) {
  StabilityOptions options = tinySweep("seam");
  options.threads = 1;
  const std::string single = csvText(runStabilitySweep(options));
  options.threads = 3;
  EXPECT_EQ(csvText(runStabilitySweep(options)), single);
}

TEST(StabilitySweep, ThreadsThatCannotStartLeaveTheSameTableNotAnAbort) {
  StabilityOptions options = tinySweep("seam");
  options.threads = 1;
  const std::string single = csvText(runStabilitySweep(options));
  options.threads = 16;
  failThreadStartsAfterForTesting(1);  // as under a process limit: one helper starts, fifteen do not
  std::string starved;
  try {
    starved = csvText(runStabilitySweep(options));
  } catch (...) {
    failThreadStartsAfterForTesting(-1);
    throw;
  }
  failThreadStartsAfterForTesting(-1);
  EXPECT_EQ(starved, single);
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
    output::writeFileAtomically(stabilityShardPath(folder, options.kind, shard.shard),
                                csvText(runStabilitySweep(shard)));
  }
  EXPECT_EQ(stabilityShardCounts(folder, options.kind), std::vector<int>{3});
  ASSERT_TRUE(mergeStabilityShards(folder, options.kind, 3, merged));
  EXPECT_EQ(csvText(merged), single);
}

TEST(StabilitySweep, MergingShardsOfDifferentGridsIsRefused) {
  const std::string folder = sl::testing::freshTestFolder("mixed");
  StabilityOptions options = tinySweep("seam");
  options.methods = {Method::Ambient};
  options.duration = 0.2;
  options.shard = {1, 2};
  output::writeFileAtomically(stabilityShardPath(folder, "seam", options.shard), csvText(runStabilitySweep(options)));
  options.grid = 3;
  options.shard = {2, 2};
  output::writeFileAtomically(stabilityShardPath(folder, "seam", options.shard), csvText(runStabilitySweep(options)));
  CsvTable merged;
  EXPECT_THROW(mergeStabilityShards(folder, "seam", 2, merged), std::invalid_argument);
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
    if (rows.text(r, "method") == nameOf(Method::ChristoffelFd)) {
      EXPECT_EQ(rows.text(r, "integrator"), nameOf(Integrator::Rk4));
      if (column == 1 || column == 2) {
        const std::string status = rows.text(r, "status");
        EXPECT_TRUE(status == nameOf(StopReason::PoleFoldBack) || status == nameOf(StopReason::NonFinite))
            << status << ": " << rows.text(r, "stop_detail");
        foldBacks += status == nameOf(StopReason::PoleFoldBack);
      }
      if (column < 3) {
        EXPECT_LE(rows.number(r, "stop_time"), 1.0);
      }
      if (column == 0) {
        EXPECT_NE(rows.text(r, "status"), nameOf(Verdict::Ok));
      }
    }
    if (rows.text(r, "method") == nameOf(Method::Ambient)) {
      EXPECT_EQ(rows.text(r, "status"), nameOf(Verdict::Ok));
      EXPECT_LT(rows.number(r, "max_error"), 1e-7);
    }
  }
  EXPECT_GE(foldBacks, 6);
}

TEST(StabilitySweep, WithoutAReferenceOnlyFateAndInvariantsAreMeasured) {
  StabilityOptions options = tinySweep("launch");
  options.grid = 2;
  options.methods = {Method::Ambient};
  options.checkAgainstReference = false;
  const CsvTable rows = runStabilitySweep(options);
  ASSERT_EQ(rows.rows.size(), 4u);
  for (size_t r = 0; r < rows.rows.size(); ++r) {
    EXPECT_EQ(rows.text(r, "status"), nameOf(Verdict::Ok));
    EXPECT_EQ(rows.text(r, "reference_method"), "none");
    EXPECT_EQ(rows.text(r, "max_error"), "");  // no value
    EXPECT_LT(rows.number(r, "max_energy_drift"), 1e-8);
  }
  EXPECT_EQ(stabilitySummary(rows).text(0, "within_1e-9"), "");
}

TEST(StabilitySummary, CountsFractionsAndFailureModes) {
  CsvTable rows{stabilityColumns(), {}};
  auto add = [&](Method method, const RunStatus& status, double error) {
    std::vector<std::string> row(rows.columns.size(), "0");
    row[rows.column("method")] = nameOf(method);
    row[rows.column("integrator")] = nameOf(Integrator::Dopri5);
    row[rows.column("status")] = statusName(status);
    row[rows.column("max_error")] = formatNumber(error);
    rows.rows.push_back(row);
  };
  add(Method::Embedded, Verdict::Ok, 1e-12);
  add(Method::Embedded, Verdict::Ok, 1e-7);
  add(Method::Embedded, Verdict::Ok, 1e-3);
  add(Method::Embedded, StopReason::NonFinite, 1e-13);  // failed: never counted as accurate
  add(Method::Ambient, Verdict::Ok, 1e-11);
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

// The summary's columns and the maps' colour codes follow this order: it must not move.
TEST(StabilityStatus, NamesKeepTheirOrderAndCodes) {
  const std::vector<std::string> expected = {"ok",
                                             "wrong-path",
                                             "pole-fold-back",
                                             "field-blow-up",
                                             "non-finite",
                                             "energy-blow-up",
                                             "step-size-collapse",
                                             "rod-length",
                                             "max-steps",
                                             "constraint-rank-loss",
                                             "reference-stopped",
                                             "other"};
  EXPECT_EQ(stabilityStatusNames(), expected);
  for (const auto& reason : kStopReasons) EXPECT_LT(stabilityStatusCode(std::string(reason.name)), 10) << reason.name;
  EXPECT_EQ(stabilityStatusCode("reference-stopped"), 10);
  EXPECT_EQ(stabilityStatusCode("no such status"), 11);
}

TEST(StabilitySweep, ThePublishedMethodsAreSweptWithRk4AndTheOthersWithTheDefaultIntegrator) {
  EXPECT_EQ(sweepIntegratorFor(Method::ChristoffelFd), Integrator::Rk4);
  EXPECT_EQ(sweepIntegratorFor(Method::EmbeddedFd), Integrator::Rk4);
  for (const Method method : {Method::Christoffel, Method::Embedded, Method::Ambient})
    EXPECT_EQ(sweepIntegratorFor(method), RunConfig().integrator) << nameOf(method);
}

}  // namespace
}  // namespace sl

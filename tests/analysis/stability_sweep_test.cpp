// The stability sweep machinery on tiny grids: bytes independent of threads and shards, the published
// method's pole failure classified, cells well formed, and the summary's fractions.

#include <cmath>
#include <functional>
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
  static const CsvTable rows = stabilityTable(runStabilitySweep(tinySweep("pole")));
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
  const std::string single = csvText(stabilityTable(runStabilitySweep(options)));
  options.threads = 3;
  EXPECT_EQ(csvText(stabilityTable(runStabilitySweep(options))), single);
}

TEST(StabilitySweep, ThreadsThatCannotStartLeaveTheSameTableNotAnAbort) {
  StabilityOptions options = tinySweep("seam");
  options.threads = 1;
  const std::string single = csvText(stabilityTable(runStabilitySweep(options)));
  options.threads = 16;
  failThreadStartsAfterForTesting(1);  // as under a process limit: one helper starts, fifteen do not
  std::string starved;
  try {
    starved = csvText(stabilityTable(runStabilitySweep(options)));
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
  std::vector<StabilityRow> merged;
  for (int k = 1; k <= 3; ++k) {
    EXPECT_FALSE(mergeStabilityShards(folder, options.kind, 3, merged)) << "merged before shard " << k << " ran";
    StabilityOptions shard = options;
    shard.shard = {k, 3};
    shard.threads = 1;
    writeFileAtomically(stabilityShardPath(folder, options.kind, shard.shard),
                                stabilityShardText(shard, runStabilitySweep(shard)));
  }
  EXPECT_EQ(stabilityShardCounts(folder, options.kind), std::vector<int>{3});
  ASSERT_TRUE(mergeStabilityShards(folder, options.kind, 3, merged));
  EXPECT_EQ(csvText(stabilityTable(merged)), single);
}

// Shards of different sweeps never merge: each records its whole job, and the message names what differs.
TEST(StabilitySweep, MergingShardsOfDifferentSweepsIsRefusedNamingTheDifference) {
  StabilityOptions options = tinySweep("seam");
  options.methods = {Method::Ambient};
  options.duration = 0.2;
  options.grid = 2;
  const std::vector<std::pair<std::string, std::function<void(StabilityOptions&)>>> changes = {
      {"grid 3 here, 2 in shard 1", [](StabilityOptions& o) { o.grid = 3; }},
      {"duration 0.3 here, 0.2 in shard 1", [](StabilityOptions& o) { o.duration = 0.3; }},
      {"tolerance 1e-07 here", [](StabilityOptions& o) { o.tolerance = 1e-7; }},
      {"step 0.02 here", [](StabilityOptions& o) { o.step = 0.02; }},
      {"interval 0.05 here", [](StabilityOptions& o) { o.sampleInterval = 0.05; }},
      {"integrators rk4 here, rkf78 in shard 1", [](StabilityOptions& o) { o.integrator = Integrator::Rk4; }},
      {"references none here, embedded in shard 1", [](StabilityOptions& o) { o.checkAgainstReference = false; }},
      {"methods embedded here, ambient in shard 1", [](StabilityOptions& o) { o.methods = {Method::Embedded}; }},
  };
  for (const auto& [expected, change] : changes) {
    SCOPED_TRACE(expected);
    const std::string folder = sl::testing::freshTestFolder("mixed");
    StabilityOptions first = options;
    first.shard = {1, 2};
    writeFileAtomically(stabilityShardPath(folder, "seam", first.shard),
                                stabilityShardText(first, runStabilitySweep(first)));
    StabilityOptions second = options;
    change(second);
    second.shard = {2, 2};
    writeFileAtomically(stabilityShardPath(folder, "seam", second.shard),
                                stabilityShardText(second, runStabilitySweep(second)));
    std::vector<StabilityRow> merged;
    try {
      mergeStabilityShards(folder, "seam", 2, merged);
      ADD_FAILURE() << "merged shards of different sweeps";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("a shard of another sweep"), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
  }
}

// A shard file is read as strictly as a scene: no identity line, a field that is not its column's, a row of
// another cell, a cut file: each refused naming the file (and row).
TEST(StabilitySweep, ShardFilesAreReadStrictly) {
  StabilityOptions options = tinySweep("seam");
  options.methods = {Method::Ambient};
  options.duration = 0.2;
  options.grid = 2;
  options.shard = {1, 2};
  const std::string good = stabilityShardText(options, runStabilitySweep(options));
  StabilityOptions second = options;
  second.shard = {2, 2};
  const std::string other = stabilityShardText(second, runStabilitySweep(second));
  const size_t header = good.find('\n') + 1, firstRow = good.find('\n', header) + 1;
  const std::string row = good.substr(firstRow, good.find('\n', firstRow) + 1 - firstRow);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {good.substr(header), "not a stability shard of this version"},
      {good.substr(0, firstRow) + "0,0,0,x" + row.substr(row.find(',', 6)), "column x is 'x', expected a number"},
      {good.substr(0, firstRow) + "2" + row.substr(1) + good.substr(firstRow + row.size()), "expected cell 0"},
      {good.substr(0, firstRow + row.size()), "ends before cell 2"},
      {good.substr(0, firstRow) + row.substr(0, row.find("ambient")) + "nonsense" +
           row.substr(row.find("ambient") + 7) + good.substr(firstRow + row.size()),
       "column method is 'nonsense', not a known name"},
  };
  for (const auto& [text, expected] : cases) {
    SCOPED_TRACE(expected);
    const std::string folder = sl::testing::freshTestFolder("strict");
    writeFileAtomically(stabilityShardPath(folder, "seam", {1, 2}), text);
    writeFileAtomically(stabilityShardPath(folder, "seam", {2, 2}), other);
    std::vector<StabilityRow> merged;
    try {
      mergeStabilityShards(folder, "seam", 2, merged);
      ADD_FAILURE() << "merged a bad shard";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("shard-1-of-2.csv"), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
  }
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
  const std::vector<StabilityRow> sweep = runStabilitySweep(options);
  const CsvTable rows = stabilityTable(sweep);
  ASSERT_EQ(rows.rows.size(), 4u);
  for (size_t r = 0; r < rows.rows.size(); ++r) {
    EXPECT_EQ(rows.text(r, "status"), nameOf(Verdict::Ok));
    EXPECT_EQ(rows.text(r, "reference_method"), "none");
    EXPECT_EQ(rows.text(r, "max_error"), "");  // no value
    EXPECT_LT(rows.number(r, "max_energy_drift"), 1e-8);
  }
  EXPECT_EQ(stabilitySummary(sweep).text(0, "within_1e-9"), "");
}

TEST(StabilitySummary, CountsFractionsAndFailureModes) {
  std::vector<StabilityRow> rows;
  auto add = [&](Method method, const RunStatus& status, double error) {
    StabilityRow row;
    row.method = method;
    row.integrator = Integrator::Dopri5;
    row.status = status;
    row.maxError = error;
    row.referenceMethod = "0";
    rows.push_back(row);
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

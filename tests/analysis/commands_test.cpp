// The two subcommands end to end on tiny inputs, and their refusals of bad arguments.

#include <filesystem>

#include <gtest/gtest.h>
#include <CLI/CLI.hpp>

#include "analysis/csv_table.hpp"
#include "cli/commands.hpp"
#include "test_paths.hpp"

namespace sl {
namespace {

void parse(std::vector<std::string> arguments) {
  CLI::App app("linkage");
  app.require_subcommand(1);
  addBenchCommand(app);
  addStabilityCommand(app);
  arguments.insert(arguments.begin(), "linkage");
  std::vector<char*> argv;
  for (auto& argument : arguments) argv.push_back(argument.data());
  app.parse(static_cast<int>(argv.size()), argv.data());
}

TEST(StabilityCommand, WritesTheCsvAndSummaryOfASweep) {
  const std::string out = sl::testing::freshTestFolder("out");
  parse({"stability", "--kind", "seam", "--grid", "2", "--duration", "0.5", "--methods", "embedded,ambient",
         "--threads", "2", "--no-charts", "--quiet", "--out", out});
  const CsvTable rows = readCsvFile(out + "/stability-seam.csv");
  EXPECT_EQ(rows.rows.size(), 2u * 2u * 2u);
  const CsvTable summary = readCsvFile(out + "/stability-seam-summary.csv");
  EXPECT_EQ(summary.rows.size(), 2u);
}

TEST(StabilityCommand, TheLastShardMergesAutomatically) {
  const std::string out = sl::testing::freshTestFolder("out");
  const std::vector<std::string> common = {"stability",  "--kind", "length",    "--grid",  "2",
                                           "--duration", "0.3",    "--methods", "ambient", "--no-charts",
                                           "--quiet",    "--out",  out};
  auto withShard = [&](const std::string& shard) {
    auto arguments = common;
    arguments.insert(arguments.end(), {"--shard", shard});
    return arguments;
  };
  parse(withShard("2/2"));
  EXPECT_FALSE(std::filesystem::exists(out + "/stability-length.csv"));
  parse(withShard("1/2"));
  ASSERT_TRUE(std::filesystem::exists(out + "/stability-length.csv"));
  EXPECT_EQ(readCsvFile(out + "/stability-length.csv").rows.size(), 4u);
}

TEST(StabilityCommand, RefusesUnknownKindsMethodsAndShards) {
  const std::string out = sl::testing::freshTestFolder("out");
  EXPECT_THROW(parse({"stability", "--kind", "poles", "--out", out}), CLI::ValidationError);
  EXPECT_THROW(parse({"stability", "--methods", "ambiant", "--out", out}), std::invalid_argument);
  EXPECT_THROW(parse({"stability", "--grid", "0", "--out", out}), CLI::ValidationError);
  EXPECT_THROW(parse({"stability", "--shard", "3/2", "--no-charts", "--grid", "1", "--out", out}),
               std::invalid_argument);
  EXPECT_THROW(parse({"stability", "--merge", "--no-charts", "--out", out}), std::runtime_error);
}

TEST(BenchCommand, WritesTheCsvAndTheCheapestSettingTable) {
  const std::string out = sl::testing::freshTestFolder("out");
  parse({"bench", "--start", "generic", "--methods", "ambient", "--integrators", "dopri5", "--tolerances", "1e-6,1e-9",
         "--repeats", "1", "--no-charts", "--out", out});
  const CsvTable rows = readCsvFile(out + "/work-precision.csv");
  ASSERT_EQ(rows.rows.size(), 2u);
  EXPECT_EQ(rows.text(0, "reference_method"), "embedded");
  EXPECT_TRUE(std::filesystem::exists(out + "/cheapest-settings.txt"));
}

TEST(BenchCommand, RefusesUnknownStartsAndIntegrators) {
  const std::string out = sl::testing::freshTestFolder("out");
  EXPECT_THROW(parse({"bench", "--start", "nowhere", "--no-charts", "--out", out}), CLI::ValidationError);
  EXPECT_THROW(parse({"bench", "--integrators", "euler", "--no-charts", "--out", out}), std::invalid_argument);
  // Refused by the option's own check (the one finite-number rule of every option), before the command runs.
  EXPECT_THROW(parse({"bench", "--steps", "0", "--no-charts", "--out", out}), CLI::ValidationError);
}

TEST(StabilityCommand, AnUnknownIntegratorNamesTheOptionAndTheChoices) {
  const std::string out = sl::testing::freshTestFolder("out");
  try {
    parse({"stability", "--integrator", "euler", "--no-charts", "--out", out});
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(),
                 "--integrator: unknown integrator 'euler' (expected rk4, dopri5, rkf78 or bulirsch-stoer)");
  }
}

}  // namespace
}  // namespace sl

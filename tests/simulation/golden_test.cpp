// Golden trajectories: short runs per method stored as trajectory CSV under tests/data/golden/, so that a
// change in any method's numbers shows up even where the cross-method tests still pass. Tolerances are per
// method: the -fd methods amplify rounding (difference quotients), the exact ones do not.
//
// Regenerate on purpose (after an intended change, and say why in the commit):
//   SL_REGENERATE_GOLDENS=1 ./build/tests/simulation/test_simulation --gtest_filter='*Golden*'
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "simulation/trajectory_csv.hpp"
#include "support.hpp"

namespace sl {
namespace {

struct GoldenCase {
  std::string name;
  Chain chain;
  std::string method, integrator;
  double tolerance;  // of the adaptive integrators (rk4 runs with h = 0.01)
  double allowed;    // max difference from the stored numbers
};

Chain fiveRodsWithMasses() {
  Chain chain = Chain::uniform(5, 3.6);
  chain.hingeMasses << 1.0, 2.0, 0.5, 1.5;
  chain.rodMasses << 0.2, 0.4, 0.0, 0.3, 0.1;
  return chain;
}

std::vector<GoldenCase> goldenCases() {
  const Chain spec = Chain::uniform(4, 3.0);
  return {
      {"christoffel_fd_rk4", spec, "christoffel-fd", "rk4", 1e-10, 1e-9},
      {"embedded_fd_rk4", spec, "embedded-fd", "rk4", 1e-10, 1e-8},
      {"christoffel_dopri5", spec, "christoffel", "dopri5", 1e-11, 1e-12},
      {"embedded_dopri5", spec, "embedded", "dopri5", 1e-11, 1e-12},
      {"ambient_rkf78", spec, "ambient", "rkf78", 1e-13, 1e-12},
      {"ambient_five_rods_masses_bulirsch_stoer", fiveRodsWithMasses(), "ambient", "bulirsch-stoer", 1e-12, 1e-12},
  };
}

std::string goldenPath(const std::string& name) {
  return std::string(SL_SOURCE_DIR) + "/tests/data/golden/" + name + ".csv";
}

std::string runCsv(const GoldenCase& c) {
  RunConfig config = testing::config(c.method, c.integrator, c.tolerance);
  config.step = 0.01;
  InitialState start = c.chain.rods == 4 ? testing::genericStart(c.chain)
                                         : initialStateFromDrag(c.chain, Eigen::Vector4d(0.5, -0.2, 0.7, 0.4),
                                                                Eigen::Vector4d(0.3, 1.0, -0.4, 0.2), true);
  Trajectory run(c.chain, start, config);
  std::ostringstream out;
  writeTrajectoryCsv(out, c.name, run, testing::evenTimes(2.0, 20));
  return out.str();
}

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesTheStoredTrajectory) {
  const GoldenCase& c = GetParam();
  const std::string fresh = runCsv(c);
  if (std::getenv("SL_REGENERATE_GOLDENS")) {
    std::ofstream(goldenPath(c.name)) << fresh;
    GTEST_SKIP() << "regenerated " << goldenPath(c.name);
  }
  std::ifstream stored(goldenPath(c.name));
  ASSERT_TRUE(stored) << "missing " << goldenPath(c.name) << " (see the regeneration command at the top of this file)";
  const TrajectoryCsv expected = readTrajectoryCsv(stored, goldenPath(c.name));
  std::istringstream freshIn(fresh);
  const TrajectoryCsv actual = readTrajectoryCsv(freshIn, "fresh run");
  ASSERT_EQ(actual.columns, expected.columns);
  ASSERT_EQ(actual.rows.size(), expected.rows.size());
  for (size_t i = 0; i < actual.rows.size(); ++i) {
    EXPECT_EQ(actual.rows[i].status, expected.rows[i].status);
    for (size_t k = 0; k < actual.rows[i].values.size(); ++k)
      EXPECT_NEAR(actual.rows[i].values[k], expected.rows[i].values[k], c.allowed)
          << c.name << " row " << i << " column " << actual.columns[k + 1];
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, Golden, ::testing::ValuesIn(goldenCases()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace sl

// The yardstick: every exact method against the independent reference trajectories (hinge positions
// trusted to ~2e-9) over T = 20, with energy and rod-length invariants.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "support.hpp"

namespace sl {
namespace {

struct Case {
  std::string method, integrator;
  double tolerance;
};

class AgainstReference : public ::testing::TestWithParam<Case> {};

void compareWithReference(const std::string& file, InitialState (*start)(const Chain&), const Case& c) {
  const Chain chain = Chain::uniform(4, 3.0);
  const std::vector<testing::ReferenceRow> rows = testing::loadReference(file);
  Trajectory run(chain, start(chain), testing::config(c.method, c.integrator, c.tolerance));
  double worst = 0, worstDrift = 0, worstRod = 0;
  for (size_t i = 0; i < rows.size(); i += 5) {
    const auto s = run.sampleAt(rows[i].time);
    ASSERT_TRUE(s) << c.method << " stopped: " << nameOf(run.stop()->reason) << " " << run.stop()->detail();
    worst = std::max(worst, (s->hinges - rows[i].hinges).cwiseAbs().maxCoeff());
    worstDrift = std::max(worstDrift, s->relativeEnergyDrift);
    worstRod = std::max(worstRod, s->rodLengthError);
    EXPECT_NEAR(2 * s->energy, rows[i].speed2, 1e-9 * rows[i].speed2);
  }
  std::cout << file << " " << c.method << "/" << c.integrator << " tol " << c.tolerance << ": max hinge error " << worst
            << ", energy drift " << worstDrift << ", rod error " << worstRod << ", steps " << run.steps()
            << ", evaluations " << run.vectorFieldEvaluations() << "\n";
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(worstDrift, 1e-9);
  EXPECT_LT(worstRod, 1e-12);
}

TEST_P(AgainstReference, GenericPathNearAPole) {
  compareWithReference("generic_L3.csv", testing::genericStart, GetParam());
}
TEST_P(AgainstReference, SeamCrossings) {
  compareWithReference("seam_crossings_L3.csv", testing::seamStart, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Methods, AgainstReference,
                         ::testing::Values(Case{"christoffel", "dopri5", 1e-12}, Case{"embedded", "dopri5", 1e-12},
                                           Case{"ambient", "dopri5", 1e-12}, Case{"ambient", "bulirsch-stoer", 1e-12},
                                           Case{"christoffel", "bulirsch-stoer", 1e-12},
                                           Case{"ambient", "rkf78", 1e-12}, Case{"ambient", "rkf78", 1e-13},
                                           Case{"christoffel", "rkf78", 1e-12}),
                         [](const auto& info) {
                           std::string name =
                               info.param.method + "_" + info.param.integrator + "_tol1e" +
                               std::to_string(static_cast<int>(std::round(-std::log10(info.param.tolerance))));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace sl

// How a single-chart (published) method's failure is named, at the exact thresholds of
// ChartSystem::methodFailureAt: within |cos phi| < 1e-3 of a pole, or just past pi/2, the chart folds back
// (pole-fold-back); a latitude more than 0.25 past pi/2 after one step cannot be a crossing, the vector field
// blew up (field-blow-up). Both are read far from the seam, so the seam's explanation plays no part.
#include <cmath>
#include <optional>

#include <gtest/gtest.h>

#include "linkage/chain_constants.hpp"
#include "simulation/chart_system.hpp"
#include "simulation/initial_state.hpp"

namespace sl {
namespace {

std::optional<StopReason> failureAtLatitude(Method method, double latitude) {
  const Chain chain = Chain::uniform(4, 3.0);
  const ChainConstants bound(chain);
  const Eigen::VectorXd coords = Eigen::Vector2d(0.2, 0.3), rates = Eigen::Vector2d(1, 0);
  const ChartSystem system(bound, chartMethod(method, bound), initialStateFromChart(chain, coords, rates));
  State y = system.initialState();
  y[0] = latitude;
  y[1] = 0.3;  // t, far from the seam t = pi/2
  const auto failure = system.methodFailureAt(y);
  if (!failure) return std::nullopt;
  return failure->reason;
}

TEST(ChartFailures, ThePolesFoldBackAndAJumpFarPastThemIsAFieldBlowUp) {
  const double pole = M_PI / 2;
  for (const Method method : {Method::ChristoffelFd, Method::EmbeddedFd}) {
    SCOPED_TRACE(nameOf(method));
    EXPECT_EQ(failureAtLatitude(method, 0.3), std::nullopt);
    EXPECT_EQ(failureAtLatitude(method, std::acos(1.01e-3)), std::nullopt);  // |cos| just above the margin
    EXPECT_EQ(failureAtLatitude(method, std::acos(0.99e-3)), StopReason::PoleFoldBack);
    EXPECT_EQ(failureAtLatitude(method, -std::acos(0.99e-3)), StopReason::PoleFoldBack);
    EXPECT_EQ(failureAtLatitude(method, pole + 0.1), StopReason::PoleFoldBack);
    EXPECT_EQ(failureAtLatitude(method, pole + 0.249), StopReason::PoleFoldBack);
    EXPECT_EQ(failureAtLatitude(method, pole + 0.251), StopReason::FieldBlowUp);
    EXPECT_EQ(failureAtLatitude(method, -pole - 0.251), StopReason::FieldBlowUp);
    EXPECT_EQ(failureAtLatitude(method, 40.0), StopReason::FieldBlowUp);
  }
  // The exact methods switch charts instead of failing.
  EXPECT_EQ(failureAtLatitude(Method::Christoffel, pole + 0.3), std::nullopt);
}

}  // namespace
}  // namespace sl

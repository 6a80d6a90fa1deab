// The rule every found result passes before it is reported as found (inverse/self_check.hpp): each bound is
// tested on both sides, and a NaN anywhere is never confirmed.
#include <cmath>

#include <gtest/gtest.h>

#include "inverse/self_check.hpp"

namespace sl {
namespace {

ClosedGeodesic closedGeodesic(double closure, std::optional<double> independent) {
  ClosedGeodesic g;
  g.length = 10;
  g.positionClosure = closure;
  g.velocityClosure = closure / 2;
  g.independentLength = independent;
  return g;
}

TEST(SelfCheck, AClosedGeodesicClosesAndItsRoutesAgree) {
  EXPECT_EQ(selfCheck(closedGeodesic(1e-12, 10 + 1e-10)), SelfCheck::confirmed);
  EXPECT_EQ(selfCheck(closedGeodesic(1e-12, std::nullopt)), SelfCheck::confirmed);  // no second route applies
  EXPECT_EQ(selfCheck(closedGeodesic(0.5 * kClosureBound, 10)), SelfCheck::confirmed);
  EXPECT_EQ(selfCheck(closedGeodesic(2 * kClosureBound, 10)), SelfCheck::openClosure);
  // The 3-rod case at L = 1.5 as it was listed: closed to 1.3, the other route 10.769 against 6.655.
  EXPECT_EQ(selfCheck(closedGeodesic(1.3, 10.769)), SelfCheck::openClosure);
  EXPECT_EQ(selfCheck(closedGeodesic(1e-12, 10 * (1 + 2 * kRouteAgreement))), SelfCheck::routesDisagree);
  EXPECT_EQ(selfCheck(closedGeodesic(1e-12, 10 * (1 + 0.5 * kRouteAgreement))), SelfCheck::confirmed);
  EXPECT_EQ(selfCheck(closedGeodesic(NAN, 10)), SelfCheck::notFinite);
  EXPECT_EQ(selfCheck(closedGeodesic(1e-12, NAN)), SelfCheck::notFinite);
  ClosedGeodesic infinite = closedGeodesic(1e-12, std::nullopt);
  infinite.length = INFINITY;
  EXPECT_EQ(selfCheck(infinite), SelfCheck::notFinite);
}

TEST(SelfCheck, AConnectionReachesItsTargetAndItsRoutesAgree) {
  Connection c;
  c.length = 3;
  c.endError = 1e-13;
  EXPECT_EQ(selfCheck(c), SelfCheck::confirmed);
  c.discrete = DiscreteGeodesic{};
  c.discrete->length = 3 + 1e-11;
  EXPECT_EQ(selfCheck(c), SelfCheck::confirmed);
  c.discrete->length = 3.1;
  EXPECT_EQ(selfCheck(c), SelfCheck::routesDisagree);
  c.discrete->length = 3;
  c.endError = 2 * kEndErrorBound;
  EXPECT_EQ(selfCheck(c), SelfCheck::missedTarget);
  c.endError = NAN;
  EXPECT_EQ(selfCheck(c), SelfCheck::notFinite);
}

TEST(SelfCheck, ADistanceMapsTwoInjectivityRadiiAgreeToItsGrid) {
  DistanceMap map;
  map.phis.assign(33, 0.0);  // cells of pi / 32
  map.conjugateRadius = 2.0;
  map.shortestLoop = 0;
  map.injectivityRadius = 2.0 + (kInjectivityAgreementCells - 1) * std::acos(-1.0) / 32;
  EXPECT_EQ(selfCheck(map), SelfCheck::confirmed);
  map.injectivityRadius = 2.0 + (kInjectivityAgreementCells + 1) * std::acos(-1.0) / 32;
  EXPECT_EQ(selfCheck(map), SelfCheck::radiiDisagree);
  map.injectivityRadius = NAN;
  EXPECT_EQ(selfCheck(map), SelfCheck::notFinite);
}

}  // namespace
}  // namespace sl

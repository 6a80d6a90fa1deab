#include <cmath>

#include <gtest/gtest.h>

#include "inverse/periodic.hpp"
#include "inverse/self_check.hpp"
#include "linkage/chart.hpp"

namespace sl {
namespace {

// The 4-rod chain with unit hinge masses: at least three simple closed geodesics (Lyusternik-Schnirelmann),
// each closing to 1e-10 and, where route 2 applies, agreeing with it to 1e-8; the end swap's fixed curve is
// one of them.
TEST(Periodic, FourRodChainHasThreeSimpleClosedGeodesics) {
  for (double length : {2.5, 3.0, 3.5}) {
    const auto found = chainClosedGeodesics(Chain::uniform(4, length), PeriodicOptions{});
    int simple = 0, checked = 0;
    bool fixedSet = false;
    for (const ClosedGeodesic& g : found) {
      EXPECT_LT(g.positionClosure, 1e-10);
      EXPECT_LT(g.velocityClosure, 1e-10);
      EXPECT_NEAR(g.monodromy.determinant(), 1.0, 1e-6) << "L = " << length;
      if (g.simple) ++simple;
      if (g.independentLength) {
        ++checked;
        EXPECT_NEAR(g.length, *g.independentLength, 1e-8) << g.independentRoute;
      }
      if (g.fixedBy(ChainSymmetry::EndSwap)) fixedSet = true;
    }
    EXPECT_GE(simple, 3) << "L = " << length;
    EXPECT_GE(checked, 3) << "L = " << length;
    EXPECT_TRUE(fixedSet);
  }
}

// Asymmetric hinge masses: only the mirror is left; shooting half a period to the mirror image finds the three.
TEST(Periodic, AsymmetricMassesStillThreeSimple) {
  Chain chain = Chain::uniform(4, 3.0);
  chain.hingeMasses << 1.0, 2.0, 3.0;
  const auto found = chainClosedGeodesics(chain, PeriodicOptions{});
  int simple = 0;
  for (const ClosedGeodesic& g : found) {
    EXPECT_LT(std::max(g.positionClosure, g.velocityClosure), 1e-10);
    EXPECT_FALSE(g.invariantUnder(ChainSymmetry::EndSwap));  // not an isometry here
    simple += g.simple;
  }
  EXPECT_GE(simple, 3);
}

// A triaxial ellipsoid through the same code: its three principal ellipses, lengths by elliptic integrals; the
// middle one is hyperbolic, the others elliptic.
TEST(Periodic, TriaxialEllipsoidPrincipalEllipses) {
  const double a = 1.0, b = 1.5, c = 2.0;
  const ConstrainedModel model = ConstrainedModel::ellipsoid(a, b, c);
  const std::vector<Eigen::VectorXd> points{Eigen::Vector3d(a, 0, 0), Eigen::Vector3d(0, b, 0),
                                            Eigen::Vector3d(0, 0, c)};
  PeriodicOptions options;
  options.maxLength = 14;
  const auto found = findClosedGeodesics(model, nullptr, points, options);
  const double expected[3] = {ellipsePerimeter(a, b), ellipsePerimeter(a, c), ellipsePerimeter(b, c)};
  const Stability stability[3] = {Stability::Elliptic, Stability::Hyperbolic, Stability::Elliptic};
  ASSERT_GE(found.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(found[static_cast<std::size_t>(i)].simple);
    EXPECT_NEAR(found[static_cast<std::size_t>(i)].length, expected[i], 1e-8);
    EXPECT_EQ(found[static_cast<std::size_t>(i)].stability, stability[i]);
  }
}

// The 3-rod chain's circle, across 1 < L < 3: the period of its motion at unit speed is the circle's length by
// the exact speed's quadrature, and (away from L = 1, where the polygons converge slowly) by polygons too. At
// L < 2 route 1 used to stop at a near-approach a third of the way round (L = 1.5: 6.655 against 10.769).
TEST(Periodic, ThreeRodCircleAcrossTheWholeRange) {
  for (double length : {1.0001, 1.001, 1.01, 1.1, 1.5, 1.9, 1.99, 2.0, 2.01, 2.5, 2.9, 2.99, 2.9999}) {
    SCOPED_TRACE(length);
    const Chain chain = Chain::uniform(3, length);
    const ClosedGeodesic g = circleClosedGeodesic(chain);
    EXPECT_LT(g.positionClosure, 1e-10);
    EXPECT_LT(g.velocityClosure, 1e-10);
    ASSERT_TRUE(g.independentLength.has_value());
    EXPECT_NEAR(g.length, *g.independentLength, 1e-9 * g.length);
    EXPECT_EQ(selfCheck(g), SelfCheck::confirmed);
    if (length >= 1.1) {
      const ConstrainedModel model = ConstrainedModel::fromChain(chain);
      const double polygons = closedCurveLength(model, [&](double w) {
        return ConstrainedModel::stack(hingePositionsAt(chain, Eigen::Vector2d(std::cos(w), std::sin(w))));
      });
      EXPECT_NEAR(g.length, polygons, 1e-9 * g.length);
    }
  }
  EXPECT_NEAR(circleClosedGeodesic(Chain::uniform(3, 1.5)).length, 10.769046335885, 1e-9);
  EXPECT_GT(circleClosedGeodesic(Chain::uniform(3, 2.0)).length, 2 * 3.14159);  // longer than p1's own unit circle
}

// Class 12 of the fourth hostile round: near L = n the configuration sphere shrinks like sqrt(n - L), and the
// search's absolute thresholds (on-orbit tolerance, covered seeds, Newton's step) were written for unit-size
// spheres. At L = 3.99999 it listed one closed geodesic twice and another three times, with different symmetry
// labels; at L = 3.999999 none. Lyusternik and Schnirelmann promise three simple ones: each once, confirmed.
TEST(Periodic, NearTheStraightChainEachClosedGeodesicIsListedOnce) {
  for (double length : {3.99999, 3.999999}) {
    SCOPED_TRACE(length);
    const auto found = chainClosedGeodesics(Chain::uniform(4, length), PeriodicOptions{});
    int simple = 0;
    for (std::size_t i = 0; i < found.size(); ++i) {
      simple += found[i].simple;
      EXPECT_EQ(selfCheck(found[i]), SelfCheck::confirmed) << i;
      for (std::size_t j = 0; j < i; ++j)
        EXPECT_FALSE(std::abs(found[i].length - found[j].length) < 1e-7 * found[i].length &&
                     std::abs(found[i].monodromy.trace() - found[j].monodromy.trace()) < 1e-6)
            << "closed geodesics " << j << " and " << i << " are one (length " << found[i].length << ")";
    }
    EXPECT_GE(simple, 3);
  }
}

// Masses 100 apart bend the mass-weighted orbit far more sharply than even masses do: the twin test measures
// the chord sag on the orbit itself (one mirror-symmetric closed geodesic was listed five times), and half the
// shots go to the earliest returns (the long orbits' close recurrences took every shot, and no simple one was
// listed). Mirror pairs (two orbits, one the other's image) share length and trace; a mirror-symmetric one has
// no pair.
TEST(Periodic, MassesFarApartListEachClosedGeodesicOnce) {
  Chain chain = Chain::uniform(4, 3.5);
  chain.hingeMasses << 0.01, 1.0, 100.0;
  PeriodicOptions options;
  options.maxLength = 24;
  const auto found = chainClosedGeodesics(chain, options);
  int simple = 0;
  const std::vector<ChainSymmetryOf> mirrorOnly{{ChainSymmetry::Mirror, false}};
  for (std::size_t i = 0; i < found.size(); ++i) {
    simple += found[i].simple;
    EXPECT_EQ(selfCheck(found[i]), SelfCheck::confirmed) << i;
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_FALSE(found[i].symmetries == found[j].symmetries && found[i].symmetries == mirrorOnly &&
                   std::abs(found[i].length - found[j].length) < 1e-7 * found[i].length &&
                   std::abs(found[i].monodromy.trace() - found[j].monodromy.trace()) < 1e-6)
          << "closed geodesics " << j << " and " << i << " are one (length " << found[i].length << ")";
  }
  ASSERT_FALSE(found.empty());
  EXPECT_TRUE(found[0].simple);
  EXPECT_NEAR(found[0].length, 3.488186331482, 1e-9);
}

// Masses beyond limits::kMaxPeriodicMassRatio apart are refused before the search, with the reason; at the
// limit they are searched.
TEST(Periodic, MassesTooFarApartAreRefusedBeforeTheSearch) {
  Chain chain = Chain::uniform(4, 3.5);
  chain.hingeMasses << 1e-3, 1.0, 1e3;
  const auto refusal = periodicSearchRefusal(chain);
  ASSERT_TRUE(refusal);
  EXPECT_NE(refusal->find("1e+06 apart"), std::string::npos) << *refusal;
  EXPECT_THROW(closedGeodesicsOf(chain, 5), std::invalid_argument);
  chain.hingeMasses << 1e-2, 1.0, 1e2;
  EXPECT_FALSE(periodicSearchRefusal(chain));
  EXPECT_FALSE(periodicSearchRefusal(Chain::uniform(4, 3.0)));
}

// The fixed curve of the end swap really is fixed by it, and lies on the rods.
TEST(Periodic, EndSwapFixedCurve) {
  const Chain chain = Chain::uniform(4, 3.0);
  const ConstrainedModel model = ConstrainedModel::fromChain(chain);
  for (double w : {0.0, 0.7, 2.0, 4.5}) {
    const Eigen::VectorXd q = endSwapFixedPoint(chain, w);
    EXPECT_LT(model.values(q).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_LT((applyChainSymmetry(chain, ChainSymmetry::EndSwap, q) - q).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_GT((applyChainSymmetry(chain, ChainSymmetry::Mirror, q) - q).cwiseAbs().maxCoeff(), 1e-3);
  }
}

}  // namespace
}  // namespace sl

// Sectional curvature (geometry/sectional_curvature.hpp): the Gauss-equation and Riemann-tensor routes against each
// other, against the Gaussian curvature for 4 rods, and on model spheres whose curvature is known.

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "geometry/curvature.hpp"
#include "geometry/sectional_curvature.hpp"
#include "geometry/sectional_curvature_routes.hpp"
#include "geometry_support.hpp"
#include "linkage/chain_constants.hpp"

namespace sl {
namespace {

// S^k in R^(k+1) scaled along its axes, with the Euclidean metric: the round sphere (K = 1) when every scale is 1.
struct ScaledSphere {
  Eigen::VectorXd scales;
  Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(scales.size(), scales.size());
  int sphereDimension() const { return static_cast<int>(scales.size()) - 1; }
  const Eigen::MatrixXd& mass() const { return identity; }
  template <class S>
  VectorX<S> operator()(const std::vector<int>& axes, const VectorX<S>& coords) const {
    VectorX<S> x = spherePointInChart<S>(axes, coords);
    for (Eigen::Index i = 0; i < x.size(); ++i) x(i) = x(i) * scales(i);
    return x;
  }
};

struct RandomPlanes {
  std::mt19937 random;
  std::normal_distribution<double> normal{0.0, 1.0};
  explicit RandomPlanes(unsigned seed) : random(seed) {}
  Eigen::VectorXd vector(Eigen::Index size) {
    Eigen::VectorXd v(size);
    for (Eigen::Index i = 0; i < size; ++i) v(i) = normal(random);
    return v;
  }
  Eigen::VectorXd point(Eigen::Index size) { return vector(size).normalized(); }
  Eigen::VectorXd tangent(const Eigen::VectorXd& x) {
    const Eigen::VectorXd v = vector(x.size());
    return v - v.dot(x) * x;
  }
  // A second tangent vector, orthogonal to `other` in R^(n-1) (not in the kinetic metric): a plane that is never
  // nearly degenerate, where the quotient would only measure rounding.
  Eigen::VectorXd tangent(const Eigen::VectorXd& x, const Eigen::VectorXd& other) {
    const Eigen::VectorXd v = tangent(x);
    return v - v.dot(other) / other.squaredNorm() * other;
  }
};

Chain fiveRods(double L, int setting) {
  Chain chain = Chain::uniform(5, L);
  if (setting == 1) chain.rodMasses.setConstant(2.0);
  if (setting == 2) {
    chain.hingeMasses << 0.5, 2.0, 1.0, 3.0;
    chain.rodMasses << 0.0, 1.5, 0.25, 3.0, 0.5;
  }
  return chain;
}

TEST(SectionalCurvature, IsTheGaussianCurvatureForFourRodsByBothRoutes) {
  RandomPlanes draw(3);
  double worst = 0;
  for (double L : testing::issueBaseLengths())
    for (const testing::MassSetting& setting : testing::massSettings(L)) {
      const ChainConstants bound(setting.chain);
      const ConfigurationSurface surface(setting.chain);
      for (int i = 0; i < 25; ++i) {
        const Eigen::VectorXd x = draw.point(3);
        const Eigen::VectorXd X = draw.tangent(x), Y = draw.tangent(x, X);
        const double K = surface.gaussianCurvature(Eigen::Vector3d(x));
        const double scale = std::max(1.0, std::abs(K));
        worst = std::max(worst, std::abs(sectionalCurvature(bound, x, X, Y) - K) / scale);
        worst = std::max(worst, std::abs(sectionalCurvatureIntrinsic(bound, x, X, Y) - K) / scale);
        const SectionalRange range = sectionalCurvatureRange(bound, x);
        EXPECT_NEAR(range.minimum, K, 1e-10 * scale);
        EXPECT_NEAR(range.maximum, K, 1e-10 * scale);
      }
    }
  RecordProperty("worst_relative_difference", testing::scientific(worst));
  EXPECT_LT(worst, 1e-9);
}

TEST(SectionalCurvature, RoundThreeSphereHasCurvatureOneEverywhereByBothRoutes) {
  const ScaledSphere round{Eigen::VectorXd::Ones(4)};
  RandomPlanes draw(5);
  for (int i = 0; i < 200; ++i) {
    const Eigen::VectorXd x = draw.point(4);
    const Eigen::VectorXd X = draw.tangent(x), Y = draw.tangent(x, X);
    EXPECT_NEAR(sectional::gaussRoute(round, x, X, Y), 1.0, 1e-12);
    EXPECT_NEAR(sectional::intrinsicRoute(round, x, X, Y), 1.0, 1e-12);
  }
  const SectionalRange range = sectional::curvatureRange(round, draw.point(4));
  EXPECT_NEAR(range.minimum, 1.0, 1e-12);
  EXPECT_NEAR(range.maximum, 1.0, 1e-12);
}

// On an ellipsoidal S^3 (K varies with the point and the plane) both routes agree, and the range holds every plane.
TEST(SectionalCurvature, RoutesAgreeAndTheRangeHoldsEveryPlaneOnAnEllipsoidalThreeSphere) {
  const ScaledSphere ellipsoid{(Eigen::VectorXd(4) << 1.0, 1.5, 2.0, 2.5).finished()};
  RandomPlanes draw(7);
  for (int i = 0; i < 100; ++i) {
    const Eigen::VectorXd x = draw.point(4);
    const SectionalRange range = sectional::curvatureRange(ellipsoid, x);
    EXPECT_LT(range.minimum, range.maximum);
    for (int j = 0; j < 10; ++j) {
      const Eigen::VectorXd X = draw.tangent(x), Y = draw.tangent(x, X);
      const double K = sectional::gaussRoute(ellipsoid, x, X, Y);
      EXPECT_NEAR(sectional::intrinsicRoute(ellipsoid, x, X, Y), K, 1e-10 * std::max(1.0, std::abs(K)));
      EXPECT_GE(K, range.minimum - 1e-12);
      EXPECT_LE(K, range.maximum + 1e-12);
    }
    // The planes reported carry the extremes.
    EXPECT_NEAR(sectional::gaussRoute(ellipsoid, x, range.minimumPlane[0], range.minimumPlane[1]), range.minimum, 1e-10);
    EXPECT_NEAR(sectional::gaussRoute(ellipsoid, x, range.maximumPlane[0], range.maximumPlane[1]), range.maximum, 1e-10);
  }
}

TEST(SectionalCurvature, FiveRodsRoutesAgreeAtAThousandRandomPointsAndPlanes) {
  RandomPlanes draw(13);
  double worst = 0;
  int count = 0;
  for (double L : {3.1, 3.6, 4.2, 4.8, 4.97})
    for (int setting = 0; setting < 3; ++setting) {
      const ChainConstants bound(fiveRods(L, setting));
      for (int i = 0; i < 67; ++i, ++count) {
        const Eigen::VectorXd x = draw.point(4);
        const Eigen::VectorXd X = draw.tangent(x), Y = draw.tangent(x, X);
        const double gauss = sectionalCurvature(bound, x, X, Y), intrinsic = sectionalCurvatureIntrinsic(bound, x, X, Y);
        ASSERT_TRUE(std::isfinite(gauss));
        worst = std::max(worst, std::abs(gauss - intrinsic) / std::max(1.0, std::abs(gauss)));
      }
    }
  EXPECT_GE(count, 1000);
  RecordProperty("worst_relative_difference", testing::scientific(worst));
  EXPECT_LT(worst, 1e-9);
}

// The exact range for 5 rods (the curvature operator's eigenvalues) holds every random plane and is attained; for 6
// rods the alternating search finds planes at least as extreme as any random one.
TEST(SectionalCurvature, RangeHoldsRandomPlanesAndIsAttained) {
  RandomPlanes draw(17);
  for (int rods : {5, 6})
    for (double L : {rods - 1.7, rods - 0.4}) {
      const ChainConstants bound(Chain::uniform(rods, L));
      for (int i = 0; i < 20; ++i) {
        const Eigen::VectorXd x = draw.point(rods - 1);
        const SectionalRange range = sectionalCurvatureRange(bound, x);
        const double scale = std::max(1.0, std::abs(range.maximum) + std::abs(range.minimum));
        for (int j = 0; j < 30; ++j) {
          const Eigen::VectorXd X = draw.tangent(x);
          const double K = sectionalCurvature(bound, x, X, draw.tangent(x, X));
          EXPECT_GE(K, range.minimum - 1e-10 * scale) << rods << " rods, L = " << L;
          EXPECT_LE(K, range.maximum + 1e-10 * scale) << rods << " rods, L = " << L;
        }
        EXPECT_NEAR(sectionalCurvature(bound, x, range.maximumPlane[0], range.maximumPlane[1]), range.maximum,
                    1e-10 * scale);
        EXPECT_NEAR(sectionalCurvatureIntrinsic(bound, x, range.minimumPlane[0], range.minimumPlane[1]), range.minimum,
                    1e-9 * scale);
      }
    }
}

// The range through a velocity holds every plane through it and lies within the range over all planes.
TEST(SectionalCurvature, RangeThroughAVelocityHoldsEveryPlaneThroughIt) {
  RandomPlanes draw(19);
  const ChainConstants bound(fiveRods(3.7, 2));
  for (int i = 0; i < 20; ++i) {
    const Eigen::VectorXd x = draw.point(4), v = draw.tangent(x);
    const std::array<double, 2> through = sectionalCurvatureThrough(bound, x, v);
    const SectionalRange all = sectionalCurvatureRange(bound, x);
    const double scale = std::max({1.0, std::abs(all.minimum), std::abs(all.maximum)});
    EXPECT_LE(through[0], through[1]);
    EXPECT_GE(through[0], all.minimum - 1e-12 * scale);
    EXPECT_LE(through[1], all.maximum + 1e-12 * scale);
    double lo = INFINITY, hi = -INFINITY;
    for (int j = 0; j < 200; ++j) {
      const double K = sectionalCurvature(bound, x, v, draw.tangent(x, v));
      lo = std::min(lo, K), hi = std::max(hi, K);
    }
    EXPECT_GE(lo, through[0] - 1e-10 * scale);
    EXPECT_LE(hi, through[1] + 1e-10 * scale);
    EXPECT_NEAR(lo, through[0], 0.05 * (through[1] - through[0]) + 1e-12);  // 200 planes come close to both ends
    EXPECT_NEAR(hi, through[1], 0.05 * (through[1] - through[0]) + 1e-12);
  }
}

TEST(SectionalCurvature, RefusesVectorsThatSpanNoPlane) {
  const ChainConstants bound(fiveRods(4.2, 0));
  const Eigen::VectorXd x = Eigen::Vector4d(1, 0, 0, 0);
  const Eigen::VectorXd X = Eigen::Vector4d(0, 1, 0, 0);
  EXPECT_THROW(sectionalCurvature(bound, x, X, 2.0 * X), std::invalid_argument);
  EXPECT_THROW(sectionalCurvatureIntrinsic(bound, x, X, Eigen::Vector4d::Zero()), std::invalid_argument);
  EXPECT_THROW(sectionalCurvatureRange(bound, Eigen::Vector3d(1, 0, 0)), std::invalid_argument);
}

}  // namespace
}  // namespace sl

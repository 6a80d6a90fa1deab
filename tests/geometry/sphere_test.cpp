// The configuration sphere as a whole: Gauss-Bonnet, area, maps, extrema, summaries and the L at
// which K turns positive everywhere.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/curvature_grid.hpp"
#include "geometry_support.hpp"
#include "linkage/kinetic_metric.hpp"
#include "linkage/sphere_coordinates.hpp"

namespace sl {
namespace {

using testing::chartZeroPoint;

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

TEST(SphereIntegrals, GaussLegendreIsExactToDegreeTwoNMinusOne) {
  for (int n : {1, 2, 5, 24, 97}) {
    std::vector<double> x, w;
    gaussLegendre(n, x, w);
    for (int degree = 0; degree <= 2 * n - 1; degree += (n > 5 ? 7 : 1)) {
      double sum = 0;
      for (int i = 0; i < n; ++i) sum += w[static_cast<size_t>(i)] * std::pow(x[static_cast<size_t>(i)], degree);
      const double exact = degree % 2 ? 0.0 : 2.0 / (degree + 1);
      EXPECT_NEAR(sum, exact, 1e-14) << "n=" << n << " degree " << degree;
    }
  }
}

TEST(SphereIntegrals, GaussBonnetHoldsForEveryLengthAndMassSetting) {
  double worst = 0;
  for (double L : {2.2, 2.5, 3.0, 3.5, 3.9})
    for (const auto& setting : testing::massSettings(L)) {
      const SphereIntegrals integrals = integrateOverSphereConverged(ConfigurationSurface(setting.chain), 1e-11);
      EXPECT_TRUE(integrals.converged) << setting.name << " L=" << L;
      const double error = std::abs(integrals.totalCurvature - 4 * M_PI) / (4 * M_PI);
      worst = std::max(worst, error);
      EXPECT_LE(error, 1e-9) << setting.name << " L=" << L << " nodes " << integrals.phiNodes;
      EXPECT_GT(integrals.area, 0.0);
    }
  RecordProperty("worst_relative_error", testing::scientific(worst));
}

TEST(SphereIntegrals, AreaAtLThreeMatchesAnIndependentDifferenceFigure) {
  const Chain chain = Chain::uniform(4, 3.0);
  const SphereIntegrals integrals = integrateOverSphereConverged(ConfigurationSurface(chain));
  EXPECT_NEAR(integrals.area, 21.326, 1e-3);
  // Independent: the metric from central differences of the chart (linkage/kinetic_metric.hpp), the midpoint rule
  // on chart 0 at n x 2n and 2n x 4n cells, Richardson-extrapolated (the rule's error is even in the cell size:
  // the integrand sqrt(det g) is periodic in t and smooth in phi up to the poles).
  const std::vector<int> axes = sphereChartAxes(3, 0);
  const auto midpoint = [&](int n) {
    double sum = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < 2 * n; ++j) {
        const Eigen::Vector2d c(-M_PI / 2 + M_PI * (i + 0.5) / n, -M_PI + M_PI * (j + 0.5) / n);
        sum += std::sqrt(kineticMetricCentralDifferences(chain, axes, c).determinant());
      }
    return sum * (M_PI / n) * (M_PI / n);
  };
  const double coarse = midpoint(60), fine = midpoint(120);
  const double area = (4 * fine - coarse) / 3;
  EXPECT_NEAR(integrals.area, area, 1e-5);
  RecordProperty("difference_figure", std::to_string(area));
}

TEST(SphereIntegrals, AreaAndCurvatureScaleWithTheMasses) {
  Chain chain = Chain::uniform(4, 3.0);
  const SphereIntegrals one = integrateOverSphere(ConfigurationSurface(chain), 96, 192);
  chain.hingeMasses *= 2.5;
  const SphereIntegrals scaled = integrateOverSphere(ConfigurationSurface(chain), 96, 192);
  EXPECT_NEAR(scaled.area, 2.5 * one.area, 1e-12 * scaled.area);
  EXPECT_NEAR(scaled.totalCurvature, 4 * M_PI, 1e-11);
}

TEST(SphereIntegrals, ResultsDoNotDependOnTheThreadCount) {
  const ConfigurationSurface surface(testing::massSettings(3.3)[3].chain);
  const SphereIntegrals one = integrateOverSphere(surface, 40, 80, 1), two = integrateOverSphere(surface, 40, 80, 2),
                        three = integrateOverSphere(surface, 40, 80, 3);
  EXPECT_EQ(one.area, two.area);
  EXPECT_EQ(one.totalCurvature, two.totalCurvature);
  EXPECT_EQ(one.totalCurvature, three.totalCurvature);
}

TEST(CurvatureMaps, GridIsRowMajorOverBothPolesAndMatchesPointwiseValues) {
  const ConfigurationSurface surface(Chain::uniform(4, 3.0));
  const ChartGrid grid = uniformChartGrid(9, 12);
  EXPECT_EQ(grid.phis.front(), -M_PI / 2);
  EXPECT_EQ(grid.phis.back(), M_PI / 2);
  EXPECT_EQ(grid.ts.front(), -M_PI);
  EXPECT_LT(grid.ts.back(), M_PI);
  const std::vector<CurvatureSample> one = curvatureGrid(surface, grid.phis, grid.ts, 1);
  const std::vector<CurvatureSample> two = curvatureGrid(surface, grid.phis, grid.ts, 2);
  ASSERT_EQ(one.size(), 9u * 12u);
  for (size_t i = 0; i < grid.phis.size(); ++i)
    for (size_t j = 0; j < grid.ts.size(); ++j) {
      const CurvatureSample& s = one[i * grid.ts.size() + j];
      const CurvatureSample direct = surface.curvatureAtCoordinates(grid.phis[i], grid.ts[j]);
      EXPECT_EQ(s.phi, grid.phis[i]);
      EXPECT_EQ(s.t, grid.ts[j]);
      EXPECT_EQ(s.gaussianCurvature, direct.gaussianCurvature);
      EXPECT_EQ(s.stiffnessAngle, direct.stiffnessAngle);
      const CurvatureSample& other = two[i * grid.ts.size() + j];
      EXPECT_EQ(s.gaussianCurvature, other.gaussianCurvature);
      EXPECT_EQ(s.bending, other.bending);
      EXPECT_EQ(s.stiffnessMax, other.stiffnessMax);
      EXPECT_EQ(s.stiffnessMin, other.stiffnessMin);
      EXPECT_EQ(s.stiffnessAngle, other.stiffnessAngle);
    }
  const std::vector<Eigen::Vector2d> points = {{0.3, 0.2}, {M_PI / 2, 1.0}, {-0.2, M_PI / 2}};
  const std::vector<CurvatureSample> at = curvatureSamples(surface, points, 2);
  for (size_t k = 0; k < points.size(); ++k)
    EXPECT_EQ(at[k].gaussianCurvature, surface.curvatureAtCoordinates(points[k](0), points[k](1)).gaussianCurvature);
}

TEST(CurvatureExtrema, LThreeUnitHingeMasses) {
  // docs/geometry.md: min K ~ -0.272 near (0.39, 1.34) and its mirror (-0.39, 1.34 - pi); max K ~ 4.15.
  const ConfigurationSurface surface(Chain::uniform(4, 3.0));
  const CurvatureExtrema extrema = curvatureExtrema(surface);
  EXPECT_NEAR(extrema.curvatureMin.value, -0.272, 1e-3);
  EXPECT_NEAR(extrema.curvatureMin.phi, 0.39, 0.01);
  EXPECT_NEAR(extrema.curvatureMin.t, 1.34, 0.01);
  EXPECT_NEAR(extrema.curvatureMax.value, 4.15, 0.01);
  EXPECT_TRUE(extrema.curvatureMin.converged && extrema.curvatureMax.converged && extrema.bendingMax.converged);
  // The mirror image is a minimum of the same depth.
  const SurfaceExtremum mirror =
      refineExtremum(surface, SurfaceQuantity::gaussianCurvature, false, chartZeroPoint(-0.39, 1.34 - M_PI));
  EXPECT_NEAR(mirror.value, extrema.curvatureMin.value, 1e-13);
  EXPECT_LT(angleBetween(mirror.spherePoint, -extrema.curvatureMin.spherePoint), 1e-9);
  // No grid point beats the refined extrema.
  const ChartGrid grid = uniformChartGrid(129, 256);
  for (const CurvatureSample& s : curvatureGrid(surface, grid.phis, grid.ts)) {
    EXPECT_GE(s.gaussianCurvature, extrema.curvatureMin.value - 1e-12);
    EXPECT_LE(s.gaussianCurvature, extrema.curvatureMax.value + 1e-12);
    EXPECT_LE(s.bending, extrema.bendingMax.value + 1e-12);
  }
}

TEST(CurvatureExtrema, RefinedPositionsAreGoodToOneInABillion) {
  // Refinements from different starts, in different tangent planes, land on the same point; the value there is
  // a local extremum at the scale of the position tolerance's square root.
  for (const auto& setting : testing::massSettings(3.0)) {
    const ConfigurationSurface surface(setting.chain);
    const CurvatureExtrema extrema = curvatureExtrema(surface, 48);
    for (const auto& [e, quantity, maximum] :
         {std::tuple{extrema.curvatureMin, SurfaceQuantity::gaussianCurvature, false},
          std::tuple{extrema.curvatureMax, SurfaceQuantity::gaussianCurvature, true},
          std::tuple{extrema.bendingMax, SurfaceQuantity::bending, true}}) {
      EXPECT_TRUE(e.converged) << setting.name;
      EXPECT_LE(e.positionError, 1e-10);
      for (const Eigen::Vector3d& offset : {Eigen::Vector3d(0.02, -0.01, 0.015), Eigen::Vector3d(-0.01, 0.03, 0.0)}) {
        const SurfaceExtremum again = refineExtremum(surface, quantity, maximum, e.spherePoint + offset);
        EXPECT_LT(angleBetween(again.spherePoint, e.spherePoint), 1e-9) << setting.name;
        EXPECT_NEAR(again.value, e.value, 1e-13 * std::max(1.0, std::abs(e.value)));
      }
      const double sign = maximum ? -1.0 : 1.0;
      for (int k = 0; k < 8; ++k) {
        const Eigen::Vector3d u = e.spherePoint.cross(Eigen::Vector3d(std::cos(k), std::sin(k), 0.5)).normalized();
        EXPECT_GE(sign * (surfaceQuantity(surface, quantity, e.spherePoint + 1e-4 * u) - e.value), -1e-15);
      }
    }
  }
}

TEST(CurvatureExtrema, CurvatureTurnsPositiveEverywhereNearLThreePointOneFiveThree) {
  const Chain chain = Chain::uniform(4, 3.0);
  const double threshold = positiveCurvatureThreshold(chain, 3.0, 3.3, 1e-9);
  RecordProperty("threshold", std::to_string(threshold));
  EXPECT_NEAR(threshold, 3.153, 1e-3);
  EXPECT_LT(minimumCurvature(chain, threshold - 1e-6), 0.0);
  EXPECT_GT(minimumCurvature(chain, threshold + 1e-6), 0.0);
  for (double L : {3.2, 3.5, 3.9}) {
    const ConfigurationSurface surface(Chain::uniform(4, L));
    EXPECT_GT(curvatureExtrema(surface).curvatureMin.value, 0.0) << L;
    const ChartGrid grid = uniformChartGrid(65, 128);
    for (const CurvatureSample& s : curvatureGrid(surface, grid.phis, grid.ts)) ASSERT_GT(s.gaussianCurvature, 0.0);
  }
  EXPECT_THROW(positiveCurvatureThreshold(chain, 3.3, 3.9), std::invalid_argument);
}

TEST(CurvatureSummaries, SummaryAndSweep) {
  Chain chain = testing::massSettings(3.0)[2].chain;  // heavy rods
  const std::vector<CurvatureSummary> sweep = curvatureSweep(chain, 2.6, 3.4, 3);
  ASSERT_EQ(sweep.size(), 3u);
  EXPECT_DOUBLE_EQ(sweep[1].baseLength, 3.0);
  const CurvatureSummary single = curvatureSummary(chain);
  EXPECT_EQ(sweep[1].area, single.area);
  EXPECT_EQ(sweep[1].curvatureMin.value, single.curvatureMin.value);
  for (const CurvatureSummary& s : sweep) {
    EXPECT_LE(std::abs(s.gaussBonnetError), 1e-9) << s.baseLength;
    EXPECT_LE(s.curvatureMin.value, s.curvatureMax.value);
    EXPECT_GT(s.bendingMax.value, 0.0);
    EXPECT_GE(s.bendingMax.value, s.curvatureMax.value);  // K = <A,C> - |B|^2 <= (|A|^2 + |C|^2)/2 <= |II|^2 / 2
  }
  // The area shrinks as L grows towards 4 (the chain has less room to move).
  EXPECT_GT(sweep[0].area, sweep[1].area);
  EXPECT_GT(sweep[1].area, sweep[2].area);
}

}  // namespace
}  // namespace sl

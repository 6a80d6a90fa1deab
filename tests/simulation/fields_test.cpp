// The geodesic vector fields at single states: exact routes against each other and against independent
// finite differences; the published -fd fields against the exact ones where they are valid.
#include <gtest/gtest.h>

#include <random>

#include "linkage/chart.hpp"
#include "linkage/kinetic_metric.hpp"
#include "linkage/sphere_coordinates.hpp"
#include "simulation/exact_fields.hpp"
#include "simulation/published_fields.hpp"

namespace sl {
namespace {

Chain massiveChain(int rods, double L) {
  Chain chain = Chain::uniform(rods, L);
  for (int j = 0; j < rods - 1; ++j) chain.hingeMasses(j) = 0.5 + 0.37 * j;
  for (int k = 0; k < rods; ++k) chain.rodMasses(k) = 0.2 + 0.1 * (k % 3);
  return chain;
}

// Random chart coordinates away from the chart's own singular set (|latitudes| < 1.3).
Eigen::VectorXd randomCoords(std::mt19937& rng, int k) {
  std::uniform_real_distribution<double> latitude(-1.3, 1.3), angle(-M_PI, M_PI);
  Eigen::VectorXd c(k);
  for (int i = 0; i + 1 < k; ++i) c(i) = latitude(rng);
  c(k - 1) = angle(rng);
  return c;
}

TEST(ExactFields, ChristoffelAndEmbeddedAgreeForAnyChainChartAndMasses) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  for (int rods = 3; rods <= 6; ++rods)
    for (const Chain& chain : {Chain::uniform(rods, rods - 0.6), massiveChain(rods, rods - 1.3)})
      for (int chart = 0; chart < sphereChartCount(rods - 1); ++chart)
        for (int trial = 0; trial < 4; ++trial) {
          const std::vector<int> axes = sphereChartAxes(rods - 1, chart);
          const Eigen::VectorXd c = randomCoords(rng, rods - 2);
          Eigen::VectorXd v(rods - 2);
          for (Eigen::Index i = 0; i < v.size(); ++i) v(i) = normal(rng);
          const Eigen::VectorXd a = christoffelAcceleration(chain, axes, c, v);
          const Eigen::VectorXd b = embeddedAcceleration(chain, axes, c, v);
          EXPECT_LT((a - b).norm(), 1e-10 * (1 + a.norm())) << "n = " << rods << ", chart " << chart;
        }
}

TEST(ExactFields, ChristoffelSymbolsMatchFiniteDifferencesOfTheMetric) {
  // Independent route: Gamma from central differences (step 1e-4, fourth-order stencil) of the AD pullback.
  const Chain chain = massiveChain(5, 3.6);
  const std::vector<int> axes = sphereChartAxes(4, 1);
  const Eigen::Vector3d c(0.4, -0.7, 2.1);
  const double h = 1e-3;
  std::vector<Eigen::MatrixXd> dh(3);
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(a) * h;
    dh[a] = (8 * (kineticMetricPullback(chain, axes, c + e) - kineticMetricPullback(chain, axes, c - e)) -
             (kineticMetricPullback(chain, axes, c + 2 * e) - kineticMetricPullback(chain, axes, c - 2 * e))) /
            (12 * h);
  }
  const Eigen::MatrixXd inverse = kineticMetricPullback(chain, axes, c).inverse();
  const std::vector<Eigen::MatrixXd> gamma = christoffelSymbols(chain, axes, c);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) {
        double expected = 0;
        for (int l = 0; l < 3; ++l) expected += 0.5 * inverse(i, l) * (dh[j](l, k) + dh[k](l, j) - dh[l](j, k));
        EXPECT_NEAR(gamma[i](j, k), expected, 1e-8 * (1 + std::abs(expected)));
        EXPECT_EQ(gamma[i](j, k), gamma[i](k, j));
      }
}

TEST(ExactFields, AccelerationIsNormalToTheConfigurationSpace) {
  // The defining property of a geodesic (spec section 5), checked with the finite-difference second
  // derivative of Psi along the path: q'' = J a + q_bc v^b v^c must be M-orthogonal to every q_a.
  const Chain chain = massiveChain(4, 3.2);
  const std::vector<int> axes = sphereChartAxes(3, 0);
  const Eigen::Vector2d c(0.3, 1.1), v(0.8, -0.5);
  const Eigen::VectorXd a = christoffelAcceleration(chain, axes, c, v);
  const double s = 1e-4;
  auto q = [&](double tau) {
    const Eigen::VectorXd at = c + tau * v + 0.5 * tau * tau * a;
    const Eigen::Matrix2Xd hinges = hingePositionsInChart<double>(chain, axes, at);
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(hinges.data(), hinges.size()));
  };
  const Eigen::VectorXd qdd = (q(s) - 2 * q(0) + q(-s)) / (s * s);
  const Eigen::MatrixXd J = chartJacobian(chain, axes, c);
  const Eigen::VectorXd tangential = J.transpose() * stackedMassMatrix(chain) * qdd;
  EXPECT_LT(tangential.norm(), 1e-6 * qdd.norm());
}

TEST(PublishedFields, FourRodHingesAreTheChart) {
  for (double L : {2.2, 3.0, 3.9})
    for (double phi = -1.5; phi <= 1.5; phi += 0.25)
      for (double t = -3.1; t <= 3.1; t += 0.2) {
        const Eigen::Matrix2Xd expected = hingePositions(Chain::uniform(4, L), Eigen::Vector2d(phi, t));
        const Eigen::Matrix<double, 6, 1> q = fourRodHinges(L, phi, t);
        EXPECT_LT((Eigen::Map<const Eigen::Matrix<double, 2, 3>>(q.data()) - expected).cwiseAbs().maxCoeff(), 1e-14);
      }
  // Exactly on the seam t = pi/2 too.
  const Eigen::Matrix<double, 6, 1> q = fourRodHinges(3.0, 0.4, M_PI / 2);
  EXPECT_LT((Eigen::Map<const Eigen::Matrix<double, 2, 3>>(q.data()) -
             hingePositions(Chain::uniform(4, 3.0), Eigen::Vector2d(0.4, M_PI / 2)))
                .cwiseAbs()
                .maxCoeff(),
            1e-14);
}

TEST(PublishedFields, AgreeWithTheExactFieldToTheirDifferenceError) {
  const Chain chain = Chain::uniform(4, 3.0);
  const std::vector<int> axes = sphereChartAxes(3, 0);
  double worstChristoffel = 0, worstEmbedded = 0;
  for (double phi : {-1.2, -0.5, 0.3, 1.0})
    for (double t : {-2.5, -0.4, 0.2, 1.3, 2.9}) {
      const Eigen::Vector2d c(phi, t), v(0.6, -0.9);
      const Eigen::VectorXd exact = christoffelAcceleration(chain, axes, c, v);
      worstChristoffel = std::max(worstChristoffel, (christoffelFdAcceleration(3.0, c, v) - exact).norm() / exact.norm());
      worstEmbedded = std::max(worstEmbedded, (embeddedFdAcceleration(3.0, c, v) - exact).norm() / exact.norm());
    }
  // Central differences: eps^2 truncation plus rounding / eps (1e-5 and 1e-4 steps, second differences).
  EXPECT_LT(worstChristoffel, 1e-7);
  EXPECT_LT(worstEmbedded, 1e-6);
  EXPECT_GT(worstEmbedded, 1e-12);  // they are approximations: a bit-exact match would mean a wiring mistake
}

TEST(PublishedFields, ChristoffelFdFailsOnTheSeamWhereThePublishedMetricDoes) {
  // At t = pi/2 the published metric4 divides by nu_in ~ cos t; its t-differences straddle the seam.
  const Eigen::Vector2d onSeam(0.3, M_PI / 2), v(0.5, 0.7);
  const Eigen::Vector2d published = christoffelFdAcceleration(3.0, onSeam, v);
  const Eigen::VectorXd exact = christoffelAcceleration(Chain::uniform(4, 3.0), sphereChartAxes(3, 0), onSeam, v);
  const bool broken = !published.allFinite() || (published - exact).norm() > 1e-3 * exact.norm();
  EXPECT_TRUE(broken) << "published " << published.transpose() << " exact " << exact.transpose();
  // The embedded-fd route never touches nu_in's division: fine on the seam.
  EXPECT_LT((embeddedFdAcceleration(3.0, onSeam, v) - exact).norm(), 1e-6 * exact.norm());
}

}  // namespace
}  // namespace sl
